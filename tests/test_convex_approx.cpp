// The approximate convex decompositions: naive and naive-chains (thesis 000, Sec. 2.2), hertel-mehlhorn
// and greene-sweep. Hand-made polygons for the degenerate shots (an extension through a vertex, along an
// edge, through collinear vertices, through an earlier Steiner point, onto an unresolved notch), then
// every generator family: exact validity, exactly r + 1 pieces with degree <= 3 for the naive pair,
// Theorem 3's pseudo-notch bound, the Hertel-Mehlhorn bound 2r + 1.
#include "core/registry.h"
#include "core/validate.h"
#include "engines/naive/naive.h"
#include "generators/family.h"
#include "generators/rng.h"
#include "tests/fixtures.h"
#include "tests/same_decomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pd {
namespace {

std::vector<Point> ring(std::initializer_list<std::pair<double, double>> xy) {
  std::vector<Point> pts;
  for (const auto& [x, y] : xy) pts.emplace_back(x, y);
  return pts;
}

// An L: the notch (2,2)'s extension meets the left edge inside it.
std::vector<Point> ell() { return ring({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}); }

// The notch (5,5)'s extension runs exactly into the convex vertex (0,0).
std::vector<Point> into_vertex() { return ring({{0, 0}, {10, 0}, {10, 10}, {5, 5}, {0, 10}}); }

// Two dents in the top: the extension of the notch (6,2) runs through the notch (4,2) and along the
// edge (4,2)-(2,2) before it crosses the left edge.
std::vector<Point> along_edge() {
  return ring({{0, 0}, {10, 0}, {10, 4}, {8, 4}, {8, 2}, {6, 2}, {6, 4}, {4, 4}, {4, 2}, {2, 2}, {2, 4}, {0, 4}});
}

// The L with a collinear vertex (0,2) exactly where the notch's extension meets the left edge.
std::vector<Point> onto_collinear_vertex() { return ring({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}, {0, 2}}); }

// Collinear vertices on the extension's way and at its end, and a collinear vertex next to the notch.
std::vector<Point> collinear_run() {
  return ring({{0, 0}, {3, 0}, {6, 0}, {6, 3}, {4, 3}, {3, 3}, {3, 6}, {0, 6}, {0, 3}, {0, 1}});
}

// Dents facing each other: the extension of the notch (2,1) runs into the unresolved notch (2,3).
std::vector<Point> facing_notches() {
  return ring({{0, 0}, {2, 0}, {2, 1}, {4, 1}, {4, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 3}, {2, 3}, {2, 4}, {0, 4}});
}

// The extension of the notch (1,3) runs into the Steiner point (0,2) that the notch (2,2) made.
std::vector<Point> into_steiner_point() {
  return ring({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {1, 3}, {1, 5}, {0, 5}});
}

struct Named {
  std::string name;
  std::vector<Point> ring;
  bool repairs;  // whether a shot must be turned off its extension in index order
};

std::vector<Named> hand_made() {
  return {{"ell", ell(), false},
          {"into_vertex", into_vertex(), true},
          {"along_edge", along_edge(), true},
          {"onto_collinear_vertex", onto_collinear_vertex(), true},
          {"collinear_run", collinear_run(), true},
          {"facing_notches", facing_notches(), true},
          {"into_steiner_point", into_steiner_point(), true}};
}

// Each cycle from its smallest id, so that two piece lists compare as sets.
std::multiset<Piece> canonical(std::vector<Piece> pieces) {
  std::multiset<Piece> out;
  for (Piece& piece : pieces) {
    std::rotate(piece.begin(), std::min_element(piece.begin(), piece.end()), piece.end());
    out.insert(piece);
  }
  return out;
}

