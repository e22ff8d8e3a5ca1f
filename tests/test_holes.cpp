// Polygons with holes and multipolygons (issue 26): the checked door (rings, layout, merged vertices),
// the validator and the independent checker with holes, and every algorithm that takes holes.
#include "core/polygon.h"
#include "core/registry.h"
#include "core/ring_layout.h"
#include "core/validate.h"
#include "generators/rng.h"
#include "core/io.h"
#include "tests/command.h"
#include "tests/fixtures.h"
#include "tests/independent_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace pd {
namespace {

namespace fs = std::filesystem;

Ring square(double x0, double y0, double size) { return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}; }
Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}

std::string error_of(Rings rings) {
  try {
    Polygon::make_with_holes(std::move(rings));
  } catch (const PolygonError& e) {
    return e.what();
  }
  return "accepted";
}

std::string parts_error(std::vector<Rings> parts) {
  try {
    make_parts(std::move(parts));
  } catch (const PolygonError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Holes, RingsAreNumberedInOrderAndOriented) {
  // The hole given counter-clockwise is turned round; the outer ring given clockwise too.
  const Polygon p = Polygon::make_with_holes({reversed(square(0, 0, 10)), square(2, 2, 2), reversed(square(6, 6, 2))});
  EXPECT_EQ(p.size(), 12u);
  EXPECT_EQ(p.hole_count(), 2u);
  EXPECT_EQ(p.ring_begin(1), 4u);
  EXPECT_EQ(p.ring_end(2), 12u);
  EXPECT_EQ(p.ring_of(5), 1u);
  EXPECT_EQ(p.next(7), 4u);
  EXPECT_EQ(p.prev(4), 7u);
  EXPECT_GT(twice_signed_area(p.rings()[0]), 0);
  EXPECT_LT(twice_signed_area(p.rings()[1]), 0);
  EXPECT_LT(twice_signed_area(p.rings()[2]), 0);
  Rational area = 0;
  for (const Ring& ring : p.rings()) area += twice_signed_area(ring);
  EXPECT_EQ(area, Rational(2 * (100 - 4 - 4)));
  EXPECT_TRUE(p.input_was_clockwise());
  EXPECT_TRUE(p.ring_was_reversed(1));
  EXPECT_FALSE(p.ring_was_reversed(2));
  // Every hole corner is reflex for the polygon; the outer corners are not.
  EXPECT_EQ(p.reflex_count(), 8u);
  EXPECT_EQ(p.first_reflex(), 4u);
  // input_index: each ring keeps its first vertex, the rest of a turned ring runs backwards.
  const std::vector<Point> input = p.input_points();
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i], input[p.input_index(i)]) << i;
  EXPECT_EQ(p.input_index(4), 4u);
  EXPECT_EQ(p.input_index(5), 7u);
  EXPECT_EQ(p.input_index(9), 9u);
}

TEST(Holes, RepeatedVerticesAreMergedAndRemembered) {
  // Vertex 2 repeats 1, vertex 5 repeats 0 across the ring's end, the hole repeats its last vertex.
  const Polygon p = Polygon::make_with_holes(
      {{{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}, {{2, 2}, {2, 4}, {4, 4}, {4, 2}, {4, 2}}});
  EXPECT_EQ(p.size(), 8u);
  EXPECT_EQ(p.input_size(), 10u);
  using Merge = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(p.merged(), (std::vector<Merge>{{2, 1}, {9, 8}}));
  const std::vector<Point> input = p.input_points();
  ASSERT_EQ(input.size(), 10u);
  EXPECT_EQ(input[2], Point(10, 0));
  EXPECT_EQ(input[9], Point(4, 2));
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i], input[p.input_index(i)]) << i;
  const Polygon q = Polygon::make({{0, 0}, {0, 0}, {4, 0}, {4, 4}, {4, 4}, {4, 4}, {0, 4}, {0, 0}});
  EXPECT_EQ(q.size(), 4u);
  EXPECT_EQ(q.merged(), (std::vector<Merge>{{1, 0}, {4, 3}, {5, 3}}));
  EXPECT_EQ(error_of({{{0, 0}, {0, 0}, {1, 0}, {1, 0}}}), "2 vertices once repeated vertices are merged; a polygon needs at least 3");
  // A spike is a change of geometry, not a repeat: refused with the vertices named in the file's order.
  EXPECT_EQ(error_of({{{0, 0}, {0, 0}, {4, 0}, {6, 0}, {4, 0}, {4, 4}}}), "not simple: vertices 2 and 4 coincide");
}

TEST(Holes, EachRingIsCheckedAndNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of({square(0, 0, 10), {{2, 2}, {3, 3}}}), "hole 1 has 2 vertices; a ring needs at least 3");
  EXPECT_EQ(error_of({square(0, 0, 10), {{2, 2}, {3, nan}, {2, 3}}}), "vertex 1 of hole 1 has a coordinate that is not finite");
  EXPECT_EQ(error_of({square(0, 0, 10), square(1, 1, 1), {{2, 2}, {4, 4}, {4, 2}, {2, 4}}}),
            "hole 2 is not simple: edge 0-1 crosses edge 2-3");
  EXPECT_EQ(error_of({{{0, 0}, {9, 9}, {9, 0}, {0, 9}}, square(1, 1, 1)}), "the outer ring is not simple: edge 0-1 crosses edge 2-3");
}

TEST(Holes, TheLayoutIsCheckedWithTheRingsNamed) {
  const Ring outer = square(0, 0, 10);
  EXPECT_EQ(error_of({outer, {{0, 0}, {2, 1}, {1, 2}}}), "vertex 0 of the outer ring coincides with vertex 0 of hole 1");
  EXPECT_EQ(error_of({outer, {{5, 0}, {6, 2}, {4, 2}}}), "edge 0-1 of the outer ring touches edge 2-0 of hole 1");
  EXPECT_EQ(error_of({outer, {{5, 5}, {12, 6}, {5, 7}}}), "edge 1-2 of the outer ring crosses edge 0-1 of hole 1");
  EXPECT_EQ(error_of({outer, {{12, 5}, {13, 5}, {12, 6}}}), "hole 1 is not inside the outer ring");
  EXPECT_EQ(error_of({outer, square(-5, -5, 20)}), "hole 1 is not inside the outer ring");
  EXPECT_EQ(error_of({outer, square(1, 1, 6), square(2, 2, 2)}), "hole 2 lies inside hole 1");
  EXPECT_EQ(error_of({outer, square(1, 1, 2), square(3, 1, 2)}), "vertex 1 of hole 1 coincides with vertex 0 of hole 2");
  EXPECT_EQ(error_of({outer, square(1, 1, 2), square(3, 1.5, 1)}), "edge 1-2 of hole 1 touches edge 0-1 of hole 2");
  EXPECT_EQ(error_of({outer, square(1, 1, 4), {{2, 2}, {8, 3}, {2, 3}}}), "edge 1-2 of hole 1 crosses edge 0-1 of hole 2");
  EXPECT_EQ(error_of({outer, square(1, 1, 3), square(5, 5, 3)}), "accepted");
}

