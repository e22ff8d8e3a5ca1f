// The exact validator: it accepts true tilings (collinear vertices, Steiner points, T-junctions) and
// names what is wrong in false ones.
#include "core/validate.h"

#include <gtest/gtest.h>

namespace pd {
namespace {

// An L-shaped hexagon: 0(0,0) 1(4,0) 2(4,2) 3(2,2) 4(2,4) 5(0,4); vertex 3 is reflex.
Polygon ell() { return Polygon::make({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}); }

std::vector<QPoint> points_of(const Polygon& p) { return exact_points(p, Decomposition{}); }

Validation check(const Polygon& p, const std::vector<Piece>& pieces, Kind kind = Kind::Convex) {
  return validate_pieces(p, points_of(p), pieces, kind, false);
}

TEST(Validate, AcceptsAConvexDecomposition) {
  const Validation v = check(ell(), {{0, 1, 2, 3}, {0, 3, 4, 5}});
  EXPECT_TRUE(v.ok) << v.reason;
}

TEST(Validate, AcceptsATriangulationMadeOfCuts) {
  const Polygon p = ell();
  Decomposition d;
  for (auto [a, b] : {std::pair{0, 2}, {0, 3}, {3, 5}}) d.add_cut(a, b);
  const Validation v = validate(p, d, Kind::Triangulation, false);
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(pieces_of(p, d).size(), 4u);
}

TEST(Validate, CatchesAMissingPiece) {
  const Validation v = check(ell(), {{0, 1, 2, 3}});
  EXPECT_FALSE(v.ok);
  EXPECT_NE(v.reason.find("not covered"), std::string::npos) << v.reason;
}

TEST(Validate, CatchesOverlappingPieces) {
  // A triangle and the whole square over it; then a triangle listed twice.
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const Validation v = check(p, {{0, 1, 2}, {0, 1, 2, 3}});
  EXPECT_FALSE(v.ok);
  const Validation twice = check(p, {{0, 1, 2}, {0, 2, 3}, {0, 2, 3}});
  EXPECT_FALSE(twice.ok);
  EXPECT_NE(twice.reason.find("overlap"), std::string::npos) << twice.reason;
}

TEST(Validate, CatchesANonConvexPiece) {
  const Validation v = check(ell(), {{0, 1, 2, 3, 4, 5}});
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "piece 0 turns right at vertex 3");
}

TEST(Validate, CatchesAClockwisePiece) {
  const Validation v = check(ell(), {{3, 2, 1, 0}, {0, 3, 4, 5}});
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "piece 0 turns right at vertex 2");
  const Validation tri = check(ell(), {{0, 2, 1}, {0, 3, 2}, {0, 5, 3}, {3, 5, 4}}, Kind::Triangulation);
  EXPECT_FALSE(tri.ok);
  EXPECT_EQ(tri.reason, "piece 0 is not a counter-clockwise triangle");
}

TEST(Validate, CatchesACutThatLeavesThePolygon) {
  // Diagonal 2-4 crosses the notch at vertex 3: it runs outside the polygon.
  const Polygon p = ell();
  Decomposition d;
  d.add_cut(2, 4);
  d.add_cut(0, 2);
  d.add_cut(0, 4);
  const Validation v = validate(p, d, Kind::Convex, false);
  EXPECT_FALSE(v.ok);
  EXPECT_EQ(v.reason, "piece 3 turns right at vertex 3");  // the face outside, in the notch
  // As pieces: one convex pentagon spanning the notch, its edge 2-4 outside the polygon.
  EXPECT_EQ(check(p, {{0, 1, 2, 4, 5}}).reason, "boundary edge 2-3 is not covered exactly once from inside");
}

TEST(Validate, CatchesMalformedCuts) {
  const Polygon p = ell();
  Decomposition self;
  self.add_cut(2, 2);
  EXPECT_EQ(validate(p, self, Kind::Convex, false).reason, "cut 0 joins vertex 2 to itself");
  Decomposition out_of_range;
  out_of_range.add_cut(0, 9);
  EXPECT_FALSE(validate(p, out_of_range, Kind::Convex, false).ok);
  Decomposition twice;
  twice.add_cut(0, 3);
  twice.add_cut(3, 0);
  EXPECT_FALSE(validate(p, twice, Kind::Convex, false).ok);
}

TEST(Validate, AcceptsSteinerPointsOnTheBoundaryAndTJunctions) {
  // The L cut by the segment from notch 3 down to a Steiner point s=6 at (2,0) on edge 0-1.
  const Polygon p = ell();
  Decomposition d;
  const VertexId s = static_cast<VertexId>(p.size()) + d.add_steiner(QPoint(2, 0), 0);
  d.add_cut(3, s);
  const Validation v = validate(p, d, Kind::Convex, true);
  EXPECT_TRUE(v.ok) << v.reason;
  const auto pieces = pieces_of(p, d);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(validate(p, d, Kind::Convex, false).reason, "1 Steiner points from a diagonal-only algorithm");
}

TEST(Validate, AcceptsATJunctionInsideThePolygon) {
  // Square 0..3 with a Steiner point c=4 at the centre: cuts 0-c, c-2 (one segment split at c) and 1-c.
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Decomposition d;
  const VertexId c = 4 + d.add_steiner(QPoint(2, 2));
  d.add_cut(0, c);
  d.add_cut(c, 2);
  d.add_cut(1, c);
  const Validation v = validate(p, d, Kind::Convex, true);
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(pieces_of(p, d).size(), 3u);
  // A piece that skips the T-junction point is caught.
  const std::vector<QPoint> pts = exact_points(p, d);
  EXPECT_FALSE(validate_pieces(p, pts, {{0, 1, 4}, {1, 2, 4}, {0, 2, 3}}, Kind::Convex, true).ok);
}

TEST(Validate, AcceptsATriangulationWithASteinerPointInside) {
  // Square 0..3 fanned from a Steiner point c=4 at the centre: 4 triangles, two more than n - 2.
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Decomposition d;
  const VertexId c = 4 + d.add_steiner(QPoint(2, 2));
  for (VertexId i = 0; i < 4; ++i) d.add_cut(i, c);
  const Validation v = validate(p, d, Kind::Triangulation, true);
  EXPECT_TRUE(v.ok) << v.reason;
  const std::vector<QPoint> pts = exact_points(p, d);
  EXPECT_FALSE(validate_pieces(p, pts, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}}, Kind::Triangulation, true).ok);
}

TEST(Validate, HandlesCollinearVertices) {
  // A square with a flat vertex 1 on the bottom edge.
  const Polygon p = Polygon::make({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}});
  EXPECT_TRUE(check(p, {{0, 1, 2, 3, 4}}).ok);
  EXPECT_FALSE(check(p, {{0, 2, 3, 4}}).ok);  // skips vertex 1
  Decomposition d;
  d.add_cut(1, 3);
  d.add_cut(1, 4);
  EXPECT_TRUE(validate(p, d, Kind::Triangulation, false).ok);
}

TEST(Validate, ChecksYMonotonePieces) {
  // A "W" (two notches pointing down from the top) is not y-monotone; split at the middle it is.
  const Polygon p = Polygon::make({{0, 0}, {6, 0}, {6, 4}, {4, 4}, {3, 2}, {2, 4}, {0, 4}});
  EXPECT_EQ(check(p, {{0, 1, 2, 3, 4, 5, 6}}, Kind::Partition).reason, "piece 0 is not y-monotone");
  EXPECT_TRUE(check(p, {{0, 1, 2, 3, 4}, {0, 4, 5, 6}}, Kind::Partition).ok);
}

}  // namespace
}  // namespace pd