// The naive decomposition's promises: valid, r + 1 pieces, degrees 2 and 3 only, and Theorem 2's
// pieces equal to the shared routine's.
void expect_naive_promises(const Polygon& p, const Decomposition& d, const std::string& label) {
  const Validation v = validate(p, d, Kind::Convex, true);
  ASSERT_TRUE(v.ok) << label << ": " << v.reason;
  const std::vector<Piece> pieces = pieces_of(p, d);
  EXPECT_EQ(pieces.size(), p.reflex_count() + 1) << label;
  EXPECT_EQ(d.steiner.size(), p.reflex_count()) << label;
  NaiveGraph g;
  ASSERT_NO_THROW(g = naive_graph(p, d)) << label;
  for (std::size_t u = 0; u < g.degree.size(); ++u) EXPECT_GE(g.degree[u], 2) << label << " vertex " << u;
  EXPECT_EQ(canonical(naive_pieces(p, d, g)), canonical(pieces)) << label;
}

// Theorem 3, for the algorithm that counts pseudo-notches.
void expect_pseudo_notch_bound(const Polygon& p, Counters& counters, const std::string& label) {
  if (counters.count("pseudo_notches") == 0) return;
  EXPECT_LE(counters["pseudo_notches"], 2 * (1 + static_cast<std::int64_t>(p.reflex_count()))) << label;
}

const Algorithm& algorithm(const std::string& name) {
  const Algorithm* a = find_algorithm(name);
  if (!a) throw std::invalid_argument("not registered: " + name);
  return *a;
}

// The earcut fixtures' outer rings that are simple polygons.
std::vector<std::pair<std::string, Polygon>> earcut_polygons() {
  std::vector<std::pair<std::string, Polygon>> polygons;
  for (const auto& [name, ring] : fixtures::earcut_outer_rings()) {
    try {
      polygons.emplace_back(name, Polygon::make(ring));
    } catch (const PolygonError&) {
    }
  }
  return polygons;
}

class NaivePair : public ::testing::TestWithParam<std::string> {};

TEST_P(NaivePair, HandMadeDegenerateShotsOnEveryRotation) {
  const Algorithm& a = algorithm(GetParam());
  for (const Named& h : hand_made()) {
    std::vector<Point> pts = h.ring;
    for (std::size_t k = 0; k < pts.size(); ++k, std::rotate(pts.begin(), pts.begin() + 1, pts.end())) {
      const Polygon p = Polygon::make(pts);
      Counters counters;
      const Decomposition d = a.run(p, counters);
      const std::string label = h.name + " rotation " + std::to_string(k);
      expect_naive_promises(p, d, label);
      expect_pseudo_notch_bound(p, counters, label);
      if (k == 0) {
        EXPECT_EQ(counters["repairs"] > 0, h.repairs) << label;
      }
    }
  }
}

TEST_P(NaivePair, MirroredHandMadePolygons) {
  const Algorithm& a = algorithm(GetParam());
  for (const Named& h : hand_made()) {
    std::vector<Point> mirrored;
    for (const Point& q : h.ring) mirrored.emplace_back(-q.x(), q.y());
    const Polygon p = Polygon::make(mirrored);
    Counters counters;
    expect_naive_promises(p, a.run(p, counters), h.name + " mirrored");
  }
}

TEST_P(NaivePair, EveryFamily) {
  const Algorithm& a = algorithm(GetParam());
  for (const Family& f : families())
    for (std::size_t n : {8, 13, 24, 60, 250})
      for (std::uint64_t seed : {1, 2, 3, 4}) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        const Polygon p = Polygon::make(generate(f.name, n, r, seed));
        Counters counters;
        const std::string label = f.name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
        expect_naive_promises(p, a.run(p, counters), label);
        expect_pseudo_notch_bound(p, counters, label);
      }
}

TEST_P(NaivePair, EarcutFixtures) {
  const Algorithm& a = algorithm(GetParam());
  for (const auto& [name, p] : earcut_polygons()) {
    Counters counters;
    expect_naive_promises(p, a.run(p, counters), "earcut " + name);
    expect_pseudo_notch_bound(p, counters, "earcut " + name);
  }
}

