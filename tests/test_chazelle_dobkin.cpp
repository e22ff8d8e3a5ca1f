// Chazelle-Dobkin's pattern detection (engines/chazelle_dobkin/patterns.h) against the definitions:
// X2 (Theorem 13) against the brute-force diagonal test and the range cones written out with input
// predicates; X3 (Theorem 14) by building the pattern, finishing with the naive decomposition and
// validating the result exactly (a found pattern must save one piece), and, where it reports no
// pattern, by a grid of candidate Steiner points checked against the definition.
// Then the programs (chazelle-dobkin, chazelle-dobkin-n5): valid, between ceil(r/2) + 1 and min(keil-snoeyink, r + 1)
// pieces, the known optimum of the x-pattern family (2m + 1) and of facing pairs of notches (r/2 + 1),
// and at least as many patterns as an exhaustive search over compatible X2- and X3-patterns. The
// geodesics its scans use (engines/chazelle_dobkin/geodesics.h) against a brute-force shortest-path search. Last,
// chazelle-dobkin's X4 tables (the scan over loose points) against chazelle-dobkin-n5's search of every
// pair: the same count on every family, on every rotation (both pairings of the x4-quads groups), on
// jittered x4-quads with crossing rays and with spikes where only "XY inside P" fails; every X4 of
// chazelle-dobkin-n5 with angles below 180 degrees has a loose X4 on the same notches (a brute-force
// Lemma 9 check, Theorem 18's claim on samples); the rows E and W themselves, every entry against that
// brute force given the program's S; every row against walks that test P4 with the segment search; and
// the counters the time bound rests on.
#include "core/registry.h"
#include "core/validate.h"
#include "engines/chazelle_dobkin/geodesics.h"
#include "engines/chazelle_dobkin/patterns.h"
#include "engines/chazelle_dobkin/tables.h"
#include "engines/keil_snoeyink/stacks.h"
#include "engines/naive/naive.h"
#include "generators/family.h"
#include "generators/rng.h"
#include "tests/brute_force.h"
#include "tests/lattice_polygons.h"
#include "tests/same_decomposition.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>

#include <string>
#include <vector>

