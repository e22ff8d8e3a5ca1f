// The triangulations of issue 4 and the y-monotone partition on the shapes that break sweeps and ear
// clippers: collinear (180-degree) vertices, horizontal edges, many vertices at one height, spikes,
// and random lattice polygons (polyominoes under integer shears, every lattice point of the boundary
// kept), checked with the exact validator.
#include "core/registry.h"
#include "core/validate.h"
#include "engines/triangulation/diagonal_test.h"
#include "engines/triangulation/monotone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace pd {
namespace {

const std::vector<std::string>& triangulations() {
  static const std::vector<std::string> names = {"monotone", "ear-n3", "diagonal-n3", "diagonal-n4", "seidel"};
  return names;
}

using Ring = std::vector<Point>;

std::string describe(const Ring& ring) {
  std::string s;
  for (const Point& q : ring) s += "(" + std::to_string(q.x()) + "," + std::to_string(q.y()) + ")";
  return s;
}

void expect_triangulation(const std::string& name, const Ring& ring) {
  const Algorithm* a = find_algorithm(name);
  ASSERT_NE(a, nullptr) << name << " is not registered";
  const Polygon p = Polygon::make(ring);
  Counters counters;
  const Decomposition d = a->run(p, counters);
  EXPECT_EQ(d.cuts.size(), p.size() - 3) << name << " on " << describe(ring);
  const Validation v = validate(p, d, Kind::Triangulation, false);
  EXPECT_TRUE(v.ok) << name << " on " << describe(ring) << ": " << v.reason;
}

// Split and merge vertices in the sweep order: both neighbours on one side, reflex angle. Each needs a
// diagonal, and one diagonal serves at most two of them.
std::size_t split_and_merge_vertices(const Polygon& p) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool prev_above = above(p[p.prev(i)], p[i]), next_above = above(p[p.next(i)], p[i]);
    count += prev_above == next_above && p.is_reflex(i);
  }
  return count;
}

void expect_monotone_partition(const Ring& ring) {
  const Polygon p = Polygon::make(ring);
  Counters counters;
  const Decomposition d = find_algorithm("y-monotone")->run(p, counters);
  const Validation v = validate(p, d, Kind::Partition, false);
  EXPECT_TRUE(v.ok) << describe(ring) << ": " << v.reason;
  const std::size_t cusps = split_and_merge_vertices(p);
  EXPECT_LE(d.cuts.size(), cusps) << describe(ring);
  EXPECT_GE(2 * d.cuts.size(), cusps) << describe(ring);
}

void expect_all(const Ring& ring) {
  for (const std::string& name : triangulations()) expect_triangulation(name, ring);
  expect_monotone_partition(ring);
}

// Every rotation of the ring, and its mirror images, so that each special vertex meets the sweep and
// the ear scans in every role.
void expect_all_symmetries(Ring ring) {
  for (int mirror = 0; mirror < 4; ++mirror) {
    Ring r = ring;
    for (Point& q : r) q = Point(mirror & 1 ? -q.x() : q.x(), mirror & 2 ? -q.y() : q.y());
    for (std::size_t k = 0; k < r.size(); ++k) {
      expect_all(r);
      std::rotate(r.begin(), r.begin() + 1, r.end());
    }
  }
}

TEST(Triangulations, Triangle) {
  for (const std::string& name : triangulations()) {
    const Polygon p = Polygon::make({{0, 0}, {1, 0}, {0, 1}});
    Counters counters;
    EXPECT_TRUE(find_algorithm(name)->run(p, counters).cuts.empty()) << name;
  }
}

TEST(Triangulations, SquareWithCollinearVerticesOnEverySide) {
  expect_all_symmetries(
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}});
}

TEST(Triangulations, TriangleWithManyCollinearVertices) {
  // Only the three corners are strictly convex; a fan from one corner would be degenerate.
  expect_all_symmetries(
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {3, 1}, {2, 2}, {1, 3}, {0, 4}, {0, 3}, {0, 2}, {0, 1}});
}