TEST(Holes, MultipolygonPartsMayNotMeetOrOverlap) {
  const Rings donut = {square(0, 0, 10), square(2, 2, 6)};
  EXPECT_EQ(parts_error({donut, {square(3, 3, 2)}}), "accepted");  // an island in the lake
  EXPECT_EQ(parts_error({donut, {square(20, 0, 2)}}), "accepted");
  EXPECT_EQ(parts_error({donut, {square(1, 1, 0.5)}}), "part 1 lies inside part 0");
  EXPECT_EQ(parts_error({donut, {square(9, 9, 4)}}), "edge 2-3 of part 0's outer ring crosses edge 3-0 of part 1's outer ring");
  EXPECT_EQ(parts_error({donut, {square(10, 0, 2)}}), "vertex 1 of part 0's outer ring coincides with vertex 0 of part 1's outer ring");
  EXPECT_EQ(parts_error({{square(3, 3, 2)}, donut}), "accepted");
  EXPECT_EQ(parts_error({{square(-1, -1, 20)}, donut}), "part 1 lies inside part 0");
  EXPECT_EQ(parts_error({donut, {square(0.5, 0.5, 1), square(0.7, 0.7, 0.5)}}), "part 1 lies inside part 0");
  EXPECT_EQ(parts_error({donut, {square(0, 0, 10)}}), "vertex 0 of part 0's outer ring coincides with vertex 0 of part 1's outer ring");
  EXPECT_EQ(parts_error({donut, {{{1, 1}, {2, 2}}}}), "part 1: 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(parts_error({donut, {square(3, 3, 2), square(0.5, 0.5, 0.5)}}), "part 1: hole 1 is not inside the outer ring");
  EXPECT_EQ(parts_error({{square(0, 0, 20), square(1, 1, 18)}, {square(2, 2, 16), square(25, 2, 1)}}),
            "part 1: hole 1 is not inside the outer ring");
}

// The layout sweep against the brute force of every pair of edges and point location, on random
// triangles in a small grid (so that rings touch, share vertices and run along one another often).
bool layout_brute_force(const std::vector<independent::Cycle>& rings) {
  for (std::size_t a = 0; a < rings.size(); ++a)
    for (std::size_t b = a + 1; b < rings.size(); ++b)
      for (std::size_t i = 0; i < rings[a].size(); ++i)
        for (std::size_t j = 0; j < rings[b].size(); ++j) {
          const QPoint &p = rings[a][i], &q = rings[a][(i + 1) % rings[a].size()];
          const QPoint &s = rings[b][j], &t = rings[b][(j + 1) % rings[b].size()];
          if (independent::proper_cross(p, q, s, t) || independent::on_segment(p, q, s) ||
              independent::on_segment(s, t, p))
            return false;
        }
  for (std::size_t k = 1; k < rings.size(); ++k) {
    if (independent::locate(rings[0], rings[k][0]) != 1) return false;
    for (std::size_t j = 1; j < rings.size(); ++j)
      if (j != k && independent::locate(rings[j], rings[k][0]) == 1) return false;
  }
  return true;
}

TEST(Holes, TheLayoutSweepAgreesWithTheBruteForce) {
  Rng rng(26);
  std::size_t accepted = 0, trials = 0;
  for (; trials < 4000; ++trials) {
    Rings rings = {{{0, 0}, {12, 0}, {6, 12}}};
    const std::size_t holes = 1 + rng.below(3);
    for (std::size_t k = 0; k < holes; ++k) {
      Ring t;
      for (int c = 0; c < 3; ++c) t.emplace_back(static_cast<double>(rng.below(13)), static_cast<double>(rng.below(13)));
      if (orient(t[0], t[1], t[2]) == 0) t[2] = Point(t[2].x() + 1, t[2].y());
      if (orient(t[0], t[1], t[2]) == 0) continue;
      rings.push_back(t);
    }
    std::vector<independent::Cycle> exact;
    for (const Ring& r : rings) {
      independent::Cycle c;
      for (const Point& q : r) c.push_back(to_exact(q));
      if (independent::area2(c) < 0) std::reverse(c.begin(), c.end());
      exact.push_back(c);
    }
    const bool expected = layout_brute_force(exact);
    const std::string got = error_of(rings);
    EXPECT_EQ(got == "accepted", expected) << trials << ": " << got;
    accepted += expected;
  }
  EXPECT_GT(accepted, 50u);
  EXPECT_LT(accepted, trials / 2);
}

// A square with a square hole: the validator's verdicts on tilings right and wrong.
TEST(Holes, TheValidatorChecksEveryHoleEdgeAndTheTriangleCount) {
  const Polygon p = Polygon::make_with_holes({square(0, 0, 4), {{1, 1}, {1, 3}, {3, 3}, {3, 1}}});
  // Outer 0..3 = (0,0) (4,0) (4,4) (0,4); hole 4..7 = (1,1) (1,3) (3,3) (3,1), clockwise.
  Decomposition d;
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 4}, {0, 7}, {1, 7}, {1, 6}, {2, 6}, {2, 5}, {3, 5}, {3, 4}})
    d.add_cut(a, b);
  EXPECT_TRUE(validate(p, d, Kind::Triangulation, false).ok) << validate(p, d, Kind::Triangulation, false).reason;
  EXPECT_TRUE(validate(p, d, Kind::Convex, false).ok);
  // Four trapezoids, one per side.
  Decomposition trapezoids;
  for (int k = 0; k < 4; ++k) trapezoids.add_cut(k, 4 + (4 - k) % 4);
  EXPECT_TRUE(validate(p, trapezoids, Kind::Convex, false).ok) << validate(p, trapezoids, Kind::Convex, false).reason;
  EXPECT_FALSE(validate(p, trapezoids, Kind::Triangulation, false).ok);
  // One cut too few: a piece wraps round the hole.
  Decomposition wrap;
  for (int k = 0; k < 3; ++k) wrap.add_cut(k, 4 + (4 - k) % 4);
  EXPECT_FALSE(validate(p, wrap, Kind::Convex, false).ok);
  // Pieces that cover the hole: the outer square alone, and the outer square plus the hole.
  const std::vector<QPoint> pts = exact_points(p, Decomposition{});
  EXPECT_FALSE(validate_pieces(p, pts, {{0, 1, 2, 3}}, Kind::Convex, false).ok);
  const Validation both = validate_pieces(p, pts, {{0, 1, 2, 3}, {4, 7, 6, 5}}, Kind::Convex, false);
  EXPECT_FALSE(both.ok);
  EXPECT_EQ(both.reason, "boundary edge 4-5 is not covered exactly once from inside");
}