namespace pd {
namespace {

using ExactSegment = ExactKernel::Segment_2;

struct Sample {
  std::string family;
  std::size_t n, r;
  std::uint64_t seed;
};

std::vector<Sample> small_samples() {
  std::vector<Sample> out;
  for (std::uint64_t seed : {1, 2, 3}) {
    out.push_back({"random", 14, 5, seed});
    out.push_back({"random", 20, 7, seed});
    out.push_back({"notch-heavy", 12, 8, seed});
    out.push_back({"comb", 16, 6, seed});
    out.push_back({"few-notches", 16, 6, seed});
    out.push_back({"spiral", 16, 6, seed});
  }
  out.push_back({"x-pattern", 12, 3, 1});
  out.push_back({"x-pattern", 22, 6, 1});
  return out;
}

Polygon make(const Sample& s) { return Polygon::make(generate(s.family, s.n, s.r, s.seed)); }
std::string label(const Sample& s) {
  return s.family + " n=" + std::to_string(s.n) + " r=" + std::to_string(s.r) + " seed=" + std::to_string(s.seed);
}

// X lies in the closed range of notch v: the angles (v-1, v, X) and (X, v, v+1) are at most 180.
bool in_closed_range(const Polygon& p, std::size_t v, const Point& x) {
  return orient(p[p.prev(v)], p[v], x) >= 0 && orient(p[v], p[p.next(v)], x) >= 0;
}

TEST(ChazelleDobkinPatterns, X2IsADiagonalInBothRanges) {
  for (const Sample& s : small_samples()) {
    const Polygon p = make(s);
    cd::Patterns patterns(p);
    const auto& notches = patterns.notches();
    for (std::size_t i = 0; i < notches.size(); ++i)
      for (std::size_t j = 0; j < notches.size(); ++j) {
        if (i == j) continue;
        const VertexId a = notches[i], b = notches[j];
        const bool expected = brute::is_diagonal(p, a, b) && in_closed_range(p, a, p[b]) && in_closed_range(p, b, p[a]);
        EXPECT_EQ(patterns.x2(patterns.bare(i), patterns.bare(j)), expected) << label(s) << " notches " << a << ", " << b;
      }
  }
}

// Cuts from each of the three notches to s, then the naive decomposition for the other notches, its
// boundary searched edge by edge or through the convex chains (Chazelle-Dobkin's STEP 5).
Decomposition with_x3(const Polygon& p, const std::vector<VertexId>& notches, const std::array<std::size_t, 3>& triple,
                      const QPoint& s, Counters& counters, bool through_chains = false) {
  Decomposition d;
  const VertexId sid = static_cast<VertexId>(p.size() + d.add_steiner(s));
  std::vector<VertexId> rest;
  for (std::size_t k = 0; k < notches.size(); ++k) {
    if (k == triple[0] || k == triple[1] || k == triple[2]) d.add_cut(notches[k], sid);
    else rest.push_back(notches[k]);
  }
  return through_chains ? naive_complete_chains(p, d, rest, counters) : naive_complete(p, d, rest, counters);
}

TEST(ChazelleDobkinPatterns, XPatternTriangleHasItsX3AndNoX2) {
  const Polygon p = Polygon::make(generate("x-pattern", 12, 3, 1));
  cd::Patterns patterns(p);
  ASSERT_EQ(patterns.notches().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (i != j) {
        EXPECT_FALSE(patterns.x2(patterns.bare(i), patterns.bare(j)));
      }
    }
  }
  const auto s = patterns.x3(patterns.joint(patterns.bare(0)), patterns.joint(patterns.bare(1)), patterns.joint(patterns.bare(2)));
  ASSERT_TRUE(s.has_value());
  Counters counters;
  const Decomposition d = with_x3(p, patterns.notches(), {0, 1, 2}, *s, counters);
  const Validation v = validate(p, d, Kind::Convex, true);
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(pieces_of(p, d).size(), 3u);
}

// x4-quads: no notch lies in another's range and no point lies in three ranges (the family's
// header, (i) and (ii)), so no X2- or X3-pattern between bare notches.
TEST(ChazelleDobkinPatterns, X4QuadsHaveNoX2OrX3) {
  for (std::size_t m : {1, 2, 3})
    for (std::uint64_t seed : {1, 2}) {
      const std::size_t r = 4 * m, n = 3 * r + 4 + 9 * (seed - 1);
      const Polygon p = Polygon::make(generate("x4-quads", n, r, seed));
      const std::string where = label({"x4-quads", n, r, seed});
      cd::Patterns patterns(p);
      ASSERT_EQ(patterns.notches().size(), r) << where;
      for (std::size_t i = 0; i < r; ++i)
        for (std::size_t j = 0; j < r; ++j) {
          if (i != j) {
            EXPECT_FALSE(patterns.x2(patterns.bare(i), patterns.bare(j))) << where << " notches " << i << ", " << j;
          }
        }
      for (std::size_t i = 0; i < r; ++i)
        for (std::size_t j = i + 1; j < r; ++j)
          for (std::size_t k = j + 1; k < r; ++k)
            EXPECT_FALSE(patterns.x3(patterns.joint(patterns.bare(i)), patterns.joint(patterns.bare(j)),
                                     patterns.joint(patterns.bare(k))))
                << where << " notches " << i << ", " << j << ", " << k;
    }
}

// Every X3 found is a pattern: with it, the naive decomposition of the rest gives r pieces, valid,
// and the same segments when searched through the chains (STEP 5 around an interior Steiner point).
TEST(ChazelleDobkinPatterns, EveryX3FoundSavesOnePiece) {
  std::size_t found = 0;
  for (const Sample& s : small_samples()) {
    const Polygon p = make(s);
    cd::Patterns patterns(p);
    const std::size_t r = patterns.notches().size();
    for (std::size_t i = 0; i < r; ++i)
      for (std::size_t j = i + 1; j < r; ++j)
        for (std::size_t k = j + 1; k < r; ++k) {
          const auto steiner = patterns.x3(patterns.joint(patterns.bare(i)), patterns.joint(patterns.bare(j)), patterns.joint(patterns.bare(k)));
          if (!steiner) continue;
          ++found;
          Counters counters;
          const Decomposition d = with_x3(p, patterns.notches(), {i, j, k}, *steiner, counters);
          const Validation v = validate(p, d, Kind::Convex, true);
          EXPECT_TRUE(v.ok) << label(s) << " triple " << i << "," << j << "," << k << ": " << v.reason;
          EXPECT_EQ(pieces_of(p, d).size(), r) << label(s);
          const Decomposition chained = with_x3(p, patterns.notches(), {i, j, k}, *steiner, counters, true);
          EXPECT_TRUE(same_decomposition(d, chained)) << label(s) << " triple " << i << "," << j << "," << k;
        }
  }
  EXPECT_GT(found, 3u);
}

// The definition of an X3 Steiner point, written out apart from the detector: strictly inside the
// triangle of its notches (a point on a side would make that side a diagonal, an X2-pattern), in each
// notch's closed range (an edge along the extension of a side of the notch leaves 180 degrees there),
// and each edge free of P's boundary.
bool is_x3_steiner(const Polygon& p, const std::array<VertexId, 3>& v, const QPoint& s) {
  std::array<QPoint, 3> q;
  for (int k = 0; k < 3; ++k) q[k] = to_exact(p[v[k]]);
  for (int k = 0; k < 3; ++k)
    if (orient(q[k], q[(k + 1) % 3], s) <= 0) return false;
  for (int k = 0; k < 3; ++k) {
    const QPoint before = to_exact(p[p.prev(v[k])]), after = to_exact(p[p.next(v[k])]);
    if (orient(before, q[k], s) < 0 || orient(q[k], after, s) < 0) return false;
    const ExactSegment edge(q[k], s);
    for (std::size_t e = 0; e < p.size(); ++e) {
      if (e == v[k] || p.next(e) == v[k]) continue;
      if (CGAL::do_intersect(edge, ExactSegment(to_exact(p[e]), to_exact(p[p.next(e)])))) return false;
    }
  }
  return true;
}

// The two sources of the views (cd::Views), trees of geodesics over vertical chords and walks of the
// triangulation, share no code: they agree on every ordered pair of notches (the same diagonals, and
// views across along the same ray from the notch), on the families and on degenerate lattice polygons
// where segments between notches touch vertices, run along edges and along chords, and pass
// 180-degree vertices.
TEST(ChazelleDobkinPatterns, GeodesicsAndTheTriangulationGiveTheSameViews) {
  std::size_t pairs = 0, hidden = 0;
  auto compare = [&](const Polygon& p, const std::string& where) {
    const cd::Patterns by_trees(p, cd::Views::kGeodesics), by_walks(p, cd::Views::kTriangulation);
    const auto& notches = by_trees.notches();
    for (std::size_t a = 0; a < notches.size(); ++a)
      for (std::size_t b = 0; b < notches.size(); ++b) {
        if (a == b) continue;
        ++pairs;
        EXPECT_EQ(by_trees.diagonal(a, b), by_walks.diagonal(a, b)) << where << " notches " << a << ", " << b;
        const Point &z = p[notches[a]], &x = p[by_trees.transition(a, b)], &y = p[by_walks.transition(a, b)];
        hidden += by_walks.transition(a, b) != notches[b];
        EXPECT_TRUE(orient(z, x, y) == 0 && dot_sign(z, x, z, y) > 0)
            << where << " notches " << a << ", " << b << ": views through " << by_trees.transition(a, b) << " and "
            << by_walks.transition(a, b);
      }
  };
  for (const Family& f : families())
    for (std::size_t n : {20, 60, 120, 300})
      for (std::uint64_t seed : {1, 2, 3}) {
        const std::size_t r = f.default_reflex(n);
        if (!f.infeasible(n, r)) compare(Polygon::make(generate(f.name, n, r, seed)), label({f.name, n, r, seed}));
      }
  std::mt19937 rng(11);
  for (int round = 0; round < 1000; ++round)
    compare(lattice::lattice_polygon(8 + round % 17, 5 + round % 4, rng), "lattice polygon " + std::to_string(round));
  for (int round = 0; round < 1000; ++round)
    if (const std::optional<Polygon> p = lattice::notched_rectangle(rng))
      compare(*p, "notched rectangle " + std::to_string(round));
  EXPECT_GT(pairs, 100000u);
  EXPECT_GT(hidden, 50000u);
}

// Candidate Steiner points for notches v: a barycentric grid over their triangle, all weights positive;
// every point where two of the lines through the notches' sides cross, and the midpoints between
// consecutive crossings along each line: where a degenerate region (a point, or a segment along an arm
// of a range) lies.
std::vector<QPoint> x3_candidates(const Polygon& p, const std::array<VertexId, 3>& v) {
  constexpr int kGrid = 10;
  std::array<QPoint, 3> q;
  for (int k = 0; k < 3; ++k) q[k] = to_exact(p[v[k]]);
  std::vector<QPoint> out;
  for (int a = 1; a < kGrid; ++a)
    for (int b = 1; a + b < kGrid; ++b) {
      const int c = kGrid - a - b;
      out.emplace_back((a * q[0].x() + b * q[1].x() + c * q[2].x()) / kGrid, (a * q[0].y() + b * q[1].y() + c * q[2].y()) / kGrid);
    }
  std::vector<ExactKernel::Line_2> lines;
  for (int k = 0; k < 3; ++k) {
    lines.emplace_back(to_exact(p[p.prev(v[k])]), q[k]);
    lines.emplace_back(q[k], to_exact(p[p.next(v[k])]));
  }
  for (const ExactKernel::Line_2& line : lines) {
    std::vector<QPoint> on;
    for (const ExactKernel::Line_2& other : lines) {
      const auto crossing = CGAL::intersection(line, other);
      if (!crossing) continue;
      if (const QPoint* x = boost::get<QPoint>(&*crossing)) on.push_back(*x);
    }
    std::sort(on.begin(), on.end(), [](const QPoint& s, const QPoint& t) { return CGAL::compare_xy(s, t) < 0; });
    for (std::size_t k = 0; k < on.size(); ++k) {
      out.push_back(on[k]);
      if (k + 1 < on.size()) out.emplace_back((on[k].x() + on[k + 1].x()) / 2, (on[k].y() + on[k + 1].y()) / 2);
    }
  }
  return out;
}

// Where the detector finds no X3, no candidate is an X3 Steiner point: on the small family polygons,
// and on lattice polygons, where candidates fall on arms of ranges and where arms meet.
TEST(ChazelleDobkinPatterns, NoX3MissedAmongCandidates) {
  std::size_t triples = 0;
  auto check = [&](const Polygon& p, const std::string& where) {
    cd::Patterns patterns(p);
    const auto& notches = patterns.notches();
    const std::size_t r = notches.size();
    for (std::size_t i = 0; i < r; ++i)
      for (std::size_t j = i + 1; j < r; ++j)
        for (std::size_t k = j + 1; k < r; ++k) {
          if (patterns.x3(patterns.joint(patterns.bare(i)), patterns.joint(patterns.bare(j)), patterns.joint(patterns.bare(k)))) continue;
          const std::array<VertexId, 3> v{notches[i], notches[j], notches[k]};
          if (orient(p[v[0]], p[v[1]], p[v[2]]) <= 0) continue;
          ++triples;
          for (const QPoint& x : x3_candidates(p, v))
            EXPECT_FALSE(is_x3_steiner(p, v, x)) << where << " triple " << i << "," << j << "," << k << " at " << x;
        }
  };
  for (const Sample& s : small_samples()) check(make(s), label(s));
  std::mt19937 rng(14);
  for (int round = 0; round < 300; ++round)
    check(lattice::lattice_polygon(10 + round % 15, 5 + round % 6, rng), "lattice polygon " + std::to_string(round));
  EXPECT_GT(triples, 5000u);
}

// Notch a (the dent in the bottom) looks up a corridor between notches x and y onto the far wall of a
// room; the notch w in the room's lower left edge comes after that wall in boundary order, so a's view
// passes across w's position on the ray through y, not through x, though the boundary also turns
// away behind x. Taking x there would close a's range before the gap, and the X3-pattern of a, x and w,
// whose Steiner point lies in the gap, would be missed.
TEST(ChazelleDobkinPatterns, FindsTheX3SeenBetweenTwoWindows) {
  const Polygon p = Polygon::make({{30, -30}, {30, 20}, {10, 20}, {10, 50}, {200, 100}, {-200, 100}, {-105, 76},
                                   {-10, 50}, {-10, 20}, {-30, 20}, {-30, -30}, {-5, -30}, {0, -10}, {5, -30}});
  cd::Patterns patterns(p);
  const auto& notches = patterns.notches();
  ASSERT_EQ(notches, (std::vector<VertexId>{2, 3, 6, 7, 8, 12}));
  const std::size_t a = 5, x = 1, w = 2;
  const auto s = patterns.x3(patterns.bare_joint(a), patterns.bare_joint(x), patterns.bare_joint(w));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(is_x3_steiner(p, {notches[a], notches[x], notches[w]}, *s));
  Counters counters;
  const Decomposition d = with_x3(p, notches, {a, x, w}, *s, counters);
  const Validation v = validate(p, d, Kind::Convex, true);
  EXPECT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(pieces_of(p, d).size(), notches.size());
}

// ---- the programs (chazelle-dobkin and chazelle-dobkin-n5) ----

// Runs `name` on p, expects a valid result, returns its piece count (and its counters in `counters`).
std::size_t valid_pieces(const std::string& name, const Polygon& p, const std::string& where,
                         Counters* counters = nullptr) {
  const Algorithm* a = find_algorithm(name);
  Counters own;
  const Decomposition d = a->run(p, counters ? *counters : own);
  const Validation v = validate(p, d, Kind::Convex, true);
  EXPECT_TRUE(v.ok) << name << " on " << where << ": " << v.reason;
  return pieces_of(p, d).size();
}

const std::vector<std::string>& programs() {
  static const std::vector<std::string> names{"chazelle-dobkin", "chazelle-dobkin-n5"};
  return names;
}

// ceil(r/2) + 1 <= pieces <= min(diagonal-only optimum, r + 1) (Theorem 8; a diagonal decomposition is
// a decomposition with Steiner points allowed).
TEST(ChazelleDobkin, BetweenTheLowerBoundAndTheDiagonalOptimum) {
  std::vector<Sample> samples = small_samples();
  for (std::uint64_t seed : {4, 5, 6, 7}) {
    samples.push_back({"random", 30, 10, seed});
    samples.push_back({"notch-heavy", 20, 15, seed});
    samples.push_back({"comb", 30, 12, seed});
  }
  for (const Sample& s : samples) {
    const Polygon p = make(s);
    const std::size_t r = p.reflex_count();
    Counters counters;
    const std::size_t diagonal_only = keil_snoeyink(p, counters).cuts.size() + 1;
    for (const std::string& name : programs()) {
      const std::size_t pieces = valid_pieces(name, p, label(s));
      EXPECT_GE(pieces, (r + 1) / 2 + 1) << name << " on " << label(s);
      EXPECT_LE(pieces, std::min(diagonal_only, r + 1)) << name << " on " << label(s);
    }
  }
}

// The x-pattern family: one Steiner point per triple of slits, 2m + 1 pieces for m triples (3 for the
// slit triangle, where diagonals need 4).
TEST(ChazelleDobkin, ReachesTheXPatternOptimum) {
  for (std::size_t m : {1, 2, 3, 5})
    for (std::uint64_t seed : {1, 2}) {
      const std::size_t n = m == 1 ? 12 : 9 * m + 4;
      const Polygon p = Polygon::make(generate("x-pattern", n, 3 * m, seed));
      for (const std::string& name : programs())
        EXPECT_EQ(valid_pieces(name, p, "x-pattern m=" + std::to_string(m)), 2 * m + 1) << name << " m=" << m;
    }
}

// The x4-quads family: m groups of four slits, each resolved only by an X4-pattern, 3m + 1 pieces where
// diagonals need 4m + 1 (the family's header proves both). The program's m patterns are X4-patterns.
TEST(ChazelleDobkin, ReachesTheX4QuadsOptimum) {
  for (std::size_t m = 1; m <= 8; ++m)
    for (std::uint64_t seed : {1, 2}) {
      const std::size_t r = 4 * m, n = 3 * r + 4 + (seed == 1 ? 0 : 2 * r + 3);
      const Polygon p = Polygon::make(generate("x4-quads", n, r, seed));
      const std::string where = label({"x4-quads", n, r, seed});
      Counters diagonal;
      EXPECT_EQ(keil_snoeyink(p, diagonal).cuts.size() + 1, 4 * m + 1) << where;
      for (const std::string& name : programs()) {
        Counters counters;
        const Decomposition d = find_algorithm(name)->run(p, counters);
        const Validation v = validate(p, d, Kind::Convex, true);
        EXPECT_TRUE(v.ok) << name << " on " << where << ": " << v.reason;
        EXPECT_EQ(pieces_of(p, d).size(), 3 * m + 1) << name << " on " << where;
        EXPECT_EQ(counters["patterns"], static_cast<std::int64_t>(m)) << name << " on " << where;
        EXPECT_EQ(counters["pattern_steiner_points"], static_cast<std::int64_t>(2 * m)) << name << " on " << where;
        EXPECT_GT(counters["x4_found"], 0) << name << " on " << where;
      }
    }
}

// The program finds at least as many compatible patterns as an exhaustive search over the X2- and
// X3-patterns of bare notches (pairwise disjoint, notches not interleaving round the boundary): it
// also builds larger Y-patterns and X4-patterns, so it may find more, never fewer.
std::size_t most_small_patterns(const std::vector<std::vector<std::size_t>>& patterns, std::size_t r) {
  std::vector<int> owner(r, -1);
  auto interleave = [&](const std::vector<std::size_t>& a, int b) {
    // a and pattern b interleave when some notch of b lies strictly between two consecutive notches of
    // a and some other notch of b outside that gap.
    for (std::size_t x = 0; x < a.size(); ++x) {
      const std::size_t lo = a[x], hi = a[(x + 1) % a.size()];
      auto inside = [&](std::size_t v) { return lo < hi ? lo < v && v < hi : v > lo || v < hi; };
      bool in = false, out = false;
      for (std::size_t v = 0; v < r; ++v)
        if (owner[v] == b) (inside(v) ? in : out) = true;
      if (in && out) return true;
    }
    return false;
  };
  std::size_t best = 0;
  std::function<void(std::size_t, std::size_t)> search = [&](std::size_t from, std::size_t chosen) {
    best = std::max(best, chosen);
    for (std::size_t q = from; q < patterns.size(); ++q) {
      const auto& pattern = patterns[q];
      bool free = true;
      for (std::size_t v : pattern) free = free && owner[v] < 0;
      for (int b = 0; free && b < static_cast<int>(patterns.size()); ++b)
        if (std::find(owner.begin(), owner.end(), b) != owner.end()) free = !interleave(pattern, b);
      if (!free) continue;
      for (std::size_t v : pattern) owner[v] = static_cast<int>(q);
      search(q + 1, chosen + 1);
      for (std::size_t v : pattern) owner[v] = -1;
    }
  };
  search(0, 0);
  return best;
}

TEST(ChazelleDobkin, FindsAtLeastTheBestSetOfX2AndX3Patterns) {
  std::size_t samples_with_patterns = 0;
  for (const Sample& s : small_samples()) {
    const Polygon p = make(s);
    cd::Patterns patterns(p);
    const std::size_t r = patterns.notches().size();
    if (r > 9) continue;
    std::vector<std::vector<std::size_t>> small;
    for (std::size_t i = 0; i < r; ++i)
      for (std::size_t j = i + 1; j < r; ++j) {
        if (patterns.x2(patterns.bare(i), patterns.bare(j))) small.push_back({i, j});
        for (std::size_t k = j + 1; k < r; ++k)
          if (patterns.x3(patterns.joint(patterns.bare(i)), patterns.joint(patterns.bare(j)), patterns.joint(patterns.bare(k))))
            small.push_back({i, j, k});
      }
    const std::size_t expected = most_small_patterns(small, r);
    samples_with_patterns += expected > 0;
    for (const std::string& name : programs()) {
      const std::size_t pieces = valid_pieces(name, p, label(s));
      EXPECT_LE(pieces, r + 1 - expected) << name << " on " << label(s);
    }
  }
  EXPECT_GT(samples_with_patterns, 5u);
}

// A strip with m pairs of V-shaped dents facing each other across it: one segment resolves each pair,
// so r/2 + 1 = m + 1 pieces, the lower bound.
Polygon facing_pairs(int m) {
  std::vector<Point> v;
  v.emplace_back(0, 0);
  for (int k = 0; k < m; ++k) v.emplace_back(10 * k + 3, 0), v.emplace_back(10 * k + 5, 3), v.emplace_back(10 * k + 7, 0);
  v.emplace_back(10 * m, 0);
  v.emplace_back(10 * m, 10);
  for (int k = m; k-- > 0;) v.emplace_back(10 * k + 7, 10), v.emplace_back(10 * k + 5, 7), v.emplace_back(10 * k + 3, 10);
  v.emplace_back(0, 10);
  return Polygon::make(v);
}

TEST(ChazelleDobkin, ResolvesFacingPairsWithOneSegmentEach) {
  for (int m : {1, 2, 4, 7}) {
    const Polygon p = facing_pairs(m);
    ASSERT_EQ(p.reflex_count(), static_cast<std::size_t>(2 * m));
    for (const std::string& name : programs())
      EXPECT_EQ(valid_pieces(name, p, "facing pairs m=" + std::to_string(m)), static_cast<std::size_t>(m + 1)) << name;
  }
}

// ---- chazelle-dobkin's X4 tables (Sec. 2.4) against chazelle-dobkin-n5's search of every pair ----

Polygon rotated(const Polygon& p, std::size_t by) {
  std::vector<Point> ring(p.vertices());
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(by), ring.end());
  return Polygon::make(ring);
}