INSTANTIATE_TEST_SUITE_P(Approx, NaivePair, ::testing::Values("naive", "naive-chains"),
                         [](const auto& info) { return info.param == "naive" ? std::string("naive") : std::string("naive_chains"); });

// The same shots in the same order: naive-chains finds exactly naive's decomposition, and its chains
// keep Theorem 3's bound.
TEST(NaiveChains, EqualsNaiveAndKeepsThePseudoNotchBound) {
  std::size_t cases = 0;
  for (const Family& f : families())
    for (std::size_t n : {8, 13, 24, 60, 250, 1000})
      for (std::uint64_t seed : {1, 2, 3}) {
        for (std::size_t r : {f.default_reflex(n), std::size_t{1}, n / 3}) {
          if (f.infeasible(n, r)) continue;
          const Polygon p = Polygon::make(generate(f.name, n, r, seed));
          const std::string label = f.name + " n=" + std::to_string(n) + " r=" + std::to_string(r) + " seed=" + std::to_string(seed);
          Counters plain, chained;
          const Decomposition a = naive_decomposition(p, plain);
          const Decomposition b = algorithm("naive-chains").run(p, chained);
          EXPECT_TRUE(same_decomposition(a, b)) << label;
          const std::int64_t bound = 2 * (1 + static_cast<std::int64_t>(p.reflex_count()));
          EXPECT_LE(chained["pseudo_notches"], bound) << label;
          EXPECT_GE(chained["pseudo_notches"], static_cast<std::int64_t>(p.reflex_count())) << label;
          ++cases;
        }
      }
  EXPECT_GT(cases, 100u);
}

// Every family's polygon with up to three small triangular holes dropped at random into its box, the
// ones that land inside and apart kept: outer rings with notches and holes together.
std::vector<Polygon> family_polygons_with_holes() {
  std::vector<Polygon> out;
  Rng rng(33);
  for (const Family& f : families())
    for (std::size_t n : {24, 60}) {
      const std::size_t r = f.default_reflex(n);
      if (f.infeasible(n, r)) continue;
      const Ring outer = generate(f.name, n, r, 7);
      CGAL::Bbox_2 box;
      for (const Point& q : outer) box += q.bbox();
      const double w = box.xmax() - box.xmin(), hgt = box.ymax() - box.ymin(), size = std::min(w, hgt) / 40;
      Rings rings = {outer};
      for (int trial = 0; trial < 200 && rings.size() < 4; ++trial) {
        const double x = box.xmin() + w * static_cast<double>(rng.below(1000)) / 1000;
        const double y = box.ymin() + hgt * static_cast<double>(rng.below(1000)) / 1000;
        Rings with = rings;
        with.push_back({{x, y}, {x + size, y + size / 2}, {x + size / 3, y + size}});
        try {
          Polygon::make_with_holes(with);
          rings = with;
        } catch (const PolygonError&) {
        }
      }
      if (rings.size() > 1) out.push_back(Polygon::make_with_holes(rings));
    }
  for (const HoleFamily& f : hole_families())
    for (std::size_t n : {24, 60, 250}) out.push_back(Polygon::make_with_holes(generate_with_holes(f.name, n, {}, {}, 1)));
  return out;
}

// With holes too: the same decomposition as naive's, exactly r + 1 - h pieces, Theorem 3's bound
// ring by ring.
TEST(NaiveChains, EqualsNaiveWithHoles) {
  const std::vector<Polygon> polygons = family_polygons_with_holes();
  EXPECT_GT(polygons.size(), 15u);
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const Polygon& p = polygons[k];
    Counters plain, chained;
    const Decomposition a = naive_decomposition(p, plain);
    const Decomposition b = algorithm("naive-chains").run(p, chained);
    EXPECT_TRUE(same_decomposition(a, b)) << "polygon " << k;
    EXPECT_TRUE(validate(p, b, Kind::Convex, true).ok) << "polygon " << k;
    EXPECT_EQ(pieces_of(p, b).size() + p.hole_count(), p.reflex_count() + 1) << "polygon " << k;
    EXPECT_LE(chained["pseudo_notches"], 2 * (1 + static_cast<std::int64_t>(p.reflex_count()))) << "polygon " << k;
  }
}

