// Tests of the polygon families: exact n and r, counter-clockwise, simple, integer coordinates below
// 2^31, no collinear vertices, exact feasibility ranges, determinism (pinned checksums), and n = 10^6.
#include "generators/family.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace pd {
namespace {

constexpr std::size_t kMaxN = 2'000'000;
constexpr std::size_t kMaxXPatternN = 1'000'000;
constexpr std::size_t kMaxX2PairsN = 1'000'000;
constexpr std::size_t kMaxX4QuadsN = 1'000'000;

struct IntPoint {
  std::int64_t x, y;
  bool operator<(const IntPoint& o) const { return x != o.x ? x < o.x : y < o.y; }
  bool operator==(const IntPoint& o) const { return x == o.x && y == o.y; }
};

int orient(IntPoint p, IntPoint q, IntPoint r) {
  const __int128 c =
      static_cast<__int128>(q.x - p.x) * (r.y - p.y) - static_cast<__int128>(q.y - p.y) * (r.x - p.x);
  return (c > 0) - (c < 0);
}

// The coordinates as integers; fails the test unless each is an integer of magnitude below 2^31.
std::vector<IntPoint> integer_points(const std::vector<Point>& polygon) {
  std::vector<IntPoint> out;
  out.reserve(polygon.size());
  for (const Point& p : polygon) {
    for (double c : {p.x(), p.y()}) {
      EXPECT_EQ(c, std::floor(c)) << "non-integer coordinate " << c;
      EXPECT_LT(std::abs(c), 2147483648.0) << "coordinate beyond 2^31";
    }
    out.push_back({static_cast<std::int64_t>(p.x()), static_cast<std::int64_t>(p.y())});
  }
  return out;
}

std::size_t reflex_count(const std::vector<Point>& polygon) {
  const std::size_t n = polygon.size();
  std::size_t reflex = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (pd::orient(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]) < 0) ++reflex;
  }
  return reflex;
}

std::size_t collinear_count(const std::vector<IntPoint>& v) {
  const std::size_t n = v.size();
  std::size_t collinear = 0;
  for (std::size_t i = 0; i < n; ++i) collinear += orient(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == 0;
  return collinear;
}

__int128 twice_signed_area(const std::vector<IntPoint>& v) {
  __int128 area = 0;
  for (std::size_t i = 0, n = v.size(); i < n; ++i) {
    const IntPoint& p = v[i];
    const IntPoint& q = v[(i + 1) % n];
    area += static_cast<__int128>(p.x) * q.y - static_cast<__int128>(q.x) * p.y;
  }
  return area;
}

bool in_box(IntPoint p, IntPoint q, IntPoint r) {
  return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
         r.y <= std::max(p.y, q.y);
}

// Whether the closed segments ab and cd share a point.
bool segments_meet(IntPoint a, IntPoint b, IntPoint c, IntPoint d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) || (o3 == 0 && in_box(c, d, a)) ||
         (o4 == 0 && in_box(c, d, b));
}

// O(n^2): empty when the cycle is simple, else the first problem found.
std::string simplicity_problem(const std::vector<IntPoint>& v) {
  const std::size_t n = v.size();
  std::vector<IntPoint> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return "duplicate vertex";
  for (std::size_t i = 0; i < n; ++i) {
    // Adjacent edges v[i]v[i+1] and v[i+1]v[i+2] may share only v[i+1].
    const IntPoint a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
    if (orient(a, b, c) == 0 && (in_box(b, c, a) || in_box(a, b, c))) {
      return "edges " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " overlap";
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const IntPoint a = v[i], b = v[(i + 1) % n];
    const std::int64_t lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
    const std::int64_t lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      const IntPoint c = v[j], d = v[(j + 1) % n];
      if (std::max(c.x, d.x) < lo_x || std::min(c.x, d.x) > hi_x || std::max(c.y, d.y) < lo_y ||
          std::min(c.y, d.y) > hi_y) {
        continue;
      }
      if (segments_meet(a, b, c, d))
        return "edges " + std::to_string(i) + " and " + std::to_string(j) + " meet";
    }
  }
  return "";
}

