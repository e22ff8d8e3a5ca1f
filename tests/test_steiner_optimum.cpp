// The minimum convex decomposition with Steiner points: the independent checker
// (tests/steiner_optimum_check.h) against known answers and the bounds of Chazelle's thesis, then every
// registered optimal program with Steiner points against the checker.
// SteinerOptimalPrograms.AreRegistered fails if none is (the comparisons would otherwise pass
// vacuously).
#include "core/registry.h"
#include "core/validate.h"
#include "generators/family.h"
#include "tests/lattice_polygons.h"
#include "tests/reliability.h"
#include "tests/steiner_optimum_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace pd {
namespace {

Polygon polygon(std::vector<std::pair<double, double>> xy) {
  std::vector<Point> pts;
  for (auto [x, y] : xy) pts.emplace_back(x, y);
  return Polygon::make(pts);
}

std::vector<Point> rotated(const Polygon& p, std::size_t by) {
  std::vector<Point> ring(p.vertices());
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(by), ring.end());
  return ring;
}

std::size_t lower_bound(const Polygon& p) { return (p.reflex_count() + 1) / 2 + 1; }

// The checker's answer, after checking its witness with the project's validator: valid, convex, with
// as many pieces as the answer.
steiner_check::Result checked(const Polygon& p, const std::string& label) {
  const steiner_check::Result result = steiner_check::check(p);
  const Validation v = validate(p, result.witness, Kind::Convex, /*allow_steiner*/ true);
  EXPECT_TRUE(v.ok) << label << ": " << v.reason;
  if (v.ok) {
    EXPECT_EQ(pieces_of(p, result.witness).size(), result.pieces) << label;
  }
  return result;
}

std::size_t diagonal_optimum(const Polygon& p) {
  Counters counters;
  return find_algorithm("keil-snoeyink")->run(p, counters).cuts.size() + 1;
}

std::string label_of(const std::string& family, std::size_t n, std::size_t r, std::uint64_t seed) {
  return family + " n=" + std::to_string(n) + " r=" + std::to_string(r) + " seed=" + std::to_string(seed);
}

struct Case {
  std::string label;
  Polygon polygon;
};

// Every family at every 1 <= r <= 6 it can make, at its three smallest n for that r (two for r = 6, the
// checker's slowest), seeds 1 and 2.
const std::vector<Case>& small_family_cases() {
  static const std::vector<Case> cases = [] {
    std::vector<Case> out;
    for (const Family& f : families())
      for (std::size_t r = 1; r <= steiner_check::kMaxReflex; ++r)
        for (std::size_t n = 4, made = 0; n <= 40 && made < (r == 6 ? 2 : 3); ++n) {
          if (f.infeasible(n, r)) continue;
          ++made;
          for (std::uint64_t seed : {1, 2})
            out.push_back({label_of(f.name, n, r, seed), Polygon::make(generate(f.name, n, r, seed))});
        }
    return out;
  }();
  return cases;
}

// The checker's count for a small family case, computed (and its witness checked) once for the tests
// of the checker and of the programs.
std::size_t checker_count(const Case& c) {
  static std::map<std::string, std::size_t> counts;
  const auto known = counts.find(c.label);
  if (known != counts.end()) return known->second;
  return counts[c.label] = checked(c.polygon, c.label).pieces;
}

std::vector<Case> hand_made() {
  return {
      {"L", polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})},
      {"plus", polygon({{1, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 2}, {0, 2}, {0, 1}, {1, 1}})},
      {"star", polygon({{0, -4}, {1, -1}, {4, 0}, {1, 1}, {0, 4}, {-1, 1}, {-4, 0}, {-1, -1}})},
      {"zigzag", polygon({{0, 0}, {6, 0}, {6, 2}, {5, 1}, {4, 2}, {3, 1}, {2, 2}, {1, 1}, {0, 2}})},
      {"spiral", polygon({{0, 0}, {6, 0}, {6, 6}, {1, 6}, {1, 2}, {4, 2}, {4, 4}, {3, 4}, {3, 3}, {2, 3}, {2, 5}, {5, 5}, {5, 1}, {0, 1}})},
      {"two notches on one line", polygon({{0, 0}, {8, 0}, {8, 4}, {6, 4}, {5, 2}, {4, 4}, {3, 2}, {2, 4}, {0, 4}})},
      // 5 pieces: the diagonal (7, 4)-(7, 7), and the diagonal (6, 1)-(6, 4) continued straight through the
      // spike's tip (6, 4) to the only Steiner point (6, 7) that also joins (7, 8) and (3, 7): there the
      // extension of that diagonal meets the extensions of an edge of each of the two other notches (an
      // X3 region with no interior, at a joint adapted to the diagonal).
      {"arms of three joints through one point",
       polygon({{6, 4}, {1, 7}, {0, 0}, {6, 1}, {7, 0}, {7, 4}, {8, 1}, {9, 1}, {9, 2}, {7, 7}, {7, 8}, {8, 9}, {0, 8}, {3, 7}, {2, 7}})},
  };
}