// Chazelle-Dobkin's STEP 5: completing a decomposition that already has cuts and Steiner points (here
// the naive segments of every other notch) through the chains gives naive_complete's segments.
TEST(NaiveChains, CompletesAGivenDecompositionAsNaiveDoes) {
  std::size_t cases = 0;
  for (const Family& f : families())
    for (std::size_t n : {13, 60, 250})
      for (std::uint64_t seed : {1, 2}) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        const Polygon p = Polygon::make(generate(f.name, n, r, seed));
        const std::vector<VertexId> notches = naive::notches_of(p);
        std::vector<VertexId> first, rest;
        for (std::size_t k = 0; k < notches.size(); ++k) (k % 2 ? rest : first).push_back(notches[k]);
        Counters counters;
        const Decomposition given = naive_complete(p, Decomposition{}, first, counters);
        const Decomposition a = naive_complete(p, given, rest, counters);
        const Decomposition b = naive_complete_chains(p, given, rest, counters);
        EXPECT_TRUE(same_decomposition(a, b)) << f.name << " n=" << n << " seed=" << seed;
        cases += !rest.empty();
      }
  EXPECT_GT(cases, 40u);
}

// Figure 2.6 by hand: a 12-gon with one vertex pushed in, a notch at (500,0). From the notch the
// boundary stays left of the notch's outgoing edge through (-500,-866), so the first chain has 8 edges
// (the next vertex, (0,-1000), would make the chain's angle at the notch reflex); the second chain
// closes back to the notch. 2 pseudo-notches, within 2(1 + 1).
TEST(NaiveChains, CountsPseudoNotches) {
  const Polygon p = Polygon::make(ring({{500, 0}, {866, 500}, {500, 866}, {0, 1000}, {-500, 866}, {-866, 500},
                                        {-1000, 0}, {-866, -500}, {-500, -866}, {0, -1000}, {500, -866}, {866, -500}}));
  ASSERT_EQ(p.reflex_count(), 1u);
  Counters counters;
  expect_naive_promises(p, algorithm("naive-chains").run(p, counters), "12-gon");
  EXPECT_EQ(counters["pseudo_notches"], 2);
}

// Exact positions of the hand-made cases, worked by hand.
TEST(Naive, ExtensionEndsInsideTheEdgeItMeets) {
  const Polygon p = Polygon::make(ell());
  Counters counters;
  const Decomposition d = naive_decomposition(p, counters);
  ASSERT_EQ(d.steiner.size(), 1u);
  EXPECT_EQ(d.steiner[0].point, QPoint(0, 2));
  EXPECT_EQ(d.steiner[0].boundary_edge, 5);
  EXPECT_EQ(counters["repairs"], 0);
}

TEST(Naive, ExtensionIntoAVertexIsTurnedIntoTheRange) {
  // From (5,5) the range is between south-west (the extension) and south-east; the ray turns towards
  // south-east, meets edge (0,0)-(10,0) next to (0,0); the range's other side meets that edge at
  // t = (10,0), nothing is in triangle (v, (0,0), t), so the segment turns by atan(1) = 45 degrees,
  // short of t, and ends at (5,0).
  const Polygon p = Polygon::make(into_vertex());
  Counters counters;
  const Decomposition d = naive_decomposition(p, counters);
  ASSERT_EQ(d.steiner.size(), 1u);
  EXPECT_EQ(d.steiner[0].point, QPoint(5, 0));
  EXPECT_EQ(d.steiner[0].boundary_edge, 0);
  EXPECT_EQ(counters["repairs"], 1);
}

