// Property tests over registry x families x seeds: every registered algorithm is tested the day it
// registers. Our algorithms must be valid; the CGAL peers are reported as they are, and the validator's
// verdict on them must agree with the independent check.
#include "core/io.h"
#include "core/registry.h"
#include "core/validate.h"
#include "generators/family.h"
#include "tests/fixtures.h"
#include "tests/independent_check.h"
#include "tests/reliability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <utility>

namespace pd {
namespace {

bool within_test_budget(const Algorithm& a, const Polygon& p) {
  return reliability::within_work(a, p, reliability::kTestWork);
}

// The names that the files in algorithms/ register, read from their REGISTER_ALGORITHM lines, and the
// number of such lines.
std::pair<std::set<std::string>, std::size_t> names_in_algorithm_files() {
  std::set<std::string> names;
  std::size_t registrations = 0;
  for (const auto& entry : std::filesystem::directory_iterator(PD_SOURCE_DIR "/algorithms")) {
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t at = text.find("\nREGISTER_ALGORITHM("); at != std::string::npos;
         at = text.find("\nREGISTER_ALGORITHM(", at + 1)) {
      ++registrations;
      const std::size_t name = text.find(".name = \"", at);
      if (name == std::string::npos) continue;
      const std::size_t begin = name + 9;
      names.insert(text.substr(begin, text.find('"', begin) - begin));
    }
  }
  return {names, registrations};
}

// Every REGISTER_ALGORITHM line in algorithms/ is in the registry, one algorithm per file named after
// it: a registration lost to the linker fails here. The variants (REGISTER_VARIANTS) have no file of
// their own: each names its base, and its family's name is an algorithm with a file.
TEST(Registry, HoldsEveryAlgorithmFile) {
  std::set<std::string> names;
  for (const Algorithm& a : algorithms())
    if (a.variant_of.empty()) names.insert(a.name);
  const auto [in_files, registrations] = names_in_algorithm_files();
  EXPECT_EQ(names, in_files);
  EXPECT_EQ(registrations, names.size());
  for (const std::string& name : names) {
    std::string file = name;
    std::replace(file.begin(), file.end(), '-', '_');
    EXPECT_TRUE(std::filesystem::exists(PD_SOURCE_DIR "/algorithms/" + file + ".cpp")) << name;
  }
  EXPECT_EQ(static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(PD_SOURCE_DIR "/algorithms"),
                                                   std::filesystem::directory_iterator())),
            names.size());
  EXPECT_THROW(register_algorithm(*find_algorithm("monotone")), std::logic_error);  // a second "monotone"
}

// hertel-mehlhorn[T] exists for exactly the registered triangulations T without Steiner points but
// monotone (whose variant is hertel-mehlhorn), made from T: its input limits, ceiling, peer and time.
TEST(Registry, HasAHertelMehlhornVariantOfEveryTriangulation) {
  std::size_t variants = 0;
  for (const Algorithm& base : algorithms()) {
    const Algorithm* v = find_algorithm(variant_name("hertel-mehlhorn", base.name));
    const bool wanted = base.kind == Kind::Triangulation && !base.steiner && base.name != "monotone";
    ASSERT_EQ(v != nullptr, wanted) << base.name;
    if (!v) continue;
    ++variants;
    EXPECT_EQ(v->variant_of, base.name);
    EXPECT_EQ(v->kind, Kind::Convex);
    EXPECT_FALSE(v->steiner);
    EXPECT_EQ(v->accepts.holes, base.accepts.holes);
    EXPECT_EQ(v->size_ceiling, base.size_ceiling);
    EXPECT_EQ(v->peer, base.peer);
    EXPECT_EQ(v->time_bound, base.name == "seidel" ? "n*log(n)" : base.time_bound);  // holes: n log n
  }
  EXPECT_GE(variants, 8u);
  for (const Algorithm& a : algorithms()) {
    if (!a.variant_of.empty()) {
      EXPECT_EQ(a.name, variant_name("hertel-mehlhorn", a.variant_of));
    }
  }
}