TEST(SteinerOptimumCheck, KnownAnswers) {
  EXPECT_EQ(checked(Polygon::make(generate("convex", 9, 0, 1)), "convex").pieces, 1u);
  EXPECT_EQ(checked(Polygon::make(generate("few-notches", 9, 1, 1)), "one notch").pieces, 2u);
  EXPECT_EQ(checked(hand_made()[0].polygon, "L").pieces, 2u);
  // Two horizontal X2-patterns at the star's waist; the two X2-patterns through its centre cross.
  EXPECT_EQ(checked(hand_made()[2].polygon, "star").pieces, 3u);
  EXPECT_EQ(checked(hand_made()[1].polygon, "plus").pieces, 3u);
  EXPECT_EQ(checked(hand_made()[6].polygon, "arms of three joints through one point").pieces, 5u);
}

TEST(SteinerOptimumCheck, SlitTriangleNeedsItsSteinerPoint) {
  const Polygon p = Polygon::make(generate("x-pattern", 12, 3, 1));
  const steiner_check::Result result = checked(p, "x-pattern n=12");
  EXPECT_EQ(result.pieces, 3u);
  EXPECT_TRUE(result.proven_optimal);
  ASSERT_EQ(result.patterns.size(), 1u);
  EXPECT_EQ(result.patterns[0].steiner.size(), 1u);
  EXPECT_EQ(result.witness.steiner.size(), 1u);
  EXPECT_EQ(diagonal_optimum(p), 4u);
}

// Three slits whose ranges share exactly one point, G = (0, 0): each slit has one edge on a line through
// G (x = 0, y = 0, y = x) and its range on the side of that line that leaves only G common to all three.
// G is the one Steiner point of an X3-pattern, a vertex of the checker's arrangement; no diagonal
// resolves two tips. Moving the second slit up by 1 leaves the ranges nothing in common.
Polygon three_slits(double second_tip_y) {
  return polygon({{40, -40}, {40, second_tip_y - 1}, {10, second_tip_y}, {40, second_tip_y}, {40, 40}, {1, 40},
                  {0, 10}, {0, 40}, {-40, 40}, {-40, -39}, {-10, -10}, {-40, -40}});
}

TEST(SteinerOptimumCheck, FindsASteinerPointThatIsASingleVertex) {
  const steiner_check::Result result = checked(three_slits(0), "three slits meeting at one point");
  EXPECT_EQ(result.pieces, 3u);
  ASSERT_EQ(result.patterns.size(), 1u);
  ASSERT_EQ(result.patterns[0].steiner.size(), 1u);
  EXPECT_EQ(result.patterns[0].steiner[0], steiner_check::EPoint(0, 0));
  EXPECT_EQ(checked(three_slits(1), "three slits missing each other").pieces, 4u);
}

Polygon four_slits() { return Polygon::make(generate("x4-quads", 16, 4, 1)); }

TEST(SteinerOptimumCheck, FindsAnX4PatternWithTwoSteinerPoints) {
  const steiner_check::Result result = checked(four_slits(), "four slits");
  EXPECT_EQ(result.pieces, 4u);
  ASSERT_EQ(result.patterns.size(), 1u);
  EXPECT_EQ(result.patterns[0].steiner.size(), 2u);
  EXPECT_EQ(diagonal_optimum(four_slits()), 5u);
}