TEST(Naive, ExtensionIntoASteinerPointEndsOnTheEarlierSegment) {
  // Notch (2,2) ends at (0,2); the extension of notch (1,3) runs into it and turns onto the segment
  // (2,2)-(0,2), bounded by the range's side x = 1: a turn by atan(1) would reach that side, by
  // atan(1/2) (direction (-1,-3)) it does not, so it ends at (2/3, 2), splitting that segment.
  const Polygon p = Polygon::make(into_steiner_point());
  Counters counters;
  const Decomposition d = naive_decomposition(p, counters);
  ASSERT_EQ(d.steiner.size(), 2u);
  EXPECT_EQ(d.steiner[1].point, QPoint(Rational(2, 3), 2));
  EXPECT_EQ(d.steiner[1].boundary_edge, kInterior);
  EXPECT_EQ(d.cuts.size(), 3u);
}

TEST(Naive, ExtensionOntoAnUnresolvedNotchPassesIt) {
  // The extension of (2,1) north runs into the notch (2,3), whose edge (2,3)-(2,4) continues it: the
  // perturbed ray passes both, first crosses edge (2,4)-(0,4) at (2,4); the turn is bounded by (0,4),
  // which atan(1) would overshoot, so it turns by atan(1/2) (direction (-1,2)) and ends at (1/2,4).
  const Polygon p = Polygon::make(facing_notches());
  Counters counters;
  const Decomposition d = naive_decomposition(p, counters);
  ASSERT_EQ(d.steiner.size(), 4u);
  EXPECT_EQ(d.steiner[0].point, QPoint(Rational(1, 2), 4));
  EXPECT_EQ(d.steiner[0].boundary_edge, 10);
}

std::size_t bit_length(const Rational& v) {
  return std::max(mpz_sizeinbase(v.get_num_mpz_t(), 2), mpz_sizeinbase(v.get_den_mpz_t(), 2));
}

// On a comb every other notch's extension runs along the gap bottoms and is turned; each turned
// segment ends on the left edge just above the one before it, a chain of r / 2 repairs. Its Steiner
// points keep a bounded bit length all the same (each segment lies on a line through its notch given
// by input points and a dyadic turn): ending halfway between the bounds, as an earlier version did,
// added a bit per repair, over 250 bits at n = 1000.
TEST(Naive, SteinerPointsStaySmallAlongAChainOfRepairs) {
  const Polygon p = Polygon::make(generate("comb", 1000, std::nullopt, 1));
  Counters counters;
  const Decomposition d = naive_decomposition(p, counters);
  expect_naive_promises(p, d, "comb n=1000");
  EXPECT_GE(counters["repairs"], 200);
  std::size_t longest = 0;
  for (const SteinerPoint& s : d.steiner) longest = std::max({longest, bit_length(s.point.x()), bit_length(s.point.y())});
  EXPECT_LE(longest, 64u);
}

// The graph representation holds degrees 2 and 3 only: a decomposition with a busier vertex is not a
// naive one and is refused.
TEST(Naive, GraphRepresentationRefusesDegreeAboveThree) {
  const Polygon p = Polygon::make(ring({{0, 0}, {4, 0}, {6, 2}, {4, 4}, {0, 4}, {-2, 2}}));
  Decomposition fan;
  fan.add_cut(0, 3);
  EXPECT_NO_THROW(naive_graph(p, fan));
  fan.add_cut(0, 2);
  EXPECT_THROW(naive_graph(p, fan), std::invalid_argument);
}

// Chazelle-Dobkin's last step: a decomposition that already resolves two notches with one cut is
// finished by the naive method, one piece for each remaining notch; the notch (4,3)'s extension runs
// into the notch (4,1), which by then has its segment.
TEST(Naive, CompletesAPartialDecomposition) {
  const Polygon p = Polygon::make(facing_notches());
  Decomposition partial;
  partial.add_cut(2, 9);
  Counters counters;
  const Decomposition d = naive_complete(p, partial, {3, 8}, counters);
  const Validation v = validate(p, d, Kind::Convex, true);
  ASSERT_TRUE(v.ok) << v.reason;
  EXPECT_EQ(pieces_of(p, d).size(), 4u);
  EXPECT_EQ(counters["repairs"], 1);
}

