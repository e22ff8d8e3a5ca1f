// The optimal convex decomposition programs (every registered optimal algorithm without Steiner points
// that is not a peer) against an exhaustive search over sets of non-crossing diagonals on small
// polygons, against each other on larger ones, and against CGAL's optimal partition where CGAL's
// result is valid.
#include "core/registry.h"
#include "core/validate.h"
#include "engines/convex/exact_ink.h"
#include "engines/keil_snoeyink/reduction.h"
#include "generators/family.h"
#include "tests/brute_force.h"
#include "tests/lattice_polygons.h"
#include "tests/reliability.h"

#include <CGAL/CORE_Expr.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace pd {
namespace {

using lattice::lattice_polygon;
using lattice::notched_rectangle;

std::vector<const Algorithm*> registered_optimal_programs() {
  std::vector<const Algorithm*> out;
  for (const Algorithm& a : algorithms())
    if (a.optimal && !a.steiner && a.kind == Kind::Convex && !is_peer(a)) out.push_back(&a);
  return out;
}

// The registered programs, plus keil-snoeyink-reduced's reduction forced on (the registered program
// skips it where shooting cannot pay, which is every polygon small enough for the brute force).
std::vector<Algorithm> optimal_programs() {
  std::vector<Algorithm> out;
  for (const Algorithm* a : registered_optimal_programs()) out.push_back(*a);
  Algorithm forced = *find_algorithm("keil-snoeyink-reduced");
  forced.name = "keil-snoeyink-reduced with the reduction forced";
  forced.run = [](const Polygon& p, Counters& counters) {
    return p.reflex_count() == 0 ? Decomposition{} : solve_on_reduced_polygon(p, counters);
  };
  out.push_back(forced);
  return out;
}

// Runs `a`, checks that its result is valid, returns its piece count.
std::size_t valid_pieces(const Algorithm& a, const Polygon& p, const std::string& label) {
  Counters counters;
  const Decomposition d = a.run(p, counters);
  const Validation v = validate(p, d, a.kind, a.steiner);
  EXPECT_TRUE(v.ok) << a.name << " on " << label << ": " << v.reason;
  EXPECT_TRUE(d.steiner.empty()) << a.name << " on " << label;
  return d.cuts.size() + 1;
}

Polygon polygon(std::vector<std::pair<double, double>> xy) {
  std::vector<Point> pts;
  for (auto [x, y] : xy) pts.emplace_back(x, y);
  return Polygon::make(pts);
}

// Hand-made polygons with the degeneracies that general-position arguments miss: 180-degree vertices,
// edge extensions through reflex vertices that end exactly at vertices, collinear reflex vertices.
std::vector<std::pair<std::string, Polygon>> hand_made() {
  return {
      {"L", polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})},
      {"L, flat vertex before the notch", polygon({{0, 0}, {2, 0}, {2, 1}, {1.5, 1}, {1, 1}, {1, 2}, {0, 2}})},
      {"L with midpoints", polygon({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}})},
      {"L, extension hits a vertex", polygon({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 2}, {0, 2}})},
      {"plus", polygon({{1, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 2}, {0, 2}, {0, 1}, {1, 1}})},
      {"comb with collinear teeth",
       polygon({{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})},
      {"triangle with flat vertices", polygon({{0, 0}, {1, 0}, {2, 0}, {1, 1}})},
      {"square with flat vertices", polygon({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}})},
      {"slot", polygon({{0, 0}, {6, 0}, {6, 3}, {4, 3}, {4, 1}, {2, 1}, {2, 3}, {0, 3}})},
      {"slot, flat top", polygon({{0, 0}, {6, 0}, {6, 3}, {5, 3}, {4, 3}, {4, 1}, {2, 1}, {2, 3}, {1, 3}, {0, 3}})},
      {"H", polygon({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 2}, {1, 2}, {1, 3}, {0, 3}})},
      {"two notches on one line", polygon({{0, 0}, {8, 0}, {8, 4}, {6, 4}, {5, 2}, {4, 4}, {3, 2}, {2, 4}, {0, 4}})},
      {"zigzag", polygon({{0, 0}, {6, 0}, {6, 2}, {5, 1}, {4, 2}, {3, 1}, {2, 2}, {1, 1}, {0, 2}})},
      {"spiral", polygon({{0, 0}, {6, 0}, {6, 6}, {1, 6}, {1, 2}, {4, 2}, {4, 4}, {3, 4}, {3, 3}, {2, 3}, {2, 5}, {5, 5}, {5, 1}, {0, 1}})},
      {"star", polygon({{0, -4}, {1, -1}, {4, 0}, {1, 1}, {0, 4}, {-1, 1}, {-4, 0}, {-1, -1}})},
      {"cross through reflex vertices",
       polygon({{0, 0}, {3, 0}, {3, 1}, {4, 1}, {4, 2}, {3, 2}, {3, 3}, {0, 3}, {0, 2}, {-1, 2}, {-1, 1}, {0, 1}})},
  };
}