// Random polygons with holes: a lattice square outline with h random disjoint square holes.
std::vector<Polygon> holed_polygons() {
  std::vector<Polygon> out;
  Rng rng(2026);
  for (int trial = 0; out.size() < 40 && trial < 4000; ++trial) {
    Rings rings = {{{0, 0}, {20, 0}, {20, 20}, {10, 25}, {0, 20}}};
    const std::size_t holes = 1 + rng.below(5);
    for (std::size_t k = 0; k < holes; ++k) {
      const double x = 1 + static_cast<double>(rng.below(16)), y = 1 + static_cast<double>(rng.below(16));
      const double w = 1 + static_cast<double>(rng.below(3));
      Ring hole = rng.below(2) ? Ring{{x, y}, {x + w, y + 1}, {x + w / 2, y + w}} : square(x, y, w);
      rings.push_back(hole);
    }
    try {
      out.push_back(Polygon::make_with_holes(rings));
    } catch (const PolygonError&) {
    }
  }
  return out;
}

TEST(Holes, EveryAlgorithmThatTakesHolesIsValid) {
  const std::vector<Polygon> polygons = holed_polygons();
  ASSERT_GE(polygons.size(), 30u);
  std::size_t takers = 0;
  for (const Algorithm& a : algorithms()) {
    if (!a.accepts.holes || a.peer.rfind("external", 0) == 0) continue;
    ++takers;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
      const Polygon& p = polygons[k];
      Counters counters;
      const Decomposition d = a.run(p, counters);
      const Validation v = validate(p, d, a.kind, a.steiner);
      if (!is_peer(a)) {
        EXPECT_TRUE(v.ok) << a.name << " on polygon " << k << ": " << v.reason;
      }
      if (!v.ok) continue;
      const std::vector<Piece> pieces = pieces_of(p, d);
      const std::size_t n = p.size(), h = p.hole_count(), r = p.reflex_count();
      if (a.kind == Kind::Triangulation) {
        EXPECT_EQ(pieces.size(), n + 2 * h - 2) << a.name;
      }
      if (a.kind == Kind::Convex) {
        EXPECT_GE(pieces.size() + h, (r + 1) / 2 + 1) << a.name;
      }
      if (a.pieces_bound == "== r+1-h") {
        EXPECT_EQ(pieces.size() + h, r + 1) << a.name << " on polygon " << k;
      }
      if (d.steiner.empty()) {
        const std::vector<QPoint> pts = exact_points(p, d);
        std::vector<independent::Cycle> cycles;
        for (const Piece& piece : pieces) {
          independent::Cycle c;
          for (VertexId v : piece) c.push_back(pts[v]);
          cycles.push_back(c);
        }
        EXPECT_TRUE(independent::tiles_once(independent::rings_of(p), cycles, a.kind != Kind::Partition)) << a.name;
      }
    }
  }
  EXPECT_GE(takers, 6u);
}