// Every property, with the O(n^2) simplicity check.
void expect_valid(const std::string& family, std::size_t n, std::size_t r, std::uint64_t seed) {
  SCOPED_TRACE(family + " n=" + std::to_string(n) + " r=" + std::to_string(r) +
               " seed=" + std::to_string(seed));
  const std::vector<Point> polygon = generate(family, n, r, seed);
  ASSERT_EQ(polygon.size(), n);
  EXPECT_EQ(reflex_count(polygon), r);
  const std::vector<IntPoint> v = integer_points(polygon);
  EXPECT_GT(twice_signed_area(v), 0) << "not counter-clockwise";
  EXPECT_EQ(collinear_count(v), 0u);
  EXPECT_EQ(simplicity_problem(v), "");
}

// The documented ranges, restated independently of the families' code.
const std::map<std::string, std::function<bool(std::size_t, std::size_t)>>& documented_ranges() {
  static const std::map<std::string, std::function<bool(std::size_t, std::size_t)>> ranges{
      {"comb", [](std::size_t n, std::size_t r) { return n >= 3 && n <= kMaxN && 3 * r <= 2 * (n - 3); }},
      {"convex", [](std::size_t n, std::size_t r) { return n >= 3 && n <= kMaxN && r == 0; }},
      {"few-notches",
       [](std::size_t n, std::size_t r) { return n >= 4 && n <= kMaxN && 2 * r <= n && r + 4 <= n; }},
      {"notch-heavy",
       [](std::size_t n, std::size_t r) { return n >= 3 && n <= kMaxN && r + 3 <= n && n - 3 - r <= r; }},
      {"random", [](std::size_t n, std::size_t r) { return n >= 3 && n <= kMaxN && (r == 0 || r + 4 <= n); }},
      {"spiral",
       [](std::size_t n, std::size_t r) { return n >= 6 && n <= kMaxN && r >= 1 && 2 * r + 4 <= n; }},
      {"x-pattern",
       [](std::size_t n, std::size_t r) {
         return n <= kMaxXPatternN && r >= 3 && r % 3 == 0 && n >= (r == 3 ? 12 : 3 * r + 4);
       }},
      {"x2-pairs",
       [](std::size_t n, std::size_t r) { return n <= kMaxX2PairsN && r >= 2 && r % 2 == 0 && n >= 3 * r + 4; }},
      {"x4-quads",
       [](std::size_t n, std::size_t r) { return n <= kMaxX4QuadsN && r >= 4 && r % 4 == 0 && n >= 3 * r + 4; }},
      // r is an outcome of the method: a grid of (n, r) never holds these (OutcomeFamilies).
      {"star", [](std::size_t, std::size_t) { return false; }},
      {"space-partition", [](std::size_t, std::size_t) { return false; }},
      {"2-opt", [](std::size_t, std::size_t) { return false; }},
  };
  return ranges;
}

std::uint64_t fnv1a(const std::vector<Point>& polygon) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const Point& p : polygon) {
    const std::string line = std::to_string(static_cast<std::int64_t>(p.x())) + " " +
                             std::to_string(static_cast<std::int64_t>(p.y())) + "\n";
    for (unsigned char c : line) {
      hash ^= c;
      hash *= 0x100000001b3ULL;
    }
  }
  return hash;
}

TEST(Generators, SimplicityCheckFindsProblems) {
  EXPECT_EQ(simplicity_problem({{0, 0}, {4, 0}, {4, 4}, {0, 4}}), "");
  EXPECT_NE(simplicity_problem({{0, 0}, {4, 4}, {4, 0}, {0, 4}}), "");          // bow tie
  EXPECT_NE(simplicity_problem({{0, 0}, {4, 0}, {2, 0}, {2, 3}}), "");          // folds back on itself
  EXPECT_NE(simplicity_problem({{0, 0}, {6, 0}, {6, 6}, {3, 0}, {0, 6}}), "");  // vertex on an edge
  EXPECT_NE(simplicity_problem({{0, 0}, {6, 0}, {3, 3}, {6, 6}, {0, 6}, {3, 3}}), "");  // repeated vertex
}