TEST(SteinerOptimumCheck, SameAnswerOnEveryRotation) {
  std::vector<Case> cases = hand_made();
  cases.push_back({"three slits", three_slits(0)});
  cases.push_back({"four slits", four_slits()});
  cases.push_back({"x-pattern n=13", Polygon::make(generate("x-pattern", 13, 3, 2))});
  for (const Case& c : cases) {
    const std::size_t best = checked(c.polygon, c.label).pieces;
    for (std::size_t k = 1; k < c.polygon.size(); ++k) {
      const std::string label = c.label + " rotated " + std::to_string(k);
      EXPECT_EQ(checked(Polygon::make(rotated(c.polygon, k)), label).pieces, best) << label;
    }
  }
}

TEST(SteinerOptimumCheck, PairsReachHalfTheNotchesPlusOne) {
  for (std::size_t r : {2, 4, 6})
    for (std::size_t n : {3 * r + 4, 3 * r + 5, 3 * r + 9})
      for (std::uint64_t seed : {1, 2, 3}) {
        const std::string label = label_of("x2-pairs", n, r, seed);
        const steiner_check::Result result = checked(Polygon::make(generate("x2-pairs", n, r, seed)), label);
        EXPECT_EQ(result.pieces, r / 2 + 1) << label;
        EXPECT_TRUE(result.proven_optimal) << label;
      }
}

// One group of x4-quads is four_slits() with bulging sides: one X4-pattern, 4 pieces (above Theorem 8's
// bound, so not `proven_optimal`; the family's header proves it); 5 with diagonals.
TEST(SteinerOptimumCheck, QuadsGroupNeedsItsX4Pattern) {
  for (std::size_t n : {17, 21, 28})
    for (std::uint64_t seed : {1, 2}) {
      const std::string label = label_of("x4-quads", n, 4, seed);
      const Polygon p = Polygon::make(generate("x4-quads", n, 4, seed));
      const steiner_check::Result result = checked(p, label);
      EXPECT_EQ(result.pieces, 4u) << label;
      ASSERT_EQ(result.patterns.size(), 1u) << label;
      EXPECT_EQ(result.patterns[0].steiner.size(), 2u) << label;
      EXPECT_EQ(diagonal_optimum(p), 5u) << label;
    }
}

// Theorem 8's bounds, and never above the optimum with diagonals only.
void expect_within_bounds(const Case& c) {
  const std::size_t pieces = checker_count(c);
  const std::size_t r = c.polygon.reflex_count();
  EXPECT_GE(pieces, lower_bound(c.polygon)) << c.label;
  EXPECT_LE(pieces, r + 1) << c.label;
  EXPECT_LE(pieces, diagonal_optimum(c.polygon)) << c.label;
}

TEST(SteinerOptimumCheck, WithinTheBoundsOnEverySmallFamilyPolygon) {
  const std::vector<Case>& cases = small_family_cases();
  EXPECT_GE(cases.size(), 190u);
  for (const Case& c : cases) expect_within_bounds(c);
}

TEST(SteinerOptimumCheck, WithinTheBoundsOnHandMadePolygons) {
  for (const Case& c : hand_made()) expect_within_bounds(c);
}

TEST(SteinerOptimumCheck, RefusesMoreThanSixNotches) {
  EXPECT_THROW(steiner_check::check(Polygon::make(generate("x2-pairs", 28, 8, 1))), std::invalid_argument);
}

// --- The registered optimal programs with Steiner points against the checker ----------------------

std::vector<const Algorithm*> steiner_optimal_programs() {
  std::vector<const Algorithm*> out;
  for (const Algorithm& a : algorithms())
    if (a.steiner && a.optimal) out.push_back(&a);
  return out;
}

// A count below the checker's with a valid result would mean a pattern the checker does not search
// (see its header); a count above it, a program missing the witness's patterns.
void expect_programs_agree(const Polygon& p, std::size_t best, const std::string& label) {
  std::size_t ran = 0;
  for (const Algorithm* a : steiner_optimal_programs()) {
    if (!reliability::takes(*a, p)) continue;
    ++ran;
    Counters counters;
    const Decomposition d = a->run(p, counters);
    const Validation valid = validate(p, d, a->kind, a->steiner);
    EXPECT_TRUE(valid.ok) << a->name << " on " << label << ": " << valid.reason;
    if (valid.ok) {
      EXPECT_EQ(pieces_of(p, d).size(), best) << a->name << " on " << label;
    }
  }
  EXPECT_GT(ran, 0u) << label;
}