TEST(Triangulations, CombWithHorizontalTeeth) {
  // Tips and gaps of the teeth all at one height: split vertices whose helpers are level with them.
  expect_all_symmetries({{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3},
                         {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
}

TEST(Triangulations, StaircaseOfHorizontalEdges) {
  expect_all_symmetries({{0, 0}, {4, 0}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 4}, {0, 4}});
}

TEST(Triangulations, MergeAndSplitVerticesAtTheSameHeight) {
  // An hourglass-like octagon whose two notches face each other at y = 2.
  expect_all_symmetries({{0, 0}, {4, 0}, {4, 4}, {3, 4}, {2, 2}, {1, 4}, {0, 4}, {1, 2}});
  expect_all_symmetries({{0, 0}, {1, 2}, {2, 0}, {3, 2}, {4, 0}, {4, 4}, {3, 4}, {2, 2}, {1, 4}, {0, 4}});
}

TEST(Triangulations, Spikes) {
  // Thin spikes out of and into a block, and a needle.
  expect_all_symmetries(
      {{0, -40}, {10, -40}, {10, 1}, {9, 1}, {8, 20}, {7, 1}, {5, 1}, {4, -30}, {3, 1}, {2, 1}, {1, 2}, {0, 1}});
  expect_all_symmetries({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 100}, {0, 100}});
}

TEST(Triangulations, SpiralWithCollinearRuns) {
  expect_all_symmetries({{0, 0}, {3, 0}, {6, 0}, {6, 6}, {1, 6}, {1, 4}, {1, 2}, {4, 2}, {4, 4}, {3, 4}, {3, 3},
                         {2, 3}, {2, 5}, {3, 5}, {5, 5}, {5, 3}, {5, 1}, {2, 1}, {0, 1}});
}

// A random polyomino on a small grid (cells added next to the set until it has `cells` of them), its
// boundary with every lattice point on it, mapped by a random unimodular integer shear. Returns
// nothing when the boundary is not one simple cycle (a hole or a pinch); the caller tries again.
std::optional<Ring> lattice_polygon(std::mt19937& rng, int cells) {
  std::set<std::pair<int, int>> set{{0, 0}};
  std::vector<std::pair<int, int>> list{{0, 0}};
  const int step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  while (static_cast<int>(set.size()) < cells) {
    const auto [x, y] = list[rng() % list.size()];
    const auto* s = step[rng() % 4];
    if (set.insert({x + s[0], y + s[1]}).second) list.push_back({x + s[0], y + s[1]});
  }
  // Unit boundary edges, counter-clockwise round each cell, where the neighbour is outside.
  std::map<std::pair<int, int>, std::pair<int, int>> next;
  for (const auto& [x, y] : set) {
    const std::pair<int, int> corner[4] = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
    for (int k = 0; k < 4; ++k)
      if (!set.count({x + step[(k + 3) % 4][0], y + step[(k + 3) % 4][1]}))
        if (!next.emplace(corner[k], corner[(k + 1) % 4]).second) return std::nullopt;
  }
  Ring ring;
  std::pair<int, int> at = next.begin()->first;
  do {
    ring.emplace_back(at.first, at.second);
    at = next.at(at);
  } while (at != next.begin()->first);
  if (ring.size() != next.size()) return std::nullopt;
  const int a = static_cast<int>(rng() % 5) - 2, b = static_cast<int>(rng() % 3) - 1;
  for (Point& q : ring) {
    const double x = q.x() + a * q.y();
    q = Point(x, q.y() + b * x);
  }
  return ring;
}

TEST(Triangulations, RandomLatticePolygons) {
  std::mt19937 rng(4);
  int tested = 0;
  while (tested < 300) {
    const std::optional<Ring> ring = lattice_polygon(rng, 2 + tested % 25);
    if (!ring) continue;
    ++tested;
    expect_all(*ring);
  }
}

TEST(Monotone, TriangulateMonotoneIsTheRegisteredAlgorithm) {
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 4}, {3, 4}, {2, 2}, {1, 4}, {0, 4}, {1, 2}});
  Counters c1, c2;
  const Decomposition a = triangulate_monotone(p, c1), b = find_algorithm("monotone")->run(p, c2);
  ASSERT_EQ(a.cuts.size(), 5u);
  for (std::size_t k = 0; k < a.cuts.size(); ++k) {
    EXPECT_EQ(a.cuts[k].a, b.cuts[k].a);
    EXPECT_EQ(a.cuts[k].b, b.cuts[k].b);
  }
  EXPECT_EQ(c1, c2);
  EXPECT_EQ(c1.at("pieces"), 2);  // the merge vertex (2, 2) needs the one diagonal
}

// Both diagonal-based programs build the greedy triangulation: the same diagonals in the same order.
TEST(DiagonalBased, ImprovedVersionOutputsTheSameDiagonals) {
  std::mt19937 rng(3);
  for (int tested = 0; tested < 100;) {
    const std::optional<Ring> ring = lattice_polygon(rng, 3 + tested % 20);
    if (!ring) continue;
    ++tested;
    const Polygon p = Polygon::make(*ring);
    Counters c3, c4;
    const Decomposition d3 = find_algorithm("diagonal-n3")->run(p, c3), d4 = find_algorithm("diagonal-n4")->run(p, c4);
    ASSERT_EQ(d3.cuts.size(), d4.cuts.size());
    for (std::size_t k = 0; k < d3.cuts.size(); ++k) {
      EXPECT_EQ(d3.cuts[k].a, d4.cuts[k].a) << describe(*ring);
      EXPECT_EQ(d3.cuts[k].b, d4.cuts[k].b) << describe(*ring);
    }
  }
}