TEST(Holes, AlgorithmsThatDoNotTakeHolesRefuseThem) {
  const Polygon p = Polygon::make_with_holes({square(0, 0, 10), square(2, 2, 2), square(6, 6, 2)});
  for (const Algorithm& a : algorithms())
    if (!a.accepts.holes) {
      EXPECT_EQ(refusal(a, p).value_or(""), a.name + " does not take polygons with holes; this one has 2 holes");
    }
}


// Every earcut fixture, whole: accepted, or refused with the defect named (an empty verdict: accepted).
// earcut takes them all, repairing with a tolerance what it can (rings that touch, repeated points,
// one-point holes as Steiner points); polydecomp, exact, refuses any polygon whose rings share a point
// or cross, whose ring touches itself, or whose ring has fewer than 3 vertices. Repeated consecutive
// vertices are merged, not refused (eberly-6).
const std::map<std::string, std::string> kFixtureVerdicts = {
    {"bad-diagonals", "not simple: vertices 2 and 7 coincide"},
    {"bad-hole", "hole 1 is not simple: edges 7-8 and 8-9 overlap"},
    {"boxy", "vertex 6 of hole 1 coincides with vertex 0 of hole 3"},
    {"building", ""},
    {"collinear-diagonal", "not simple: vertices 17 and 20 coincide"},
    {"degenerate", "not simple: vertices 2 and 4 coincide"},
    {"dude", ""},
    {"earcut", ""},
    {"eberly-3", "vertex 36 of the outer ring coincides with vertex 0 of hole 2"},
    {"eberly-6", ""},
    {"empty-square", "vertex 0 of the outer ring coincides with vertex 0 of hole 1"},
    {"filtered-bridge-jhl", ""},
    {"hilbert", ""},
    {"hole-touching-outer", "vertex 9 of the outer ring coincides with vertex 1 of hole 1"},
    {"hourglass", "not simple: vertices 1 and 4 coincide"},
    {"infinite-loop-jhl", "vertex 0 of the outer ring coincides with vertex 2 of hole 1"},
    {"issue107", "the outer ring has 2 vertices; a ring needs at least 3"},
    {"issue111", "the outer ring is not simple: edge 0-1 crosses edge 3-4"},
    {"issue119", "vertex 1 of hole 1 coincides with vertex 0 of hole 4"},
    {"issue131", "edge 2-3 of the outer ring touches edge 3-4 of hole 1"},
    {"issue142", "vertex 1 of the outer ring coincides with vertex 4 of hole 1"},
    {"issue147", "edge 2-3 of hole 1 touches edge 0-1 of hole 2"},
    {"issue149", "the outer ring is not simple: vertices 4 and 8 coincide"},
    {"issue16", ""},
    {"issue17", ""},
    {"issue186", "not simple: edges 82-0 and 0-1 overlap"},
    {"issue29", ""},
    {"issue34", ""},
    {"issue35", ""},
    {"issue45", "vertex 3 of the outer ring coincides with vertex 2 of hole 1"},
    {"issue52", ""},
    {"issue83", "hole 2 has 1 vertex once repeated vertices are merged; a ring needs at least 3"},
    {"outside-ring", "vertex 3 of the outer ring coincides with vertex 2 of hole 1"},
    {"rain", "vertex 37 of hole 2 coincides with vertex 8 of hole 3"},
    {"self-tangent-1", "vertex 15 of the outer ring coincides with vertex 0 of hole 2"},
    {"self-tangent-2", "vertex 14 of the outer ring coincides with vertex 1 of hole 1"},
    {"self-tangent-3", "vertex 0 of the outer ring coincides with vertex 0 of hole 11"},
    {"self-tangent-4", "vertex 30 of the outer ring coincides with vertex 4 of hole 20"},
    {"self-touching", "the outer ring is not simple: vertices 97 and 100 coincide"},
    {"shared-points", "not simple: vertices 2 and 5 coincide"},
    {"simplified-us-border", "the outer ring is not simple: edge 52-53 crosses edge 55-56"},
    {"steiner", "hole 1 has 1 vertex; a ring needs at least 3"},
    {"touching-holes", "vertex 1 of hole 5 coincides with vertex 1 of hole 7"},
    {"touching-holes2", "vertex 1 of hole 1 coincides with vertex 1 of hole 2"},
    {"touching-holes3", "vertex 0 of hole 1 coincides with vertex 0 of hole 2"},
    {"touching-holes4", "vertex 0 of hole 1 coincides with vertex 0 of hole 2"},
    {"touching-holes5", "vertex 0 of hole 1 coincides with vertex 0 of hole 2"},
    {"touching-holes6", "vertex 1 of hole 43 coincides with vertex 1 of hole 44"},
    {"touching2", "edge 4-5 of the outer ring touches edge 2-0 of hole 1"},
    {"touching3", "vertex 4 of the outer ring coincides with vertex 1 of hole 1"},
    {"touching4", "vertex 1 of hole 3 coincides with vertex 1 of hole 4"},
    {"water-huge", "the outer ring is not simple: vertices 4528 and 4531 coincide"},
    {"water-huge2", "the outer ring is not simple: vertices 0 and 169 coincide"},
    {"water-huge3", "vertex 2676 of the outer ring coincides with vertex 1 of hole 1309"},
    {"water", "the outer ring is not simple: vertices 2391 and 2395 coincide"},
    {"water2", "the outer ring is not simple: edges 26-27 and 27-29 overlap"},
    {"water3", "edge 1-2 of the outer ring touches edge 6-7 of hole 2"},
    {"water3b", "edge 1-2 of the outer ring touches edge 6-7 of hole 1"},
    {"water4", "hole 5 is not simple: edge 3-4 crosses edge 81-0"},
};