TEST(Generators, RegistryListsTheFamiliesSortedByName) {
  std::vector<std::string> names;
  for (const Family& f : families()) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"2-opt", "comb", "convex", "few-notches", "notch-heavy", "random",
                                             "space-partition", "spiral", "star", "x-pattern", "x2-pairs",
                                             "x4-quads"}));
  ASSERT_NE(find_family("spiral"), nullptr);
  EXPECT_EQ(find_family("spiral")->name, "spiral");
  EXPECT_EQ(find_family("no-such"), nullptr);
  EXPECT_THROW(register_family(*find_family("comb")), std::logic_error);  // a second "comb" is a bug
  for (const Family& f : families()) {
    EXPECT_FALSE(f.shape.empty()) << f.name;
    EXPECT_FALSE(f.range().empty()) << f.name;
  }
  EXPECT_FALSE(find_family("convex")->controls_r);
  EXPECT_TRUE(find_family("random")->controls_r);
}

TEST(Generators, UnknownFamilyNamesTheFamilies) {
  try {
    generate("hexagon", 10, std::nullopt, 1);
    FAIL() << "no exception";
  } catch (const GeneratorError&) {
    FAIL() << "GeneratorError for an unknown family";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown family hexagon; families: 2-opt, comb, convex, few-notches, notch-heavy, random, "
              "space-partition, spiral, star, x-pattern, x2-pairs, x4-quads, comb-holes, convex-holes");
  }
}

TEST(Generators, InfeasibleMatchesTheDocumentedRange) {
  for (const auto& [name, feasible] : documented_ranges()) {
    const Family* f = find_family(name);
    ASSERT_NE(f, nullptr) << name;
    std::vector<std::size_t> sizes;
    for (std::size_t n = 0; n <= 200; ++n) sizes.push_back(n);
    for (std::size_t n : {kMaxXPatternN - 1, kMaxXPatternN, kMaxXPatternN + 1, kMaxN - 1, kMaxN, kMaxN + 1}) {
      sizes.push_back(n);
    }
    for (std::size_t n : sizes) {
      std::vector<std::size_t> rs;
      if (n <= 200) {
        for (std::size_t r = 0; r <= n + 2; ++r) rs.push_back(r);
      } else {
        rs = {0,     1,     3,     6,     n / 4, n / 2 - 3, n / 2 - 2, n / 2, (2 * n - 6) / 3,
              n - 6, n - 5, n - 4, n - 3, n - 2};
      }
      for (std::size_t r : rs) {
        EXPECT_EQ(!f->infeasible(n, r).has_value(), feasible(n, r)) << name << " n=" << n << " r=" << r;
      }
    }
  }
}

TEST(Generators, InfeasibleThrowsNamingTheRange) {
  for (const Family& f : families()) {
    if (f.r_is_outcome) continue;  // it makes the r its method gives (OutcomeFamilies)
    for (std::size_t n = 0; n <= 40; ++n) {
      for (std::size_t r = 0; r <= n + 2; ++r) {
        if (!f.infeasible(n, r)) continue;
        try {
          generate(f.name, n, r, 1);
          ADD_FAILURE() << f.name << " made n=" << n << " r=" << r;
        } catch (const GeneratorError& e) {
          const std::string what = e.what();
          EXPECT_NE(what.find("feasible"), std::string::npos) << what;
          EXPECT_NE(what.find(f.range()), std::string::npos) << what;
        }
      }
    }
  }
  try {
    generate("spiral", 10, 9, 1);
    FAIL() << "no exception";
  } catch (const GeneratorError& e) {
    EXPECT_EQ(std::string(e.what()),
              "family spiral cannot make n=10, r=9: feasible 6 <= n <= 2000000, 1 <= r <= n/2-2");
  }
}

TEST(Generators, EveryFeasibleSmallCaseIsValid) {
  for (const Family& f : families()) {
    for (std::size_t n = 3; n <= 48; ++n) {
      for (std::size_t r = 0; r + 3 <= n; ++r) {
        if (f.infeasible(n, r)) continue;
        for (std::uint64_t seed : {1, 2, 3, 4, 5}) expect_valid(f.name, n, r, seed);
      }
    }
  }
}

