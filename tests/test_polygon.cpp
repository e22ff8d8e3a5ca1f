// The checked constructor: what it rejects, what it accepts, and how it normalises.
#include "core/polygon.h"

#include <gtest/gtest.h>

#include <limits>

namespace pd {
namespace {

std::vector<Point> square() { return {{0, 0}, {2, 0}, {2, 2}, {0, 2}}; }

std::string error_of(std::vector<Point> v) {
  try {
    Polygon::make(std::move(v));
  } catch (const PolygonError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Polygon, RejectsTooFewVertices) {
  EXPECT_EQ(error_of({}), "0 vertices; a polygon needs at least 3");
  EXPECT_EQ(error_of({{0, 0}, {1, 0}}), "2 vertices; a polygon needs at least 3");
  EXPECT_EQ(error_of({{0, 0}, {1, 0}, {0, 0}}), "2 vertices; a polygon needs at least 3");
}

TEST(Polygon, RejectsNonFiniteCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of({{0, 0}, {1, nan}, {0, 1}}), "vertex 1 has a coordinate that is not finite");
  EXPECT_EQ(error_of({{0, 0}, {1, 0}, {inf, 1}}), "vertex 2 has a coordinate that is not finite");
}

TEST(Polygon, NamesTheCrossingEdges) {
  // A bow tie: edge 1-2 crosses edge 3-0.
  EXPECT_EQ(error_of({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), "not simple: edge 0-1 crosses edge 2-3");
}

TEST(Polygon, RejectsRepeatedVerticesAndFoldsAndDegenerateRings) {
  EXPECT_EQ(error_of({{0, 0}, {2, 0}, {1, 1}, {2, 0}, {2, 2}}), "not simple: vertices 1 and 3 coincide");
  EXPECT_EQ(error_of({{0, 0}, {2, 0}, {1, 0}, {1, 1}}), "not simple: edges 0-1 and 1-2 overlap");
  EXPECT_NE(error_of({{0, 0}, {1, 0}, {2, 0}}), "accepted");
  // A vertex touching another edge.
  EXPECT_NE(error_of({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}), "accepted");
}

TEST(Polygon, DropsTheClosingVertex) {
  auto v = square();
  v.push_back(v.front());
  EXPECT_EQ(Polygon::make(v).size(), 4u);
}

TEST(Polygon, MakesClockwiseInputCounterClockwiseAndRemembersTheOrder) {
  const std::vector<Point> cw = {{0, 0}, {0, 2}, {2, 2}, {2, 0}};
  const Polygon p = Polygon::make(cw);
  EXPECT_TRUE(p.input_was_clockwise());
  EXPECT_GT(twice_signed_area(p.vertices()), 0);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i], cw[p.input_index(i)]);
  EXPECT_EQ(p.input_index(0), 0u);
  const Polygon q = Polygon::make(square());
  EXPECT_FALSE(q.input_was_clockwise());
  EXPECT_EQ(q.input_index(3), 3u);
}

TEST(Polygon, KeepsCollinearVerticesAndDoesNotCountThemReflex) {
  const Polygon p = Polygon::make({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}});
  EXPECT_EQ(p.size(), 6u);
  EXPECT_FALSE(p.is_reflex(1));
  EXPECT_TRUE(p.is_reflex(4));
  EXPECT_EQ(p.reflex_count(), 1u);
}

TEST(Polygon, PredicatesAreExactNearDegeneracy) {
  // A vertex on a long edge at 2^30 is flat, not reflex; a point one unit off a line of slope 2^-31
  // is seen on its side, which a floating-point test with an epsilon would call collinear.
  const double big = 1073741824.0;  // 2^30
  const Polygon p = Polygon::make({{0, 0}, {2 * big, 1}, {big + 1, 1}, {0, 1}});
  EXPECT_EQ(p.reflex_count(), 0u);
  EXPECT_EQ(orient(Point(0, 0), Point(2 * big, 1), Point(big, 0.5)), 0);
  EXPECT_EQ(orient(Point(0, 0), Point(2 * big, 1), Point(big + 1, 0.5)), -1);
}

}  // namespace
}  // namespace pd