std::vector<Point> rotated(const Polygon& p, std::size_t by) {
  std::vector<Point> ring(p.vertices());
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(by), ring.end());
  return ring;
}

TEST(OptimalPrograms, AreRegistered) {
  std::vector<std::string> names;
  for (const Algorithm* a : registered_optimal_programs()) names.push_back(a->name);
  for (const std::string name : {"greene-dp", "keil", "keil-snoeyink", "keil-snoeyink-reduced"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(BruteForce, KnowsTheHandMadeAnswers) {
  EXPECT_EQ(brute::min_convex_pieces(hand_made()[0].second), 2u);
  EXPECT_EQ(brute::min_convex_pieces(hand_made()[4].second), 3u);
  EXPECT_EQ(brute::min_convex_pieces(hand_made()[6].second), 1u);
  EXPECT_EQ(brute::min_convex_pieces(hand_made()[14].second), 3u);
}

void expect_count(const Polygon& p, std::size_t best, const std::string& label) {
  std::size_t ran = 0;
  for (const Algorithm& a : optimal_programs()) {
    if (!reliability::takes(a, p)) continue;
    EXPECT_EQ(valid_pieces(a, p, label), best) << a.name << " on " << label;
    ++ran;
  }
  EXPECT_GT(ran, 0u) << label;
}

void expect_brute_force_agrees(const Polygon& p, const std::string& label) {
  expect_count(p, brute::min_convex_pieces(p), label);
}

// The brute force once, every rotation of the input for the programs.
void expect_brute_force_agrees_on_every_rotation(const Polygon& p, const std::string& label) {
  const std::size_t best = brute::min_convex_pieces(p);
  for (std::size_t k = 0; k < p.size(); ++k)
    expect_count(Polygon::make(rotated(p, k)), best, label + " rotated " + std::to_string(k));
}

TEST(BruteForce, AgreesOnHandMadePolygonsAndEveryRotation) {
  for (const auto& [name, p] : hand_made()) expect_brute_force_agrees_on_every_rotation(p, name);
}

TEST(BruteForce, AgreesOnEveryFamilyUpToTwelveVertices) {
  std::size_t checked = 0;
  for (const Family& f : families())
    for (std::size_t n = 4; n <= 12; ++n)
      for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        std::vector<std::size_t> rs = {f.default_reflex(n)};
        if (f.controls_r)
          for (std::size_t r = 1; r + 3 <= n; r += 2) rs.push_back(r);
        for (std::size_t r : rs) {
          if (f.infeasible(n, r)) continue;
          const Polygon p = Polygon::make(generate(f.name, n, r, seed));
          expect_brute_force_agrees(p, f.name + " n=" + std::to_string(n) + " r=" + std::to_string(r) +
                                           " seed=" + std::to_string(seed));
          ++checked;
        }
      }
  EXPECT_GT(checked, 200u);
}

TEST(BruteForce, AgreesOnManyRandomPolygons) {
  for (std::size_t n = 5; n <= 12; ++n)
    for (std::uint64_t seed = 100; seed < 160; ++seed) {
      const Polygon p = Polygon::make(generate("random", n, std::nullopt, seed));
      expect_brute_force_agrees(p, "random n=" + std::to_string(n) + " seed=" + std::to_string(seed));
    }
}

TEST(BruteForce, AgreesOnRandomLatticePolygons) {
  std::mt19937 rng(7);
  for (int round = 0; round < 300; ++round) {
    const std::size_t n = 5 + round % 8;
    const Polygon p = lattice_polygon(n, 4 + round % 3, rng);
    expect_brute_force_agrees_on_every_rotation(p, "lattice polygon " + std::to_string(round));
  }
}

// Beyond the brute force's reach, degenerate polygons of up to ~40 vertices: the programs agree (the
// two engines, narrowest pairs and convex chains, share nothing but the visibility lists).
TEST(OptimalPrograms, AgreeOnNotchedLatticeRectangles) {
  std::mt19937 rng(3);
  std::size_t checked = 0;
  for (int round = 0; round < 600; ++round) {
    const std::optional<Polygon> p = notched_rectangle(rng);
    if (!p || p->reflex_count() == 0) continue;
    ++checked;
    const std::string label = "notched rectangle " + std::to_string(round);
    std::optional<std::size_t> first;
    for (const Algorithm& a : optimal_programs()) {
      const std::size_t pieces = valid_pieces(a, *p, label);
      if (!first) first = pieces;
      EXPECT_EQ(pieces, *first) << a.name << " on " << label;
    }
  }
  EXPECT_GT(checked, 300u);
}

// The reduction (Sec. 4) at work: few reflex vertices among many, the reduced polygon within
// 3 (r^2 + 2r) vertices (r reflex vertices, r RE-diagonal ends, r + r(r-1) DE-diagonal ends, each with
// its two neighbours), and the same count as Algorithm 1 on the whole polygon. The registered program
// reduces whenever its rays cost less than Algorithm 1 on the whole polygon; that is so here at
// n = 4000 and never at n <= 12.
TEST(Reduction, ShrinksThePolygonAndKeepsTheOptimum) {
  const Algorithm& registered = *find_algorithm("keil-snoeyink-reduced");
  const Algorithm& whole = *find_algorithm("keil-snoeyink");
  for (const std::string family : {"few-notches", "random", "spiral", "comb"})
    for (std::size_t n : {200, 4000})
      for (std::size_t r : {1, 3, 8, 16})
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
          if (find_family(family)->infeasible(n, r)) continue;
          const Polygon p = Polygon::make(generate(family, n, r, seed));
          const std::string label = family + " n=" + std::to_string(n) + " r=" + std::to_string(r) + " seed=" + std::to_string(seed);
          Counters forced_counters, registered_counters, whole_counters;
          const Decomposition forced = solve_on_reduced_polygon(p, forced_counters);
          const Decomposition chosen = registered.run(p, registered_counters);
          EXPECT_TRUE(validate(p, forced, Kind::Convex, false).ok) << label;
          EXPECT_LE(forced_counters["reduced_n"], static_cast<std::int64_t>(3 * (r * r + 2 * r))) << label;
          EXPECT_LT(forced_counters["reduced_n"], static_cast<std::int64_t>(n)) << label;
          EXPECT_GT(forced_counters["rays_shot"], 0) << label;
          if (n == 4000) {
            EXPECT_EQ(registered_counters["reduced_n"], forced_counters["reduced_n"]) << label;
          }
          const std::size_t optimum = whole.run(p, whole_counters).cuts.size();
          EXPECT_EQ(forced.cuts.size(), optimum) << label;
          EXPECT_EQ(chosen.cuts.size(), optimum) << label;
        }
}

// Larger polygons: every optimal program gives the same count on every family.
TEST(OptimalPrograms, AgreeWithEachOtherOnEveryFamily) {
  for (const Family& f : families())
    for (std::size_t n : {20, 40, 80})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        const Polygon p = Polygon::make(generate(f.name, n, r, seed));
        const std::string label = f.name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
        std::optional<std::size_t> first;
        for (const Algorithm& a : optimal_programs()) {
          if (!reliability::takes(a, p)) continue;
          const std::size_t pieces = valid_pieces(a, p, label);
          if (!first) first = pieces;
          EXPECT_EQ(pieces, *first) << a.name << " on " << label;
        }
      }
}