// Both programs valid and with the same piece count; returns it (and chazelle-dobkin's counters in
// `counters`).
std::size_t same_count(const Polygon& p, const std::string& where, Counters* counters = nullptr) {
  const std::size_t tables = valid_pieces("chazelle-dobkin", p, where, counters);
  EXPECT_EQ(tables, valid_pieces("chazelle-dobkin-n5", p, where)) << where;
  return tables;
}

// Geodesics (engines/chazelle_dobkin/geodesics.h) against a brute force that shares no code with them: which pairs of
// points (vertices, and points inside every third edge) see each other in the closed polygon, tested
// against every edge and vertex, then Dijkstra's shortest paths over those pairs. Every geodesic must
// join points that see each other, turn at every point it lists between its ends, and be as long as the
// brute force's shortest path: with all those points as terminals, and with only the notches and the
// points inside edges; each time with a second terminal at the first point inside an edge (two ray
// ends at one point). With `at_vertical_crossings`, the points inside edges are instead every point
// where an edge crosses the vertical line through a notch: the ends of the chords that the geodesics'
// decomposition draws are among them, so terminals and roots lie on chords.
struct GeodesicCheck {
  explicit GeodesicCheck(const Polygon& polygon, bool at_vertical_crossings = false) : p(polygon) {
    for (std::size_t v = 0; v < p.size(); ++v) {
      corners.push_back(to_exact(p[v]));
      terminals.push_back({v, true, corners.back()});
    }
    for (std::size_t e = 0; e < p.size(); ++e) {
      const QPoint a = to_exact(p[e]), b = to_exact(p[p.next(e)]);
      if (!at_vertical_crossings) {
        if (e % 3 == 0) terminals.push_back({e, false, a + (b - a) / Rational(3)});
        continue;
      }
      std::vector<Rational> crossings;
      for (std::size_t v = 0; v < p.size(); ++v) {
        const Rational x(p[v].x());
        if (p.is_reflex(v) && (a.x() - x) * (b.x() - x) < 0) crossings.push_back((x - a.x()) / (b.x() - a.x()));
      }
      std::sort(crossings.begin(), crossings.end());
      crossings.erase(std::unique(crossings.begin(), crossings.end()), crossings.end());
      for (const Rational& t : crossings) terminals.push_back({e, false, a + t * (b - a)});
    }
    const std::size_t count = terminals.size();
    sees.assign(count * count, 0);
    for (std::size_t a = 0; a < count; ++a)
      for (std::size_t b = a + 1; b < count; ++b)
        sees[a * count + b] = sees[b * count + a] = in_closed_polygon(terminals[a].point, terminals[b].point);
    distance.assign(count * count, 0);
    for (std::size_t from = 0; from < count; ++from) dijkstra(from);
  }