// Hertel-Mehlhorn and the sweep built on it: valid, every diagonal essential (removing any one leaves
// a piece that is not convex), hence at most 2r + 1 pieces, and at most 4 OPT (OPT from keil-snoeyink,
// whose agreement with a brute force is tested in test_optimal.cpp) where OPT is cheap to compute.
class DiagonalRemoval : public ::testing::TestWithParam<std::string> {};

void expect_all_essential(const Algorithm& a, const Polygon& p, const std::string& label) {
  Counters counters;
  const Decomposition d = a.run(p, counters);
  const Validation v = validate(p, d, Kind::Convex, false);
  ASSERT_TRUE(v.ok) << label << ": " << v.reason;
  EXPECT_LE(d.cuts.size(), 2 * p.reflex_count()) << label;
  if (p.size() <= 250) {
    Counters unused;
    const std::size_t optimum = algorithm("keil-snoeyink").run(p, unused).cuts.size() + 1;
    EXPECT_LE(d.cuts.size() + 1, 4 * optimum) << label;
  }
  EXPECT_EQ(counters["diagonals_removed"] + static_cast<std::int64_t>(d.cuts.size()), counters["diagonals"]) << label;
  for (std::size_t k = 0; k < d.cuts.size() && p.size() <= 250; ++k) {
    Decomposition fewer = d;
    fewer.cuts.erase(fewer.cuts.begin() + static_cast<std::ptrdiff_t>(k));
    EXPECT_FALSE(validate(p, fewer, Kind::Convex, false).ok) << label << ": diagonal " << k << " is not essential";
  }
}

TEST_P(DiagonalRemoval, EveryFamily) {
  const Algorithm& a = algorithm(GetParam());
  for (const Family& f : families())
    for (std::size_t n : {8, 13, 24, 60, 250, 2000})
      for (std::uint64_t seed : {1, 2, 3}) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        expect_all_essential(a, Polygon::make(generate(f.name, n, r, seed)),
                             f.name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed));
      }
}

TEST_P(DiagonalRemoval, HandMadeAndEarcutFixtures) {
  const Algorithm& a = algorithm(GetParam());
  for (const Named& h : hand_made()) expect_all_essential(a, Polygon::make(h.ring), h.name);
  const auto polygons = earcut_polygons();
  EXPECT_GT(polygons.size(), 30u);
  for (const auto& [name, p] : polygons) expect_all_essential(a, p, "earcut " + name);
}

TEST_P(DiagonalRemoval, ConvexPolygonIsOnePiece) {
  const Polygon p = Polygon::make(ring({{0, 0}, {4, 0}, {6, 2}, {6, 3}, {3, 5}, {0, 3}}));
  Counters counters;
  EXPECT_TRUE(algorithm(GetParam()).run(p, counters).cuts.empty());
}

// The ell's one reflex vertex keeps one or two essential diagonals (2r + 1 pieces at most); which, the
// triangulation decides: a constrained Delaunay triangulation fans out of the reflex vertex, and its
// diagonal that alone would do is removed first.
TEST_P(DiagonalRemoval, EllIsTwoOrThreePieces) {
  const Polygon p = Polygon::make(ell());
  Counters counters;
  const std::size_t cuts = algorithm(GetParam()).run(p, counters).cuts.size();
  EXPECT_GE(cuts, 1u);
  EXPECT_LE(cuts, GetParam() == std::string("hertel-mehlhorn[cgal-cdt]") ? 2u : 1u);
}

INSTANTIATE_TEST_SUITE_P(Approx, DiagonalRemoval,
                         ::testing::Values("hertel-mehlhorn", "greene-sweep", "hertel-mehlhorn-greedy",
                                           "hertel-mehlhorn[ear-n2]", "hertel-mehlhorn[cgal-cdt]",
                                           "hertel-mehlhorn[cutting-tri]"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             if (c == '-' || c == '[' || c == ']') c = '_';
                           return s;
                         });

}  // namespace
}  // namespace pd