TEST(Generators, MediumSizesAtTheEdgesOfTheRanges) {
  for (const Family& f : families()) {
    for (std::size_t n : {97, 256, 1001, 2500}) {
      std::vector<std::size_t> candidates{
          0,           1,     3,     16,    n / 4, f.default_reflex(n), n / 2 - 2, n / 2, (2 * n - 6) / 3,
          (n - 2) / 2, n - 6, n - 5, n - 4, n - 3};
      if (n == 2500) candidates = {0, 1, 3, f.default_reflex(n), n - 4, n - 3};
      for (std::size_t r : candidates) {
        if (!f.infeasible(n, r)) expect_valid(f.name, n, r, 11 + n);
      }
    }
  }
}

// x4-quads at every r it is tested with elsewhere (1 to 8 groups), at its least n and beyond.
TEST(Generators, QuadsAreSimpleWithExactlyRNotches) {
  for (std::size_t r : {4, 8, 12, 16, 20, 24, 28, 32})
    for (std::size_t n : {3 * r + 4, 3 * r + 5, 3 * r + 17, 10 * r})
      for (std::uint64_t seed : {1, 2, 3}) expect_valid("x4-quads", n, r, seed);
}

TEST(Generators, DefaultReflexIsFeasible) {
  for (const Family& f : families()) {
    if (f.r_is_outcome) continue;  // OutcomeFamilies below
    std::size_t least = 0;
    while (f.infeasible(least, f.default_reflex(least))) ++least;
    for (std::size_t n = least; n <= 500; ++n) {
      EXPECT_FALSE(f.infeasible(n, f.default_reflex(n))) << f.name << " n=" << n;
    }
    for (std::size_t n : {4096, 65537, 1'000'000}) {
      EXPECT_FALSE(f.infeasible(n, f.default_reflex(n))) << f.name << " n=" << n;
    }
    const std::vector<Point> polygon = generate(f.name, 100, std::nullopt, 5);
    EXPECT_EQ(reflex_count(polygon), f.default_reflex(100)) << f.name;
  }
}

TEST(Generators, SameArgumentsGiveTheSamePolygon) {
  for (const Family& f : families()) {
    EXPECT_EQ(generate(f.name, 300, std::nullopt, 42), generate(f.name, 300, std::nullopt, 42)) << f.name;
  }
  EXPECT_NE(generate("random", 300, 40, 1), generate("random", 300, 40, 2));
}

TEST(Generators, ChecksumsArePinned) {
  struct Case {
    const char* family;
    std::size_t n, r;
    std::uint64_t seed;
    std::uint64_t fnv;
  };
  const Case cases[] = {
      {"random", 1000, 250, 1, 0x5d7a53d8053f50bfULL},
      {"random", 50, 46, 7, 0xfbceff2b57fc60c7ULL},
      {"convex", 999, 0, 3, 0xd5f23e43b2291e9bULL},
      {"few-notches", 5000, 16, 2, 0x691186c156f5aca2ULL},
      {"spiral", 400, 150, 5, 0xc8b70be5ebfd77eaULL},
      {"comb", 301, 120, 9, 0x910fbd8b90117cabULL},
      {"notch-heavy", 700, 500, 4, 0x06ef5b2316f4e86cULL},
      {"x-pattern", 12, 3, 1, 0x5675edbaae52109cULL},
      {"x-pattern", 500, 30, 8, 0x68a8b6a2ca73f126ULL},
      {"x2-pairs", 10, 2, 1, 0x0d73b324820f56ccULL},
      {"x2-pairs", 600, 60, 3, 0x8d7b5fdb215f625cULL},
      {"x4-quads", 16, 4, 1, 0xc10f4616a04c1751ULL},
      {"x4-quads", 700, 32, 3, 0xeacba1b31c3f0775ULL},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(fnv1a(generate(c.family, c.n, c.r, c.seed)), c.fnv)
        << c.family << " n=" << c.n << " r=" << c.r << " seed=" << c.seed;
  }
}

// O(n) checks for large n: size, coordinates, r, orientation, no collinear vertex.
void expect_large_valid(const std::string& family, std::size_t n, std::size_t r) {
  SCOPED_TRACE(family + " n=" + std::to_string(n));
  const std::vector<Point> polygon = generate(family, n, r, 2024);
  ASSERT_EQ(polygon.size(), n);
  EXPECT_EQ(reflex_count(polygon), r);
  const std::vector<IntPoint> v = integer_points(polygon);
  EXPECT_GT(twice_signed_area(v), 0);
  EXPECT_EQ(collinear_count(v), 0u);
}