  // Whether the closed segment ab lies in the closed polygon: no edge crosses it inside both, and
  // between the vertices on it each piece lies inside or along the boundary (its midpoint does).
  // Whether the open segment ab, in the closed polygon, touches its boundary: a vertex lies strictly
  // inside it, or (with none there) an edge holds it whole, and so its midpoint.
  bool touches_boundary(const QPoint& a, const QPoint& b) const {
    const QPoint mid = a + (b - a) / Rational(2);
    const std::size_t n = corners.size();
    for (std::size_t e = 0; e < n; ++e) {
      const QPoint &u = corners[e], &w = corners[(e + 1) % n];
      if (orient(a, b, u) == 0 && CGAL::collinear_are_strictly_ordered_along_line(a, u, b)) return true;
      if (orient(u, w, mid) == 0 && CGAL::collinear_are_ordered_along_line(u, mid, w)) return true;
    }
    return false;
  }

  bool in_closed_polygon(const QPoint& a, const QPoint& b) const {
    std::vector<Rational> cuts{Rational(0), Rational(1)};
    const std::size_t n = corners.size();
    for (std::size_t e = 0; e < n; ++e) {
      const QPoint &u = corners[e], &w = corners[(e + 1) % n];
      if (orient(a, b, u) * orient(a, b, w) < 0 && orient(u, w, a) * orient(u, w, b) < 0) return false;
      if (orient(a, b, u) == 0 && CGAL::collinear_are_strictly_ordered_along_line(a, u, b))
        cuts.push_back(((u - a) * (b - a)) / ((b - a) * (b - a)));
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const QPoint mid = a + ((cuts[k] + cuts[k + 1]) / Rational(2)) * (b - a);
      if (CGAL::bounded_side_2(corners.begin(), corners.end(), mid, ExactKernel()) == CGAL::ON_UNBOUNDED_SIDE)
        return false;
    }
    return true;
  }

  double length(const QPoint& a, const QPoint& b) const { return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))); }

  void dijkstra(std::size_t from) {
    const std::size_t count = terminals.size();
    std::vector<double> best(count, 1e300);
    std::vector<char> done(count, 0);
    best[from] = 0;
    for (std::size_t round = 0; round < count; ++round) {
      std::size_t u = count;
      for (std::size_t v = 0; v < count; ++v)
        if (!done[v] && (u == count || best[v] < best[u])) u = v;
      done[u] = 1;
      for (std::size_t v = 0; v < count; ++v)
        if (sees[u * count + v]) best[v] = std::min(best[v], best[u] + length(terminals[u].point, terminals[v].point));
    }
    for (std::size_t v = 0; v < count; ++v) distance[from * count + v] = best[v];
  }

  // The terminal at point q (every point of a geodesic is one: a vertex or its end).
  std::size_t terminal_at(const QPoint& q) const {
    for (std::size_t t = 0; t < terminals.size(); ++t)
      if (terminals[t].point == q) return t;
    return terminals.size();
  }

  const Polygon& p;
  std::vector<QPoint> corners;
  std::vector<GeodesicTrees::Terminal> terminals;
  std::vector<char> sees;
  std::vector<double> distance;
};