// The registrations of Registry.MakesAVariantWhicheverComesFirst, which it makes in a child process so
// that the test entries never join this process's registry: a reason, or "" when all went well.
std::string variants_made_in_either_order() {
  const Algorithm late_base{.name = "zz-test-fan", .kind = Kind::Triangulation, .accepts = {.convex_only = true},
                            .run = [](const Polygon& p, Counters&) {
                              Decomposition d;
                              for (std::size_t i = 2; i + 1 < p.size(); ++i) d.add_cut(0, i);
                              return d;
                            }};
  register_algorithm(late_base);
  const Algorithm* late = find_algorithm("hertel-mehlhorn[zz-test-fan]");
  if (late == nullptr || late->variant_of != "zz-test-fan") return "no variant of a base registered late";
  register_variant_family({.name = "zz-test-family",
                           .takes = [](const Algorithm& base) { return base.name == "zz-test-fan"; },
                           .make = [](const Algorithm& base) { return base; }});
  const Algorithm* made = find_algorithm("zz-test-family[zz-test-fan]");
  if (made == nullptr || made->variant_of != "zz-test-fan") return "no variant from a family registered late";
  if (find_algorithm("zz-test-family[hertel-mehlhorn[zz-test-fan]]")) return "a variant of a variant";
  const Polygon hexagon = Polygon::make({{0, 0}, {4, 0}, {6, 2}, {6, 3}, {3, 5}, {0, 3}});
  Counters counters;
  if (!find_algorithm("hertel-mehlhorn[zz-test-fan]")->run(hexagon, counters).cuts.empty() || counters["diagonals"] != 3)
    return "the variant did not remove the fan's 3 diagonals of a convex hexagon";
  const Algorithm clash{.name = "hertel-mehlhorn[zz-test-fan2]", .kind = Kind::Convex};
  register_algorithm(clash);
  const Algorithm clashing_base{.name = "zz-test-fan2", .kind = Kind::Triangulation};
  if (taken_name(clashing_base) != "hertel-mehlhorn[zz-test-fan2]") return "the clash of a variant's name is not seen";
  return {};
}