TEST(Generators, MillionVertices) {
  expect_large_valid("random", 1'000'000, 250'000);
  expect_large_valid("convex", 1'000'000, 0);
  expect_large_valid("few-notches", 1'000'000, 16);
  expect_large_valid("few-notches", 100'000, 16);
  expect_large_valid("spiral", 1'000'000, 499'998);
  expect_large_valid("comb", 1'000'000, 499'998);
  expect_large_valid("notch-heavy", 1'000'000, 999'997);
  expect_large_valid("x2-pairs", 1'000'000, 2);
  expect_large_valid("x2-pairs", 1'000'000, 333'332);
  expect_large_valid("x4-quads", 1'000'000, 4);
  expect_large_valid("x4-quads", 1'000'000, 333'332);
}


// The random polygons whose r is an outcome (star, space-partition, 2-opt, after Auer and Held): exact
// n, simple, counter-clockwise, no collinear vertices; r what reflex_outcome says, an r asked for
// accepted only when it is that one; every r refused in a grid of (n, r); pinned checksums.
TEST(OutcomeFamilies, AreValidAndSayTheirR) {
  std::size_t made = 0;
  for (const Family& f : families()) {
    if (!f.r_is_outcome) continue;
    EXPECT_FALSE(f.controls_r) << f.name;
    EXPECT_TRUE(f.infeasible(100, 0)) << "a grid of (n, r) leaves " << f.name << " out";
    for (std::size_t n = 3; n <= 60; ++n)
      for (std::uint64_t seed : {1, 2, 3}) {
        const std::size_t r = reflex_outcome(f.name, n, seed);
        expect_valid(f.name, n, r, seed);
        ++made;
      }
    for (std::size_t n : {257, 2000}) expect_valid(f.name, n, reflex_outcome(f.name, n, 9), 9);
    const std::size_t r = reflex_outcome(f.name, 50, 4);
    EXPECT_EQ(generate(f.name, 50, r, 4), generate(f.name, 50, std::nullopt, 4));
    try {
      generate(f.name, 50, r + 1, 4);
      ADD_FAILURE() << f.name << " made an r it does not give";
    } catch (const GeneratorError& e) {
      EXPECT_EQ(std::string(e.what()), "family " + f.name + " does not choose r: at n=50 and seed 4 its method gives r=" +
                                           std::to_string(r) + ", not " + std::to_string(r + 1) + " (feasible " +
                                           f.range() + ")");
    }
    EXPECT_THROW(generate(f.name, 2, std::nullopt, 1), GeneratorError);
    EXPECT_THROW(generate(f.name, f.max_n + 1, std::nullopt, 1), GeneratorError);
    EXPECT_NE(generate(f.name, 40, std::nullopt, 1), generate(f.name, 40, std::nullopt, 2));
  }
  EXPECT_EQ(made, 3u * 58 * 3);
}

TEST(OutcomeFamilies, LargeSizesInSeconds) {
  for (const std::string family : {"star", "space-partition"}) {
    const Polygon p = Polygon::make(generate(family, 100000, std::nullopt, 5));
    EXPECT_EQ(p.size(), 100000u);
    EXPECT_FALSE(p.input_was_clockwise());
  }
  EXPECT_EQ(Polygon::make(generate("2-opt", 10000, std::nullopt, 5)).size(), 10000u);
}

TEST(OutcomeFamilies, ChecksumsArePinned) {
  EXPECT_EQ(fnv1a(generate("star", 1000, std::nullopt, 1)), 0x65773d892b2fb501ULL);
  EXPECT_EQ(fnv1a(generate("space-partition", 1000, std::nullopt, 1)), 0xe790d73cfacd128eULL);
  EXPECT_EQ(fnv1a(generate("2-opt", 500, std::nullopt, 1)), 0x159883b530287fceULL);
}

// Collinear vertices on request: exactly n vertices, k of them at 180 degrees, r unchanged, simple and
// counter-clockwise, the family's own polygon of n - k vertices underneath; k = 0 is generate().
TEST(CollinearVertices, AreExactlyTheOnesAskedFor) {
  for (const Family& f : families())
    for (const std::size_t k : {1, 8, 20}) {
      SCOPED_TRACE(f.name + " k=" + std::to_string(k));
      const std::vector<Point> base = generate(f.name, 40, std::nullopt, 3);
      const std::vector<Point> polygon = generate_with_collinear(f.name, 40 + k, std::nullopt, k, 3);
      ASSERT_EQ(polygon.size(), 40 + k);
      const std::vector<IntPoint> v = integer_points(polygon);
      EXPECT_EQ(collinear_count(v), k);
      EXPECT_EQ(reflex_count(polygon), reflex_count(base));
      EXPECT_GT(twice_signed_area(v), 0);
      EXPECT_EQ(simplicity_problem(v), "");
      EXPECT_NO_THROW(Polygon::make(polygon));
      EXPECT_EQ(polygon, generate_with_collinear(f.name, 40 + k, std::nullopt, k, 3));
    }
  EXPECT_EQ(generate_with_collinear("comb", 30, 9, 0, 2), generate("comb", 30, 9, 2));
  EXPECT_THROW(generate_with_collinear("comb", 30, 4, 16, 2), GeneratorError);
  EXPECT_THROW(generate_with_collinear("star", 30, 0, 5, 2), GeneratorError);
  EXPECT_THROW(generate_with_collinear("convex-holes", 30, std::nullopt, 5, 2), std::invalid_argument);
  EXPECT_EQ(fnv1a(generate_with_collinear("star", 1000, std::nullopt, 300, 1)), 0x0e6a2644f275a1e5ULL);
  EXPECT_EQ(fnv1a(generate_with_collinear("random", 1000, 200, 100, 1)), 0x45039715b4be2a1eULL);
}

// The families with holes: exactly n vertices in all, r reflex vertices and h holes, through the
// checked door (every ring simple, the holes inside and apart), the same bytes for the same arguments,
// their feasible ranges as documented, and 2 * 10^6 vertices within 2^31.
std::uint64_t fnv1a(const Rings& rings) {
  std::vector<Point> all;
  for (const Ring& ring : rings) all.insert(all.end(), ring.begin(), ring.end());
  return fnv1a(all);
}

TEST(HoleFamilies, MakeExactlyNRAndHThroughTheCheckedDoor) {
  ASSERT_EQ(hole_families().size(), 2u);
  EXPECT_EQ(hole_families()[0].name, "comb-holes");
  EXPECT_EQ(hole_families()[1].name, "convex-holes");
  std::size_t made = 0;
  for (const HoleFamily& f : hole_families())
    for (const std::size_t n : {6, 7, 8, 9, 24, 25, 100, 1001})
      for (const std::size_t h : {0, 1, 2, 5, 16})
        for (const std::size_t r : {f.default_reflex(n, h), n / 2, n - 5, n - 4}) {
          if (f.infeasible(n, r, h)) continue;
          const Polygon p = Polygon::make_with_holes(generate_with_holes(f.name, n, r, h, 3));
          const std::string label = f.name + " n=" + std::to_string(n) + " r=" + std::to_string(r) + " h=" + std::to_string(h);
          EXPECT_EQ(p.size(), n) << label;
          EXPECT_EQ(p.hole_count(), h) << label;
          EXPECT_EQ(p.reflex_count(), r) << label;
          EXPECT_FALSE(p.input_was_clockwise()) << label;
          for (std::size_t k = 1; k <= h; ++k) EXPECT_FALSE(p.ring_was_reversed(k)) << "holes are written clockwise";
          ++made;
        }
  EXPECT_GT(made, 60u);
  const Polygon p = Polygon::make_with_holes(generate_with_holes("convex-holes", 40, 12, 2, 1));
  EXPECT_EQ(p.reflex_count(), 12u);
}

TEST(HoleFamilies, RangesAndDefaults) {
  const HoleFamily& f = *find_hole_family("convex-holes");
  EXPECT_FALSE(f.infeasible(3, 0, 0));
  EXPECT_TRUE(f.infeasible(10, 1, 0));
  EXPECT_FALSE(f.infeasible(6, 3, 1));
  EXPECT_TRUE(f.infeasible(5, 3, 1));    // r <= n/2
  EXPECT_TRUE(f.infeasible(100, 8, 3));  // r >= 3h
  EXPECT_EQ(f.default_holes, 4u);
  EXPECT_EQ(f.default_reflex(100, 4), 50u);
  EXPECT_EQ(f.default_reflex(24, 8), 24u);
  EXPECT_THROW(generate_with_holes("convex-holes", 100, 8, 3, 1), GeneratorError);
  EXPECT_THROW(generate_with_holes("convex", 100, 0, 2, 1), GeneratorError);
  EXPECT_EQ(generate_with_holes("convex", 100, 0, 0, 1), Rings{generate("convex", 100, 0, 1)});
  EXPECT_THROW(generate("convex-holes", 100, 50, 1), std::invalid_argument);
  EXPECT_EQ(generate_with_holes("convex-holes", 500, 100, 7, 9), generate_with_holes("convex-holes", 500, 100, 7, 9));
  EXPECT_NE(generate_with_holes("convex-holes", 500, 100, 7, 9), generate_with_holes("convex-holes", 500, 100, 7, 10));
}

TEST(HoleFamilies, CombHolesRangesAndDefaults) {
  const HoleFamily& f = *find_hole_family("comb-holes");
  EXPECT_TRUE(f.infeasible(20, 10, 0));   // at least one hole
  EXPECT_FALSE(f.infeasible(7, 3, 1));    // a rectangle and a triangle
  EXPECT_TRUE(f.infeasible(7, 4, 1));     // r <= n - 4
  EXPECT_FALSE(f.infeasible(8, 3, 1));    // the rectangle's corner cut
  EXPECT_TRUE(f.infeasible(100, 50, 2));  // k = 4 + 0 < 6
  EXPECT_FALSE(f.infeasible(100, 51, 1)); // k = 6 + 1 >= 3
  EXPECT_EQ(f.default_holes, 4u);
  EXPECT_EQ(f.default_reflex(100, 4), 73u);  // k = 50
  EXPECT_EQ(f.default_reflex(10000, 1024), 7498u);
  EXPECT_EQ(generate_with_holes("comb-holes", 500, 300, 7, 9), generate_with_holes("comb-holes", 500, 300, 7, 9));
  EXPECT_NE(generate_with_holes("comb-holes", 500, 300, 7, 9), generate_with_holes("comb-holes", 500, 300, 7, 10));
}

TEST(HoleFamilies, HugeRAndHAreRefusedNotWrapped) {
  const std::size_t huge = std::numeric_limits<std::size_t>::max() - 2;
  for (const std::string family : {"comb-holes", "convex-holes"}) {
    EXPECT_THROW(generate_with_holes(family, 100, huge, 1, 1), GeneratorError) << family;
    EXPECT_THROW(generate_with_holes(family, 100, std::nullopt, huge / 3 + 1, 1), GeneratorError) << family;
    EXPECT_THROW(generate_with_holes(family, 100, 60, huge / 3 + 1, 1), GeneratorError) << family;
  }
}

TEST(HoleFamilies, ChecksumsArePinned) {
  EXPECT_EQ(fnv1a(generate_with_holes("convex-holes", 1000, 500, 4, 1)), 0x1ac3af713f9fd3c7ULL);
  EXPECT_EQ(fnv1a(generate_with_holes("convex-holes", 300, 90, 30, 2)), 0x8efec3661af85110ULL);
  EXPECT_EQ(fnv1a(generate_with_holes("comb-holes", 1000, 748, 4, 1)), 0x70a0eeecf6f7438fULL);
  EXPECT_EQ(fnv1a(generate_with_holes("comb-holes", 301, 200, 30, 2)), 0xe525fbe8888e6552ULL);
}

TEST(HoleFamilies, TwoMillionVertices) {
  for (const HoleFamily& f : hole_families())
    for (const std::size_t h : {1, 1000}) {
      const Rings rings = generate_with_holes(f.name, 2'000'000, f.default_reflex(2'000'000, h), h, 5);
      ASSERT_EQ(rings.size(), h + 1);
      std::size_t n = 0;
      for (const Ring& ring : rings) n += ring.size();
      EXPECT_EQ(n, 2'000'000u);
    }
  const Rings one_hole = generate_with_holes("comb-holes", 2'000'000, 1'999'996, 1, 5);  // k = 1,999,996
  EXPECT_EQ(one_hole[1].size(), 1'999'996u);
}

}  // namespace
}  // namespace pd