// The funnel searches' first_holding finds the first index where a monotone predicate holds, from any
// guess, with at most 2 bit_width(d + 1) + 4 calls for d the answer's distance to the guess: what keeps
// a face's searches O(log r) each (geodesics.h). Every answer from every guess in every range up to 40
// entries, and answers near the guess in ranges of 2^16 and 2^20 entries.
TEST(Geodesics, SearchFromAGuessCostsTheLogOfTheDistance) {
  const auto check = [](std::size_t lo, std::size_t hi, std::size_t k, std::size_t guess) {
    std::int64_t calls = 0;
    const auto holds = [&](std::size_t i) {
      EXPECT_TRUE(lo <= i && i < hi) << i;
      ++calls;
      return i >= k;
    };
    EXPECT_EQ(first_holding(lo, hi, guess, holds), k) << lo << " " << hi << " " << guess;
    const std::size_t d = k > guess ? k - guess : guess - k;
    std::int64_t width = 0;
    while ((std::size_t{1} << width) <= d + 1) ++width;
    EXPECT_LE(calls, 2 * width + 4) << lo << " " << hi << " " << k << " " << guess;
  };
  for (std::size_t lo = 0; lo < 3; ++lo)
    for (std::size_t hi = lo; hi <= lo + 40; ++hi)
      for (std::size_t k = lo; k <= hi; ++k)
        for (std::size_t guess = lo; guess <= hi; ++guess) check(lo, hi, k, guess);
  for (std::size_t size : {std::size_t{1} << 16, std::size_t{1} << 20})
    for (std::size_t d = 0; d <= 8; ++d) {
      check(5, 5 + size, 5 + size / 2 + d, 5 + size / 2);
      check(5, 5 + size, 5 + size / 2 - d, 5 + size / 2);
    }
}

TEST(Geodesics, ShortestPathsOfTheBruteForce) {
  std::vector<std::pair<Polygon, std::string>> polygons;
  for (const Sample& s : small_samples()) {
    const Polygon p = make(s);
    for (std::size_t by : {std::size_t{0}, p.size() / 3}) polygons.emplace_back(rotated(p, by), label(s) + " rotated " + std::to_string(by));
  }
  // A U whose notches are joined by an edge that geodesics run along, with 180-degree vertices on the
  // bottom, on a side and on a notch's edge.
  for (const bool on_notch_edge : {false, true}) {
    std::vector<Point> u{{0, 0}, {3, 0}, {6, 0}, {6, 6}, {4, 6}, {4, 2}, {2, 2}, {2, 6}, {0, 6}, {0, 3}};
    if (on_notch_edge) u.insert(u.begin() + 7, Point(2, 4));
    polygons.emplace_back(Polygon::make(u), on_notch_edge ? "U with a flat vertex on a notch's edge" : "U");
  }
  // Lattice polygons: vertical edges, notches above one another, chords that end at vertices or run
  // into a vertex's corner; every point on a chord's line inside an edge a terminal.
  const std::size_t crossings_from = polygons.size();
  std::mt19937 rng(8);
  for (int round = 0; round < 120; ++round)
    polygons.emplace_back(lattice::lattice_polygon(8 + round % 9, 5 + round % 3, rng), "lattice polygon " + std::to_string(round));
  for (int round = 0; round < 60; ++round)
    if (const std::optional<Polygon> p = lattice::notched_rectangle(rng)) polygons.emplace_back(*p, "notched rectangle " + std::to_string(round));
  std::int64_t checked = 0, bent = 0, touching = 0;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const auto& [p, where] = polygons[k];
    const GeodesicCheck brute(p, k >= crossings_from);
    const std::size_t count = brute.terminals.size();
    // Every vertex and point as a terminal, then only the notches and the points inside edges, so that
    // the faces of the decomposition have few sites.
    std::vector<std::size_t> every(count), sparse;
    for (std::size_t t = 0; t < count; ++t) {
      every[t] = t;
      if (!brute.terminals[t].at_vertex || p.is_reflex(brute.terminals[t].edge)) sparse.push_back(t);
    }
    if (count > p.size())
      for (std::vector<std::size_t>* chosen : {&every, &sparse}) chosen->push_back(p.size());
    for (const std::vector<std::size_t>* chosen : {&every, &sparse}) {
      std::vector<GeodesicTrees::Terminal> terminals;
      for (std::size_t t : *chosen) terminals.push_back(brute.terminals[t]);
      GeodesicTrees trees(p, terminals);
      EXPECT_LE(trees.chords(), static_cast<std::int64_t>(2 * p.reflex_count())) << where;
      std::vector<const FilteredPoint*> path;
      for (std::size_t from = 0; from < chosen->size(); ++from)
        for (std::size_t to = 0; to < chosen->size(); ++to) {
          const std::size_t source = (*chosen)[from], target = (*chosen)[to];
          trees.path(from, to, path);
          ASSERT_EQ(path.front()->exact, brute.terminals[source].point) << where;
          ASSERT_EQ(path.back()->exact, brute.terminals[target].point) << where;
          double length = 0;
          for (std::size_t k = 0; k + 1 < path.size(); ++k) {
            const QPoint &a = path[k]->exact, &b = path[k + 1]->exact;
            const std::size_t ta = brute.terminal_at(a), tb = brute.terminal_at(b);
            ASSERT_LT(ta, count) << where;
            ASSERT_LT(tb, count) << where;
            EXPECT_TRUE(brute.sees[ta * count + tb]) << where << ": " << source << " -> " << target << " step " << k;
            if (k > 0) {
              EXPECT_NE(orient(path[k - 1]->exact, a, b), 0) << where << ": " << source << " -> " << target << " lists a point where it does not turn";
            }
            length += brute.length(a, b);
          }
          const double expected = brute.distance[source * count + target];
          EXPECT_NEAR(length, expected, 1e-9 * std::max(1.0, expected)) << where << ": " << source << " -> " << target;
          if (path.size() > 1) {
            // How the geodesic leaves its start (the views): towards its second point, and clear when
            // straight with its open segment off the boundary.
            const GeodesicTrees::Start start = trees.start(from, to);
            EXPECT_EQ(start.toward.point, path[1]->exact) << where << ": " << source << " -> " << target;
            const bool clear = path.size() == 2 && !brute.touches_boundary(path[0]->exact, path[1]->exact);
            EXPECT_EQ(start.clear, clear) << where << ": " << source << " -> " << target;
            touching += path.size() == 2 && !clear;
          }
          ++checked;
          bent += path.size() > 2;
        }
    }
  }
  EXPECT_GT(checked, 15000);
  EXPECT_GT(bent, 6000);
  EXPECT_GT(touching, 1000);
}

TEST(ChazelleDobkinTables, SameCountAsEveryPairOnEveryFamily) {
  std::size_t compared = 0;
  for (const Family& f : families())
    for (std::size_t r : {1, 3, 5, 8, 12, 16, 24})
      for (std::size_t n : {r + 5, 2 * r + 6, 3 * r + 9, 4 * r + 12}) {
        if (f.infeasible(n, r)) continue;
        for (std::uint64_t seed : {1, 2, 3}) {
          same_count(Polygon::make(generate(f.name, n, r, seed)), label({f.name, n, r, seed}));
          ++compared;
        }
      }
  EXPECT_GT(compared, 150u);
}

// One X4-pattern per group of x4-quads (at its smallest n, no padding): 3m + 1 pieces (r = 4m notches, naive r + 1, diagonals 4m + 1).
TEST(ChazelleDobkinTables, FindsTheX4PatternOfEachSlitGadget) {
  for (int m : {1, 2, 3}) {
    const Polygon p = Polygon::make(generate("x4-quads", 12 * m + 4, 4 * m, 1));
    const std::string where = "x4-quads groups m=" + std::to_string(m);
    ASSERT_EQ(p.reflex_count(), static_cast<std::size_t>(4 * m));
    Counters counters;
    EXPECT_EQ(same_count(p, where, &counters), static_cast<std::size_t>(3 * m + 1)) << where;
    EXPECT_GE(counters["x4_chosen"], m) << where;
    EXPECT_EQ(counters["patterns"], m) << where;
  }
}