// How many triangles fewer than n + 2h - 2 earcut's tests expect on the accepted fixtures where its
// result is not a full triangulation.
const std::map<std::string, std::size_t> kEarcutFewer = {
    {"earcut", 10}, {"eberly-6", 1}, {"filtered-bridge-jhl", 3}, {"issue34", 1}, {"issue35", 2}, {"issue52", 1}};

// The number of triangles earcut's own tests expect (expected.json).
std::map<std::string, std::size_t> earcut_triangle_counts() {
  std::ifstream in(PD_SOURCE_DIR "/data/earcut-fixtures/expected.json");
  std::ostringstream text;
  text << in.rdbuf();
  std::map<std::string, std::size_t> counts;
  const Json doc = parse_json(text.str());
  for (const auto& [name, count] : doc.get("triangles")->fields)
    counts[name] = static_cast<std::size_t>(count.number());
  return counts;
}

TEST(EarcutFixtures, EachIsTriangulatedOrRefusedForItsDefect) {
  const auto expected = earcut_triangle_counts();
  std::size_t accepted = 0, with_holes = 0, full_in_earcut = 0;
  for (const auto& path : fixtures::earcut_files()) {
    const std::string name = path.stem().string();
    ASSERT_EQ(kFixtureVerdicts.count(name), 1u) << name;
    std::vector<Polygon> parts;
    std::string verdict;
    try {
      parts = make_parts(read_parts_file(path.string()));
    } catch (const PolygonError& e) {
      verdict = e.what();
    }
    EXPECT_EQ(verdict, kFixtureVerdicts.at(name)) << name;
    if (!verdict.empty()) continue;
    ++accepted;
    const Polygon& p = parts.at(0);
    with_holes += p.hole_count() > 0;
    // earcut's count is a full triangulation's (n + 2h - 2) on 6 of them; on the others it has fewer
    // triangles (it drops collinear and nearly collinear points, and earcut's tests allow it to miss
    // some area), by as many as kEarcutFewer says.
    const std::size_t triangles = p.size() + 2 * p.hole_count() - 2;
    const auto fewer = kEarcutFewer.find(name);
    EXPECT_EQ(triangles - expected.at(name), fewer == kEarcutFewer.end() ? 0 : fewer->second) << name;
    full_in_earcut += expected.at(name) == triangles;
    for (const Algorithm& a : algorithms()) {
      if (!a.accepts.holes || is_peer(a) || p.size() > a.size_ceiling) continue;
      Counters counters;
      const Decomposition d = a.run(p, counters);
      const Validation v = validate(p, d, a.kind, a.steiner);
      EXPECT_TRUE(v.ok) << a.name << " on " << name << ": " << v.reason;
      if (v.ok && a.kind == Kind::Triangulation) {
        EXPECT_EQ(pieces_of(p, d).size(), triangles) << a.name << " on " << name;
      }
    }
  }
  EXPECT_EQ(accepted, 12u);
  EXPECT_EQ(with_holes, 10u);
  EXPECT_EQ(full_in_earcut, 6u);  // building, dude, hilbert, issue16, issue17, issue29
}