// CGAL 5.5's optimal partition is sometimes invalid or not minimal; where it is valid, no optimal
// program of ours may use more pieces, and where ours uses fewer, ours was shown valid above.
TEST(OptimalPrograms, NeverUseMorePiecesThanAValidCgalResult) {
  const Algorithm* cgal = find_algorithm("cgal-optimal");
  ASSERT_NE(cgal, nullptr);
  std::size_t valid_cgal = 0, ours_fewer = 0;
  for (const Family& f : families())
    for (std::size_t n : {10, 16, 30})
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        const Polygon p = Polygon::make(generate(f.name, n, r, seed));
        Counters counters;
        const Decomposition d = cgal->run(p, counters);
        if (!validate(p, d, cgal->kind, cgal->steiner).ok) continue;
        ++valid_cgal;
        const std::size_t cgal_pieces = pieces_of(p, d).size();
        for (const Algorithm& a : optimal_programs()) {
          const std::size_t ours = valid_pieces(a, p, f.name);
          EXPECT_LE(ours, cgal_pieces) << a.name << " on " << f.name << " n=" << n << " seed=" << seed;
          ours_fewer += ours < cgal_pieces;
        }
      }
  EXPECT_GT(valid_cgal, 20u);
  RecordProperty("cgal_valid", static_cast<int>(valid_cgal));
  RecordProperty("ours_fewer", static_cast<int>(ours_fewer));
}