TEST(ChazelleDobkinTables, SameCountOnEveryRotation) {
  for (int m : {1, 2}) {
    const Polygon p = Polygon::make(generate("x4-quads", 12 * m + 4, 4 * m, 1));
    for (std::size_t k = 0; k < p.size(); ++k)
      EXPECT_EQ(same_count(rotated(p, k), "x4-quads rotated"), static_cast<std::size_t>(3 * m + 1))
          << "m=" << m << " rotated " << k;
  }
  for (const Sample& s : {Sample{"random", 14, 6, 3}, Sample{"notch-heavy", 12, 7, 2}, Sample{"x-pattern", 13, 3, 2}}) {
    const Polygon p = make(s);
    for (std::size_t k = 0; k < p.size(); ++k) same_count(rotated(p, k), label(s) + " rotated " + std::to_string(k));
  }
}

// Rotating x4-quads moves the notch where the indexing starts, so a group's pairing falls to E (a
// rotation starting the notches at BR) or to W (starting at BL): both tables must be used.
TEST(ChazelleDobkinTables, BothPairingsAcrossRotations) {
  const Polygon p = Polygon::make(generate("x4-quads", 16, 4, 1));
  std::int64_t from_e = 0, from_w = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    Counters counters;
    find_algorithm("chazelle-dobkin")->run(rotated(p, k), counters);
    EXPECT_EQ(counters["x4_chosen"], 1) << "rotated " << k;
    from_w += counters["x4_chosen_from_w"];
    from_e += counters["x4_chosen"] - counters["x4_chosen_from_w"];
  }
  EXPECT_GT(from_e, 0);
  EXPECT_GT(from_w, 0);
}

// m groups of x4-quads' slits with each tip moved by up to 4 in x and y (seeded), so that the lines of
// a group's loose rays cross at all angles (the scan's non-parallel classes), and, with `spike`, a thin
// spike hanging from the top between some groups' Steiner points, where only P4 can fail.
Polygon jittered_quads(int m, std::uint64_t seed, bool spike) {
  Rng rng(seed);
  auto jitter = [&](int a) { return static_cast<double>(rng.between(-a, a)); };
  std::vector<Point> v{Point(0, 0)};
  for (int g = 0; g < m; ++g) {
    const double x0 = 80.0 * g;
    for (double mouth : {19.0, 59.0}) {
      const double tip = mouth == 19.0 ? 24 : 56;
      v.emplace_back(x0 + mouth, 0), v.emplace_back(x0 + tip + jitter(4), 12 + jitter(4)), v.emplace_back(x0 + mouth + 2, 0);
    }
  }
  v.emplace_back(80.0 * m, 0), v.emplace_back(80.0 * m, 60);
  for (int g = m; g-- > 0;) {
    const double x0 = 80.0 * g;
    v.emplace_back(x0 + 61, 60), v.emplace_back(x0 + 56 + jitter(4), 48 + jitter(4)), v.emplace_back(x0 + 59, 60);
    if (spike && rng.below(2) == 1) {
      const double x = x0 + 38 + jitter(4);
      v.emplace_back(x + 1, 60), v.emplace_back(x + jitter(3), 28 + jitter(6)), v.emplace_back(x - 1, 60);
    }
    v.emplace_back(x0 + 21, 60), v.emplace_back(x0 + 24 + jitter(4), 48 + jitter(4)), v.emplace_back(x0 + 19, 60);
  }
  v.emplace_back(0, 60);
  return Polygon::make(v);
}

TEST(ChazelleDobkinTables, SameCountOnJitteredQuadsWithSpikes) {
  std::int64_t chosen = 0, p4_failures = 0;
  for (int m : {1, 2, 3})
    for (bool spike : {false, true})
      for (std::uint64_t seed = 1; seed <= 15; ++seed) {
        const Polygon p = jittered_quads(m, seed, spike);
        for (std::size_t by : {std::size_t{0}, std::size_t{4}}) {
          const std::string where = "jittered quads m=" + std::to_string(m) + " spike=" + std::to_string(spike) +
                                    " seed=" + std::to_string(seed) + " rotated " + std::to_string(by);
          const Polygon turned = rotated(p, by);
          same_count(turned, where);
          cd::ProgramCubic alone(turned, cd::ProgramCubic::P4Test::kSegmentSearch);
          Counters counters;
          alone.run(counters);
          alone.report(counters);
          chosen += counters["x4_chosen"];
          p4_failures += counters["x4_p4_tests"] - counters["x4_table_witnesses"];
        }
      }
  EXPECT_GT(chosen, 30);
  EXPECT_GT(p4_failures, 0);
}

// Many small polygons of every family, each also rotated by a third of its vertices.
TEST(ChazelleDobkinTables, SameCountOnManySmallPolygons) {
  std::size_t compared = 0;
  for (const Family& f : families())
    for (std::size_t r : {4, 6, 8, 10})
      for (std::size_t n : {r + 4, 2 * r + 4}) {
        if (f.infeasible(n, r)) continue;
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
          const Polygon p = Polygon::make(generate(f.name, n, r, seed));
          for (std::size_t by : {std::size_t{0}, p.size() / 3}) {
            same_count(rotated(p, by), label({f.name, n, r, seed}) + " rotated " + std::to_string(by));
            ++compared;
          }
        }
      }
  EXPECT_GT(compared, 500u);
}

// Degenerate position, where A18' is assumed (docs/algorithms/chazelle-dobkin.md): lattice polygons,
// where loose rays stop at vertices, extensions run along edges and Steiner points fall on lines
// through vertices.
// The same count as chazelle-dobkin-n5, which does not rest on Theorem 18, and many rays stopped.
TEST(ChazelleDobkinTables, SameCountOnDegenerateLatticePolygons) {
  std::mt19937 rng(18);
  std::int64_t stopped = 0, polygons_with_stopped = 0;
  for (int round = 0; round < 600; ++round) {
    const Polygon p = lattice::lattice_polygon(16 + round % 25, 8 + round % 5, rng);
    Counters counters;
    same_count(p, "lattice polygon " + std::to_string(round), &counters);
    stopped += counters["x4_rays_at_vertex"];
    polygons_with_stopped += counters["x4_rays_at_vertex"] > 0;
  }
  EXPECT_GT(polygons_with_stopped, 500);
  EXPECT_GT(stopped, 2500);
}

// ---- Theorem 18 on samples: the X4-patterns of chazelle-dobkin-n5 (tips of Q) against loose ones ----

// Definition 2.4's loose X4-patterns on four notches, checked against Lemma 9 by brute force and apart
// from the scan: each Steiner point where the extensions of one edge of each of its two notches meet
// ahead of both; every angle at the Steiner points below 180 degrees; the edges free of P's boundary
// and meeting only at the Steiner points.
class LooseX4 {
 public:
  LooseX4(const Polygon& p, const std::vector<VertexId>& notches) : p_(p), notches_(notches) {
    for (const Point& v : p.vertices()) exact_.push_back(to_exact(v));
  }

  // The first Steiner point joins notches a and b, the second c and d (counter-clockwise order).
  bool exists(const std::array<std::size_t, 4>& t) const {
    for (int sides = 0; sides < 16; ++sides)
      if (holds(t, sides)) return true;
    return false;
  }

  // One of the 16 configurations: bit k of `sides` picks the edge of notch t[k] (0: forward, 1: backward).
  bool holds(const std::array<std::size_t, 4>& t, int sides) const {
    const auto x = meet(t[0], sides & 1, t[1], (sides >> 1) & 1);
    const auto y = meet(t[2], (sides >> 2) & 1, t[3], (sides >> 3) & 1);
    return x && y && is_x4(t, *x, *y);
  }

  const QPoint& z(std::size_t notch) const { return exact_[notches_[notch]]; }

 private:
  // Where the extensions beyond notches a and b of one of their edges each (side 0: the forward edge)
  // meet, ahead of both notches.
  std::optional<QPoint> meet(std::size_t a, int side_a, std::size_t b, int side_b) const {
    const ExactKernel::Vector_2 ua = z(a) - beside(a, side_a), ub = z(b) - beside(b, side_b), ab = z(b) - z(a);
    const Rational den = ua.x() * ub.y() - ua.y() * ub.x();
    if (den == 0) return std::nullopt;
    const Rational s = (ab.x() * ub.y() - ab.y() * ub.x()) / den, t = (ab.x() * ua.y() - ab.y() * ua.x()) / den;
    if (s <= 0 || t <= 0) return std::nullopt;
    return z(a) + s * ua;
  }
  const QPoint& beside(std::size_t notch, int side) const {
    const VertexId v = notches_[notch];
    return exact_[side == 0 ? p_.next(v) : p_.prev(v)];
  }