TEST(DiagonalTest, ClosedSegmentsMeetExactly) {
  using diagonal_test::segments_meet;
  EXPECT_TRUE(segments_meet({0, 0}, {2, 2}, {0, 2}, {2, 0}));   // proper crossing
  EXPECT_TRUE(segments_meet({0, 0}, {2, 0}, {1, 0}, {1, 5}));   // T: an endpoint inside the other
  EXPECT_TRUE(segments_meet({0, 0}, {2, 0}, {2, 0}, {3, 1}));   // shared endpoint
  EXPECT_TRUE(segments_meet({0, 0}, {2, 0}, {1, 0}, {3, 0}));   // collinear, overlapping
  EXPECT_FALSE(segments_meet({0, 0}, {2, 0}, {3, 0}, {4, 0}));  // collinear, apart
  EXPECT_FALSE(segments_meet({0, 0}, {2, 0}, {1, 1}, {3, 1}));  // parallel
  EXPECT_FALSE(segments_meet({0, 0}, {2, 0}, {3, -1}, {3, 1}));  // the line of one crosses the other
  // One unit in the last place decides: (0.1, 0.1) is on the line y = x, the next double up is not.
  EXPECT_TRUE(segments_meet({0, 0}, {1, 1}, {0.1, 0.1}, {0.1, 5}));
  EXPECT_FALSE(segments_meet({0, 0}, {1, 1}, {0.1, std::nextafter(0.1, 1.0)}, {0.1, 5}));
}

// The counters show the bounds: ear-n3 tests every remaining vertex in every round.
TEST(EarN3, TestsEveryRemainingVertexEveryRound) {
  const Polygon p = Polygon::make({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}});
  Counters counters;
  find_algorithm("ear-n3")->run(p, counters);
  EXPECT_EQ(counters.at("rounds"), 7);
  EXPECT_EQ(counters.at("ear_tests"), 10 + 9 + 8 + 7 + 6 + 5 + 4);
  EXPECT_EQ(counters.at("point_tests"), 10 * 7 + 9 * 6 + 8 * 5 + 7 * 4 + 6 * 3 + 5 * 2 + 4 * 1);
}

// Both diagonal-based programs test every candidate in full: against every edge not at its ends.
TEST(DiagonalBased, TestEveryCandidateAgainstEveryEdge) {
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 4}, {3, 4}, {2, 2}, {1, 4}, {0, 4}, {1, 2}});
  const std::int64_t candidates = 8 * 5 / 2, edges = 8 - 4;
  Counters c3, c4;
  find_algorithm("diagonal-n3")->run(p, c3);
  find_algorithm("diagonal-n4")->run(p, c4);
  EXPECT_EQ(c3.at("diagonal_tests"), candidates);
  EXPECT_EQ(c3.at("edge_tests"), candidates * edges);
  // Round k tests the candidates not yet output: 20, 19, ..., 16 over the n-3 = 5 rounds.
  EXPECT_EQ(c4.at("diagonal_tests"), 20 + 19 + 18 + 17 + 16);
  EXPECT_EQ(c4.at("edge_tests"), (20 + 19 + 18 + 17 + 16) * edges);
  EXPECT_EQ(c4.at("crossing_tests"), 19 * 1 + 18 * 2 + 17 * 3 + 16 * 4);
}

// Seidel's insertion order is random but fixed: the same polygon gives the same diagonals. Phases end
// with rounds: for 16 < n < 65536 the first ends with round L - floor(log2 log2 n) and the second with
// round L - floor(log2 log2 log2 n); the third would end with round L - 0, the last, so it is one with
// the final phase.
TEST(Seidel, IsDeterministicAndCountsItsPhases) {
  std::mt19937 rng(7);
  std::optional<Ring> ring;
  while (!(ring = lattice_polygon(rng, 40)) || ring->size() <= 16) {}
  const Polygon p = Polygon::make(*ring);
  Counters c1, c2;
  const Decomposition a = find_algorithm("seidel")->run(p, c1), b = find_algorithm("seidel")->run(p, c2);
  ASSERT_EQ(a.cuts.size(), b.cuts.size());
  for (std::size_t k = 0; k < a.cuts.size(); ++k) EXPECT_TRUE(a.cuts[k].a == b.cuts[k].a && a.cuts[k].b == b.cuts[k].b);
  EXPECT_EQ(c1, c2);
  EXPECT_EQ(c1.at("phases"), 3) << p.size();
  EXPECT_GE(c1.at("trapezoids"), static_cast<std::int64_t>(3 * p.size()));
}

TEST(YMonotone, MonotonePolygonNeedsNoDiagonal) {
  const Polygon p = Polygon::make({{0, 0}, {2, 1}, {1, 2}, {3, 3}, {1, 5}, {-1, 4}, {0, 2}});
  Counters counters;
  EXPECT_TRUE(find_algorithm("y-monotone")->run(p, counters).cuts.empty());
}

}  // namespace
}  // namespace pd