// ---- minimum ink ----

// A total length as CORE's exact expression (independent of exact_ink), and the squared lengths that
// make it up, sorted (equal multisets are equal totals without asking CORE to prove it).
struct Ink {
  CORE::Expr total;
  std::vector<Rational> squared;
};

Ink ink_of(const Polygon& p, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& diagonals) {
  Ink ink{CORE::Expr(0), {}};
  for (auto [a, b] : diagonals) {
    const CORE::Expr dx = CORE::Expr(p[a].x()) - CORE::Expr(p[b].x()), dy = CORE::Expr(p[a].y()) - CORE::Expr(p[b].y());
    ink.total += CORE::sqrt(dx * dx + dy * dy);
    const Rational qx = Rational(p[a].x()) - Rational(p[b].x()), qy = Rational(p[a].y()) - Rational(p[b].y());
    ink.squared.push_back(qx * qx + qy * qy);
  }
  std::sort(ink.squared.begin(), ink.squared.end());
  return ink;
}

int compare_ink(const Ink& a, const Ink& b) {
  if (a.squared == b.squared) return 0;
  return a.total < b.total ? -1 : (b.total < a.total ? 1 : 0);
}

// min-ink's total against every convex decomposition by diagonals: never more, and equal to the least.
// Returns min-ink's counters.
Counters expect_least_ink(const Polygon& p, const std::string& label) {
  const Algorithm& a = *find_algorithm("min-ink");
  Counters counters;
  const Decomposition d = a.run(p, counters);
  const Validation v = validate(p, d, a.kind, a.steiner);
  EXPECT_TRUE(v.ok) << label << ": " << v.reason;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cuts;
  for (const Cut& c : d.cuts) cuts.emplace_back(c.a, c.b);
  const Ink ours = ink_of(p, cuts);
  std::optional<Ink> least;
  brute::each_convex_decomposition(p, p.size(), [&](const std::vector<brute::Diagonal>& set) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> diagonals;
    for (const brute::Diagonal& x : set) diagonals.emplace_back(x.a, x.b);
    Ink other = ink_of(p, diagonals);
    EXPECT_LE(compare_ink(ours, other), 0) << label << ": min-ink " << CGAL::to_double(ours.total) << " > "
                                           << CGAL::to_double(other.total);
    if (!least || compare_ink(other, *least) < 0) least = std::move(other);
  });
  EXPECT_TRUE(least.has_value()) << label;
  if (least) {
    EXPECT_EQ(compare_ink(ours, *least), 0) << label;
  }
  return counters;
}

TEST(MinInk, LeastInkOnHandMadePolygons) {
  for (const auto& [name, p] : hand_made()) expect_least_ink(p, name);
}

TEST(MinInk, LeastInkOnEveryFamilyUpToTenVertices) {
  for (const Family& f : families())
    for (std::size_t n = 4; n <= 10; ++n)
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        expect_least_ink(Polygon::make(generate(f.name, n, r, seed)),
                         f.name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed));
      }
}

// Lattice polygons are full of equal lengths: the exact comparison is exercised (ties cancelled and
// sums evaluated), and its verdicts are checked against CORE through the brute force.
TEST(MinInk, LeastInkOnRandomLatticePolygons) {
  std::mt19937 rng(11);
  std::int64_t cancelled = 0, evaluated = 0;
  for (int round = 0; round < 300; ++round) {
    const Polygon p = lattice_polygon(5 + round % 6, 4 + round % 4, rng);
    Counters counters = expect_least_ink(p, "lattice polygon " + std::to_string(round));
    cancelled += counters["exact_ties_cancelled"];
    evaluated += counters["exact_evaluations"];
  }
  EXPECT_GT(cancelled, 0);
  EXPECT_GT(evaluated, 0);
  RecordProperty("ties_cancelled", static_cast<int>(cancelled));
  RecordProperty("sums_evaluated", static_cast<int>(evaluated));
}