// Expected to fail while no optimal program with Steiner points is registered.
TEST(SteinerOptimalPrograms, AreRegistered) {
  EXPECT_FALSE(steiner_optimal_programs().empty())
      << "no registered algorithm has steiner && optimal: the comparisons with the checker test nothing";
}

TEST(SteinerOptimalPrograms, AgreeWithTheCheckerOnEverySmallFamilyPolygon) {
  if (steiner_optimal_programs().empty()) GTEST_SKIP() << "nothing to compare (see AreRegistered)";
  for (const Case& c : small_family_cases()) expect_programs_agree(c.polygon, checker_count(c), c.label);
}

TEST(SteinerOptimalPrograms, AgreeWithTheCheckerOnEveryRotation) {
  if (steiner_optimal_programs().empty()) GTEST_SKIP() << "nothing to compare (see AreRegistered)";
  struct Generated {
    const char* family;
    std::size_t n, r;
  };
  std::vector<Case> cases = hand_made();
  for (const Generated& g : {Generated{"x-pattern", 12, 3}, Generated{"random", 12, 5}, Generated{"spiral", 14, 5},
                             Generated{"notch-heavy", 10, 5}, Generated{"comb", 12, 4}})
    cases.push_back({label_of(g.family, g.n, g.r, 7), Polygon::make(generate(g.family, g.n, g.r, 7))});
  for (const Case& c : cases) {
    const std::size_t best = checked(c.polygon, c.label).pieces;
    for (std::size_t k = 0; k < c.polygon.size(); ++k)
      expect_programs_agree(Polygon::make(rotated(c.polygon, k)), best, c.label + " rotated " + std::to_string(k));
  }
}

// Degenerate lattice polygons with 3 to 6 notches (tests/lattice_polygons.h): Steiner points where arms
// of ranges meet, edges along extensions of P's edges, straight angles at notches, rays stopped at
// vertices. The checker allows all of these (its header).
TEST(SteinerOptimalPrograms, AgreeWithTheCheckerOnDegenerateLatticePolygons) {
  if (steiner_optimal_programs().empty()) GTEST_SKIP() << "nothing to compare (see AreRegistered)";
  std::mt19937 rng(2026);
  int compared = 0;
  for (int round = 0; compared < 150; ++round) {
    const Polygon p = lattice::lattice_polygon(10 + round % 15, 5 + round % 6, rng);
    if (p.reflex_count() < 3 || p.reflex_count() > steiner_check::kMaxReflex) continue;
    const std::string label = "lattice polygon " + std::to_string(round);
    expect_programs_agree(p, checked(p, label).pieces, label);
    ++compared;
  }
}

TEST(SteinerOptimalPrograms, ReachHalfTheNotchesPlusOneOnPairs) {
  if (steiner_optimal_programs().empty()) GTEST_SKIP() << "nothing to compare (see AreRegistered)";
  for (std::size_t r : {2, 8, 20, 40})
    for (std::uint64_t seed : {1, 2}) {
      const std::size_t n = 3 * r + 4 + 3 * seed;
      const Polygon p = Polygon::make(generate("x2-pairs", n, r, seed));
      expect_programs_agree(p, r / 2 + 1, label_of("x2-pairs", n, r, seed));
    }
}

// x4-quads with m groups: 3m + 1 pieces (one X4-pattern per group, the family's header proves it).
TEST(SteinerOptimalPrograms, ReachOneX4PatternPerGroupOnQuads) {
  if (steiner_optimal_programs().empty()) GTEST_SKIP() << "nothing to compare (see AreRegistered)";
  for (std::size_t m : {1, 3, 6})
    for (std::uint64_t seed : {4, 5}) {
      const std::size_t r = 4 * m, n = 3 * r + 4 + 5 * seed;
      const Polygon p = Polygon::make(generate("x4-quads", n, r, seed));
      expect_programs_agree(p, 3 * m + 1, label_of("x4-quads", n, r, seed));
    }
}

}  // namespace
}  // namespace pd