  bool is_x4(const std::array<std::size_t, 4>& t, const QPoint& x, const QPoint& y) const {
    const QPoint &a = z(t[0]), &b = z(t[1]), &c = z(t[2]), &d = z(t[3]);
    if (orient(x, a, b) <= 0 || orient(x, b, y) <= 0 || orient(x, y, a) <= 0) return false;
    if (orient(y, c, d) <= 0 || orient(y, d, x) <= 0 || orient(y, x, c) <= 0) return false;
    for (std::size_t k : {t[0], t[1]})
      if (!free_from(notches_[k], ExactSegment(z(k), x))) return false;
    for (std::size_t k : {t[2], t[3]})
      if (!free_from(notches_[k], ExactSegment(z(k), y))) return false;
    if (!free_from(p_.size(), ExactSegment(x, y))) return false;
    for (const QPoint* u : {&a, &b})
      for (const QPoint* w : {&c, &d})
        if (CGAL::do_intersect(ExactSegment(*u, x), ExactSegment(*w, y))) return false;
    return true;
  }

  // Whether the segment meets P's boundary nowhere but at vertex `from` (p_.size(): nowhere).
  bool free_from(std::size_t from, const ExactSegment& s) const {
    for (std::size_t e = 0; e < p_.size(); ++e) {
      const ExactSegment edge(exact_[e], exact_[p_.next(e)]);
      if (!CGAL::do_intersect(s, edge)) continue;
      if (e != from && p_.next(e) != from) return false;
      const auto common = CGAL::intersection(s, edge);
      const QPoint* point = boost::get<QPoint>(&*common);
      if (point == nullptr || *point != exact_[from]) return false;
    }
    return true;
  }

  const Polygon& p_;
  std::vector<VertexId> notches_;
  std::vector<QPoint> exact_;
};

// Every X4-pattern that chazelle-dobkin-n5's test accepts with all angles at its Steiner points below
// 180 degrees has a loose X4-pattern on the same four notches and pairing: Theorem 18 (assumed by
// chazelle-dobkin's scan) on these samples, four notches at a time. n5's test also accepts an angle of
// exactly 180 degrees at a Steiner point (its cones are closed), which Lemma 9 excludes; those are
// counted apart.
TEST(ChazelleDobkinTables, EveryTipX4HasALooseX4OnTheSameNotches) {
  std::vector<std::pair<Polygon, std::string>> polygons;
  for (const Sample& s : small_samples()) polygons.emplace_back(make(s), label(s));
  for (std::uint64_t seed = 1; seed <= 60; ++seed)
    for (std::size_t n : {28, 38}) polygons.emplace_back(make({"random", n, 8, seed}), label({"random", n, 8, seed}));
  for (std::uint64_t seed = 1; seed <= 10; ++seed)
    for (bool spike : {false, true})
      polygons.emplace_back(jittered_quads(2, seed, spike), "jittered quads seed=" + std::to_string(seed));
  std::int64_t checked = 0, straight = 0;
  for (const auto& [p, where] : polygons) {
    cd::Patterns patterns(p);
    const LooseX4 loose(p, patterns.notches());
    const std::size_t r = patterns.notches().size();
    for (std::size_t a = 0; a < r; ++a)
      for (std::size_t b = a + 1; b < r; ++b)
        for (std::size_t c = b + 1; c < r; ++c)
          for (std::size_t d = c + 1; d < r; ++d)
            for (const std::array<std::size_t, 4>& t : {std::array<std::size_t, 4>{a, b, c, d}, std::array<std::size_t, 4>{b, c, d, a}}) {
              const auto tips = patterns.x4(t[0], t[1], t[2], t[3]);
              if (!tips) continue;
              const QPoint &x = tips->first, &y = tips->second;
              if (orient(x, loose.z(t[1]), y) == 0 || orient(x, y, loose.z(t[0])) == 0 ||
                  orient(y, loose.z(t[3]), x) == 0 || orient(y, x, loose.z(t[2])) == 0) {
                ++straight;
                continue;
              }
              ++checked;
              EXPECT_TRUE(loose.exists(t)) << where << " notches " << t[0] << ", " << t[1] << ", " << t[2] << ", " << t[3];
            }
  }
  EXPECT_GT(checked, 500);
}

// ---- the rows E and W themselves, entry by entry, against Lemma 9 by brute force ----

// T(g, h; m) as docs/algorithms/chazelle-dobkin.md defines it. S is taken from the program
// rather than recomputed: its counts are checked against chazelle-dobkin-n5's by the tests above, and the
// rows are checked here given S.
bool tight(const cd::ProgramCubic& program, int g, int h, int m) {
  return program.S(g + 1, m - 1) + program.S(m + 1, h - 1) == program.S(g + 1, h - 1);
}

std::array<std::size_t, 4> quad(int q, int g, int m, int h) {
  return {static_cast<std::size_t>(q), static_cast<std::size_t>(g), static_cast<std::size_t>(m), static_cast<std::size_t>(h)};
}

// What the row of (g, h) must hold at outer notch q, decided apart from the scan: some tight inner notch m
// in (g, h) with a loose X4-pattern on (q, g, m, h), X on a ray of g and Y on a ray of h, in any of the 16
// configurations (LooseX4, Lemma 9). Rows exist for h - g >= 2 only, entries for q outside [g, h] only.
bool row_should_hold(const cd::ProgramCubic& program, const LooseX4& loose, int g, int h, int q) {
  if (h - g < 2 || (q >= g && q <= h)) return false;
  for (int m = g + 1; m < h; ++m)
    if (tight(program, g, h, m) && loose.exists(quad(q, g, m, h))) return true;
  return false;
}

struct RowWitnesses {
  std::int64_t in_e = 0, in_w = 0;
};

// Runs chazelle-dobkin's program on p and checks every entry of every row, every interval and outer notch:
// a witness iff the brute force finds one, and each witness's inner notch and rays a tight loose X4.
RowWitnesses check_rows(const Polygon& p, const std::string& where) {
  cd::ProgramCubic program(p);
  Counters counters;
  program.run(counters);
  cd::Patterns patterns(p);
  const LooseX4 loose(p, patterns.notches());
  const int r = static_cast<int>(patterns.notches().size());
  RowWitnesses seen;
  for (int g = 0; g < r; ++g)
    for (int h = g + 1; h < r; ++h)
      for (int q = 0; q < r; ++q) {
        const cd::Witness w = program.entry(g, h, q);
        const auto at = [&] { return where + " row (" + std::to_string(g) + ", " + std::to_string(h) + ") at " + std::to_string(q); };
        EXPECT_EQ(w.inner >= 0, row_should_hold(program, loose, g, h, q)) << at();
        if (w.inner < 0) continue;
        (q < g ? seen.in_e : seen.in_w) += 1;
        const bool tight_inner = g < w.inner && w.inner < h && tight(program, g, h, w.inner);
        EXPECT_TRUE(tight_inner) << at() << " inner " << w.inner;
        if (tight_inner) {
          EXPECT_TRUE(loose.holds(quad(q, g, w.inner, h), w.sides)) << at() << " inner " << w.inner << " sides " << int{w.sides};
        }
      }
  return seen;
}