// Larger polygons: min-ink is valid, never has fewer pieces than the optimum, and never more ink than
// the optimal programs' decompositions (compared exactly).
TEST(MinInk, NoMoreInkThanTheOptimalProgramsOnEveryFamily) {
  const Algorithm& min_ink = *find_algorithm("min-ink");
  for (const Family& f : families())
    for (std::size_t n : {20, 40})
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        const std::size_t r = f.default_reflex(n);
        if (f.infeasible(n, r)) continue;
        const Polygon p = Polygon::make(generate(f.name, n, r, seed));
        const std::string label = f.name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
        Counters counters;
        const Decomposition d = min_ink.run(p, counters);
        ASSERT_TRUE(validate(p, d, min_ink.kind, min_ink.steiner).ok) << label;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> ours;
        for (const Cut& c : d.cuts) ours.emplace_back(c.a, c.b);
        for (const Algorithm& a : optimal_programs()) {
          const Decomposition other = a.run(p, counters);
          std::vector<std::pair<std::uint32_t, std::uint32_t>> theirs;
          for (const Cut& c : other.cuts) theirs.emplace_back(c.a, c.b);
          EXPECT_GE(ours.size(), theirs.size()) << a.name << " on " << label;
          EXPECT_LE(compare_ink(ink_of(p, ours), ink_of(p, theirs)), 0) << a.name << " on " << label;
        }
      }
}

// The least ink need not come with the fewest pieces (found by search over lattice polygons): here
// three short diagonals beat two long ones.
TEST(MinInk, CanUseMorePiecesThanTheMinimum) {
  const Polygon p = polygon({{4, 3}, {4, 1}, {5, 5}, {6, 6}, {4, 6}, {2, 4}, {2, 3}, {0, 0}});
  Counters counters;
  EXPECT_EQ(find_algorithm("keil-snoeyink")->run(p, counters).cuts.size(), 2u);
  EXPECT_EQ(find_algorithm("min-ink")->run(p, counters).cuts.size(), 3u);
  expect_least_ink(p, "more pieces, less ink");
}

// The exact rule for sums of square roots (engines/convex/exact_ink.h), against CORE's exact expressions.
std::pair<Rational, Rational> term(long c, long q) { return {Rational(c), Rational(q)}; }

TEST(ExactInk, FindsExactTiesThatIntervalsCannot) {
  EXPECT_EQ(ink::sign_of_root_sum({term(1, 8), term(-1, 2), term(-1, 2)}), 0);               // 2 sqrt2
  EXPECT_EQ(ink::sign_of_root_sum({term(1, 18), term(1, 2), term(-1, 32)}), 0);               // 4 sqrt2
  EXPECT_EQ(ink::sign_of_root_sum({term(1, 12), term(1, 27), term(-1, 75)}), 0);              // 5 sqrt3
  EXPECT_EQ(ink::sign_of_root_sum({{Rational(1), Rational(1, 2)}, {Rational(-1, 2), Rational(2)}}), 0);
  EXPECT_EQ(ink::sign_of_root_sum({term(1, 5), term(1, 45), term(-1, 20), term(-1, 20)}), 0);  // 4 sqrt5
}

TEST(ExactInk, OrdersNearTiesBeyondDoublePrecision) {
  // sqrt(m) + sqrt(m+3) < sqrt(m+1) + sqrt(m+2) by concavity; the gap is about m^(-3/2)/2, far below
  // the doubles' resolution of the totals.
  for (long m : {1000000L, 1000000000000L, 4000000000000000L}) {
    long bits = 0;
    EXPECT_EQ(ink::sign_of_root_sum({term(1, m), term(1, m + 3), term(-1, m + 1), term(-1, m + 2)}, &bits), -1) << m;
    EXPECT_GT(bits, 53) << m;
    const CORE::Expr lhs = CORE::sqrt(CORE::Expr(double(m))) + CORE::sqrt(CORE::Expr(double(m + 3)));
    const CORE::Expr rhs = CORE::sqrt(CORE::Expr(double(m + 1))) + CORE::sqrt(CORE::Expr(double(m + 2)));
    EXPECT_TRUE(lhs < rhs) << m;
  }
  EXPECT_EQ(ink::sign_of_root_sum({term(1, 2), term(1, 3), term(-1, 10)}), -1);  // 3.146 < 3.162
}

TEST(ExactInk, AgreesWithCoreOnRandomSums) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<long> radicand(1, 60), count(1, 4);
  for (int round = 0; round < 2000; ++round) {
    std::vector<std::pair<Rational, Rational>> terms;
    CORE::Expr value(0);
    for (int side : {1, -1})
      for (long k = count(rng); k > 0; --k) {
        const long q = radicand(rng);
        terms.push_back(term(side, q));
        value += side * CORE::sqrt(CORE::Expr(double(q)));
      }
    const int core_sign = value > 0 ? 1 : (value < 0 ? -1 : 0);
    EXPECT_EQ(ink::sign_of_root_sum(terms), core_sign) << "round " << round;
  }
}

}  // namespace
}  // namespace pd