// A family registered after its bases, and a base registered after its family, both get the variant; a
// base whose variant's name is taken is seen before it is registered.
TEST(Registry, MakesAVariantWhicheverComesFirst) {
  EXPECT_EXIT(
      {
        const std::string why = variants_made_in_either_order();
        std::fprintf(stderr, "%s", why.c_str());
        std::exit(why.empty() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// What an algorithm takes is refused with one sentence naming the limit, before it runs.
TEST(Registry, RefusesWhatAnAlgorithmDoesNotTake) {
  const Polygon square = Polygon::make({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const Polygon ell = Polygon::make({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const Algorithm fan{.name = "fan", .kind = Kind::Triangulation, .accepts = {.convex_only = true}};
  EXPECT_FALSE(refusal(fan, square));
  EXPECT_EQ(refusal(fan, ell), "fan takes only convex polygons; this one has 1 reflex vertex");
  const Algorithm small{.name = "small", .accepts = {.max_vertices = 5}};
  EXPECT_FALSE(refusal(small, square));
  EXPECT_EQ(refusal(small, ell), "small takes at most 5 vertices; this polygon has 6");
  EXPECT_FALSE(reliability::takes(fan, ell));
  EXPECT_TRUE(reliability::takes(fan, square));
}

struct Case {
  std::string family;
  std::size_t n;
  std::optional<std::size_t> r;
  std::uint64_t seed;
};

std::vector<Case> small_cases() {
  std::vector<Case> cases;
  for (const Family& f : families())
    for (std::size_t n : {12, 24, 60})
      for (std::uint64_t seed : {1, 2, 3}) {
        const std::size_t r = f.r_is_outcome ? reflex_outcome(f.name, n, seed) : f.default_reflex(n);
        if (f.r_is_outcome || !f.infeasible(n, r)) cases.push_back({f.name, n, r, seed});
        if (f.controls_r && n == 24 && !f.infeasible(n, 1)) cases.push_back({f.name, n, std::size_t{1}, seed});
      }
  return cases;
}

independent::Cycle cycle_of(const std::vector<QPoint>& pts, const Piece& piece) {
  independent::Cycle c;
  for (VertexId v : piece) c.push_back(pts[v]);
  return c;
}

struct Outcome {
  std::size_t pieces;
  Validation validation;
};

Outcome run_and_check(const Algorithm& a, const Polygon& p, const std::string& label) {
  Counters counters;
  const Decomposition d = a.run(p, counters);
  const Validation v = validate(p, d, a.kind, a.steiner);
  std::vector<Piece> pieces;
  try {
    pieces = pieces_of(p, d);
  } catch (const std::invalid_argument&) {
    EXPECT_FALSE(v.ok) << label;
  }
  if (!is_peer(a)) {
    EXPECT_TRUE(v.ok) << label << ": " << v.reason;
  }
  if (p.size() <= 60 && !pieces.empty() && d.steiner.empty()) {
    const std::vector<QPoint> pts = exact_points(p, d);
    std::vector<independent::Cycle> cycles;
    for (const Piece& piece : pieces) cycles.push_back(cycle_of(pts, piece));
    const bool independent_ok = independent::tiles_once(independent::rings_of(p), cycles, a.kind != Kind::Partition);
    EXPECT_EQ(v.ok, independent_ok) << label << ": validator says " << (v.ok ? "valid" : v.reason);
  }
  if (v.ok) {
    const std::size_t n = p.size(), r = p.reflex_count(), h = p.hole_count();
    if (a.kind == Kind::Triangulation) {
      EXPECT_EQ(pieces.size(), n + 2 * h - 2) << label;
    }
    if (a.kind == Kind::Convex) {
      EXPECT_GE(pieces.size() + h, (r + 1) / 2 + 1) << label;
    }
    if (a.pieces_bound == "== r+1" || a.pieces_bound == "== r+1-h") {
      EXPECT_EQ(pieces.size() + h, r + 1) << label;
    }
  }
  return {pieces.size(), v};
}

class EveryAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAlgorithm, IsValidOnEveryFamily) {
  const Algorithm& a = *find_algorithm(GetParam());
  std::size_t ran = 0;
  for (const Case& c : small_cases()) {
    const Polygon p = Polygon::make(generate(c.family, c.n, c.r, c.seed));
    if (!within_test_budget(a, p)) continue;
    run_and_check(a, p, a.name + " on " + c.family + " n=" + std::to_string(c.n) + " seed=" + std::to_string(c.seed));
    ++ran;
  }
  EXPECT_GT(ran, 0u);
}

// 180-degree vertices (generate --collinear) on every family: neither convex nor reflex, and no
// algorithm may take one for a notch or drop it from the pieces.
TEST_P(EveryAlgorithm, IsValidWithCollinearVertices) {
  const Algorithm& a = *find_algorithm(GetParam());
  std::size_t ran = 0;
  for (const Family& f : families())
    for (std::uint64_t seed : {1, 2}) {
      const Polygon p = Polygon::make(generate_with_collinear(f.name, 24, std::nullopt, 8, seed));
      if (refusal(a, p) || !within_test_budget(a, p)) continue;
      run_and_check(a, p, a.name + " on " + f.name + " with 8 collinear vertices, seed=" + std::to_string(seed));
      ++ran;
    }
  EXPECT_GT(ran, 0u);
}

// An optimal program's piece count cannot depend on the starting vertex (CGAL issue 4398, which is
// why the peer is not held to it).
class OurOptimalProgram : public ::testing::TestWithParam<std::string> {};

TEST_P(OurOptimalProgram, CountIsTheSameOnEveryRotation) {
  const Algorithm& a = *find_algorithm(GetParam());
  std::size_t ran = 0;
  for (const Case& c : small_cases()) {
    if (c.n > 12) continue;
    std::vector<Point> ring = generate(c.family, c.n, c.r, c.seed);
    if (refusal(a, Polygon::make(ring))) continue;
    ++ran;
    const std::size_t first = run_and_check(a, Polygon::make(ring), a.name).pieces;
    for (std::size_t k = 1; k < ring.size(); ++k) {
      std::rotate(ring.begin(), ring.begin() + 1, ring.end());
      EXPECT_EQ(run_and_check(a, Polygon::make(ring), a.name).pieces, first) << c.family << " rotation " << k;
    }
  }
  EXPECT_GT(ran, 0u);
}

// Real-world polygons: the outer ring of every earcut fixture that is simple and that the algorithm
// takes (none is convex).
TEST_P(EveryAlgorithm, EarcutOuterRings) {
  const Algorithm& a = *find_algorithm(GetParam());
  std::size_t taken = 0, ran = 0;
  for (const auto& [name, ring] : fixtures::earcut_outer_rings()) {
    std::optional<Polygon> p;
    try {
      p = Polygon::make(ring);
    } catch (const PolygonError&) {
      continue;
    }
    if (refusal(a, *p)) continue;
    ++taken;
    if (!within_test_budget(a, *p)) continue;
    run_and_check(a, *p, a.name + " on earcut " + name);
    ++ran;
  }
  if (taken == 0) GTEST_SKIP() << a.name << " takes none of the rings";
  EXPECT_GT(ran, 0u);
}

std::vector<std::string> registered_names(bool only_our_optimal) {
  std::vector<std::string> names;
  for (const Algorithm& a : algorithms())
    if (!only_our_optimal || (a.optimal && !is_peer(a))) names.push_back(a.name);
  return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (c == '-' || c == '[' || c == ']') c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryAlgorithm, ::testing::ValuesIn(registered_names(false)), test_name);
INSTANTIATE_TEST_SUITE_P(Registry, OurOptimalProgram, ::testing::ValuesIn(registered_names(true)), test_name);

}  // namespace
}  // namespace pd