// A box with four slits whose reflex tips g = (-4, -4), m = (6, -4), h = (16, 3), q = (-4, 4) (notches
// 0, 1, 2, 3) admit loose X4-patterns in W's pairing of the interval (0, 2) only with z_g X and z_m Y on
// the extensions of g's edge from (-10, -10) and of m's from (0, -10), which are parallel (direction
// (1, 1)); e.g. X = (0, 0) joining q and g, Y = (10, 0) joining m and h. So only the scan's pass for
// inner rays parallel to G finds them (P2 is a constant there). The other rays fail: the extension of
// g's other edge points up and left, away from both rays of q; Y on the extension of m's other edge
// (from (24, -10)) leaves an angle above 180 degrees at Y. Dropping that pass makes the row (0, 2) miss
// its entry at q = 3 (checked).
Polygon parallel_slits() {
  return Polygon::make(std::vector<Point>{{-20, -10}, {-10, -10}, {-4, -4}, {-2, -10}, {0, -10}, {6, -4}, {24, -10}, {30, -10},
                                          {30, 10}, {16, 3}, {30, 12}, {30, 14}, {-10, 14}, {-4, 4}, {-14, 14}, {-20, 14}});
}

// Every entry of E and W on small polygons of every family (each also rotated by a third of its
// vertices), every rotation of x4-quads (both pairings), jittered x4-quads with crossing rays and
// spikes, and every rotation of parallel_slits(): a scan that dropped a loose X4 where a Y-pattern or a
// split reaches the same S would keep the piece counts the tests above compare, and fail here. No
// generated polygon needs the scan's pass for M parallel to G (none of 4,800 jittered quads, m = 1 to
// 3, seeds 1 to 400, did); parallel_slits() does.
TEST(ChazelleDobkinTables, RowsHoldExactlyTheLooseX4OfTightInnerNotches) {
  std::vector<std::pair<Polygon, std::string>> polygons;
  for (const Family& f : families())
    for (std::size_t r : {4, 6, 8, 10})
      for (std::size_t n : {r + 4, 2 * r + 4}) {
        if (f.infeasible(n, r)) continue;
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
          const Polygon p = make({f.name, n, r, seed});
          for (std::size_t by : {std::size_t{0}, p.size() / 3})
            polygons.emplace_back(rotated(p, by), label({f.name, n, r, seed}) + " rotated " + std::to_string(by));
        }
      }
  for (int m : {1, 2}) {
    const Polygon p = Polygon::make(generate("x4-quads", 12 * m + 4, 4 * m, 1));
    for (std::size_t by = 0; by < p.size(); ++by)
      polygons.emplace_back(rotated(p, by), "x4-quads m=" + std::to_string(m) + " rotated " + std::to_string(by));
  }
  const Polygon parallel = parallel_slits();
  for (std::size_t by = 0; by < parallel.size(); ++by)
    polygons.emplace_back(rotated(parallel, by), "parallel slits rotated " + std::to_string(by));
  for (int m : {1, 2})
    for (std::uint64_t seed = 1; seed <= 15; ++seed)
      for (bool spike : {false, true})
        for (std::size_t by : {std::size_t{0}, std::size_t{4}})
          polygons.emplace_back(rotated(jittered_quads(m, seed, spike), by),
                                "jittered quads m=" + std::to_string(m) + " seed=" + std::to_string(seed) +
                                    " spike=" + std::to_string(spike) + " rotated " + std::to_string(by));
  RowWitnesses seen;
  for (const auto& [p, where] : polygons) {
    const RowWitnesses in_p = check_rows(p, where);
    seen.in_e += in_p.in_e;
    seen.in_w += in_p.in_w;
  }
  EXPECT_GT(seen.in_e, 300);
  EXPECT_GT(seen.in_w, 200);
}

// The scans read each query's witness from the places its X sees, found with geodesics
// (docs/algorithms/chazelle-dobkin.md, (7)). It must be the Y where a walk testing every Y in turn with
// the segment search stops: every entry of every row, inner notch and rays, the same in both on polygons
// of every family large enough for long passes (and each rotated by a third).
TEST(ChazelleDobkinTables, GeodesicsFindTheWitnessesOfWalksAlone) {
  std::vector<std::pair<Polygon, std::string>> polygons;
  for (const Family& f : families())
    for (std::size_t r : {12, 24, 40})
      for (std::size_t n : {r + 4, 3 * r}) {
        if (f.infeasible(n, r)) continue;
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
          const Polygon base = make({f.name, n, r, seed});
          for (std::size_t by : {std::size_t{0}, base.size() / 3})
            polygons.emplace_back(rotated(base, by), label({f.name, n, r, seed}) + " rotated " + std::to_string(by));
        }
      }
  // Where an earlier walk of rays apart, whose seen Y moved back, stopped one Y too early and lost a
  // witness (row (3, 13) at outer notch 2; found by a stress run over 125,815 polygons).
  polygons.emplace_back(rotated(make({"random", 22, 16, 2}), 12), "random n=22 r=16 seed=2 rotated 12");
  // Long passes of rays apart, where what X sees starts past the first steps.
  const Polygon notch_heavy = Polygon::make(generate("notch-heavy", 80, std::nullopt, 1));
  for (std::size_t by : {0, 27}) polygons.emplace_back(rotated(notch_heavy, by), "notch-heavy n=80 rotated " + std::to_string(by));
  // Polygons whose scans of rays apart share ends most often among some 850 small ones generated
  // (a ray stopping at another's notch, or two at one point): a geodesic that is a single point.
  for (const Sample& s : {Sample{"random", 40, 20, 12}, Sample{"notch-heavy", 28, 24, 3}, Sample{"random", 24, 12, 8}}) {
    const Polygon base = make(s);
    for (std::size_t by : {std::size_t{0}, base.size() / 2}) polygons.emplace_back(rotated(base, by), label(s) + " rotated " + std::to_string(by));
  }
  std::int64_t witnesses = 0, shared_ends = 0;
  for (const auto& [p, where] : polygons) {
    cd::ProgramCubic seen(p), alone(p, cd::ProgramCubic::P4Test::kSegmentSearch);
    Counters seen_counters, alone_counters;
    seen.run(seen_counters);
    alone.run(alone_counters);
    seen.report(seen_counters);
    const int notches = static_cast<int>(p.reflex_count());
    for (int g = 0; g < notches; ++g)
      for (int h = g + 2; h < notches; ++h)
        for (int q = 0; q < notches; ++q) {
          const cd::Witness a = seen.entry(g, h, q), b = alone.entry(g, h, q);
          EXPECT_TRUE(a.inner == b.inner && a.sides == b.sides)
              << where << " row (" << g << ", " << h << ") at " << q << ": " << a.inner << "/" << int{a.sides}
              << " against " << b.inner << "/" << int{b.sides};
          witnesses += a.inner >= 0;
        }
    shared_ends += seen_counters["x4_scans_sharing_an_end"];
  }
  EXPECT_GT(witnesses, 5000);
  // Scans of rays apart that share an end (a ray stopping at the other's notch, or both at one point).
  EXPECT_GT(shared_ends, 15);
}

// The list steps of the scans, their P4 decisions and funnels, and STEP 3's lookups grow as r^3 at most:
// the counters that the header's time bound rests on, checked against it with the constants of a loose
// count (about r^2/2 intervals, 4 runs of a few list positions per ray each).
TEST(ChazelleDobkinTables, ScanAndLookupsStayCubic) {
  std::vector<Sample> samples = small_samples();
  samples.push_back({"random", 60, 20, 1});
  std::int64_t tested = 0;
  for (const Sample& s : samples) {
    const Polygon p = make(s);
    const std::int64_t r = static_cast<std::int64_t>(p.reflex_count());
    Counters counters;
    find_algorithm("chazelle-dobkin")->run(p, counters);
    EXPECT_LE(counters["x4_scan_steps"] - counters["x4_p4_tests"], 16 * r * r * r) << label(s);
    EXPECT_LE(counters["x4_lookup_steps"], r * r * r / 3) << label(s);
    // What X sees: O(1) amortized per query and insert, O(r) per scan for the funnels (docs/algorithms/chazelle-dobkin.md, (7)).
    EXPECT_LE(counters["x4_p4_tests"], r * r * r) << label(s);
    EXPECT_LE(counters["x4_funnel_steps"], r * r * r) << label(s);
    EXPECT_LE(counters["x4_funnel_points"], r * r * r) << label(s);
    tested += counters["x4_p4_tests"];
  }
  EXPECT_GT(tested, 0);
}

}  // namespace
}  // namespace pd