// A sweep over the families with holes: keys carry h, the algorithms that take holes are measured and
// valid with their counts (n + 2h - 2 triangles; the lower bound ceil(r/2) + 1 - h), the others are
// skipped with the reason; a curve of families with holes needs "h", and a curve without may not have it.
TEST(HoleFamilies, AreSweptWithHInTheKeys) {
  const fs::path dir = command::scratch_folder("polydecomp-hole-sweep");
  std::ofstream(dir / "sweeps.json")
      << "{\"holes\": {\"description\": \"holes\", \"algorithms\": [\"monotone\", \"hertel-mehlhorn\", \"keil\"], "
         "\"seeds\": [1], \"min_time\": 0.001, \"budget_seconds\": 5, \"timeout_seconds\": 60, \"curves\": ["
         "{\"vs\": \"n\", \"families\": \"holes\", \"r\": [\"default\"], \"h\": [2], \"n\": [30, 60]},"
         "{\"vs\": \"h\", \"families\": [\"convex-holes\"], \"n\": [60], \"r\": [\"n/2\"], \"h\": [1, 3]}]},"
         " \"bad\": {\"description\": \"no h\", \"algorithms\": \"all\", \"seeds\": [1], \"min_time\": 0.001, "
         "\"budget_seconds\": 5, \"timeout_seconds\": 60, \"curves\": [{\"vs\": \"n\", \"families\": \"holes\", "
         "\"r\": [\"default\"], \"n\": [30]}]}}\n";
  const command::Result r =
      command::run(PD_BENCH " --sweep holes --sweeps " + (dir / "sweeps.json").string() + " --out " + dir.string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream journal(dir / "holes.journal.jsonl");
  std::map<std::string, std::string> status;
  for (std::string line; std::getline(journal, line);) {
    const Json j = parse_json(line);
    if (!j.get("status")) continue;
    const std::string name = j.get("name")->text;
    status[name] = j.get("status")->text;
    if (name.rfind("keil/", 0) == 0) {
      EXPECT_NE(j.get("error_message")->text.find("does not take polygons with holes"), std::string::npos) << name;
      continue;
    }
    EXPECT_EQ(j.get("status")->text, "ok") << name;
    const double n = j.get("n")->number(), h = j.get("h")->number(), r_ = j.get("r")->number();
    if (name.rfind("monotone/", 0) == 0) {
      EXPECT_EQ(j.get("pieces")->number(), n + 2 * h - 2) << name;
    }
    EXPECT_EQ(j.get("lower_bound")->number(), std::max(1.0, std::floor((r_ + 1) / 2) + 1 - h)) << name;
  }
  // 6 polygons (both families at n 30 and 60, h 2; convex-holes at n 60, h 1 and 3) x 3 algorithms
  EXPECT_EQ(status.size(), 18u);
  EXPECT_EQ(status.count("monotone/convex-holes/n:60/r:30/h:3/seed:1"), 1u);
  EXPECT_EQ(status.count("monotone/convex-holes/n:30/r:15/h:2/seed:1"), 1u);
  EXPECT_EQ(status.count("hertel-mehlhorn/comb-holes/n:60/r:43/h:2/seed:1"), 1u);
  const command::Result bad =
      command::run(PD_BENCH " --sweep bad --sweeps " + (dir / "sweeps.json").string() + " --out " + dir.string(), dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("missing \"h\""), std::string::npos) << bad.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pd
