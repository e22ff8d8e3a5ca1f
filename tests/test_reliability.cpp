// Reliability (issue 9): the inputs the fuzzers found, replayed; and exactness at the edges of the
// input range, where floating-point shortcuts fail first: coordinates up to 2^31 in magnitude, vertices
// one unit off a line at 2^30, slivers a few units wide and 2^31 long. Every registered algorithm within
// the test budget must give a valid result on each; the CGAL peers' failures are recorded as test
// properties (`ctest --output-junit` or --gtest_output=xml shows them), not required.
#include "generators/family.h"
#include "tests/reliability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pd {
namespace {


constexpr double k2to30 = 1073741824.0, k2to31 = 2147483648.0;

// Runs every algorithm within the budget on p: ours must be valid, the peers' failures are recorded.
void expect_every_algorithm_valid(const Polygon& p, const std::string& label) {
  const auto verdicts = reliability::run_every_algorithm(p, reliability::kTestWork);
  EXPECT_FALSE(verdicts.empty()) << label;
  for (const auto& v : verdicts) {
    if (is_peer(*v.algorithm)) {
      if (!v.ok) ::testing::Test::RecordProperty(v.algorithm->name + " on " + label, v.reason);
      continue;
    }
    EXPECT_TRUE(v.ok) << v.algorithm->name << " on " << label << ": " << v.reason;
  }
}

// Every input the fuzz targets saved (data/fuzz-regressions; docs/reliability.md), through the same
// checks the fuzz targets make.
TEST(FuzzRegressions, EverySavedInputPassesTheFuzzChecks) {
  const std::filesystem::path dir = PD_SOURCE_DIR "/data/fuzz-regressions";
  std::size_t replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename() == "README.md") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string name = entry.path().filename().string();
    std::optional<std::vector<Polygon>> parts;
    ASSERT_NO_THROW(parts = reliability::read_checked(text.str())) << name;
    ++replayed;
    for (const Polygon& p : parts.value_or(std::vector<Polygon>{})) {
      if (p.size() > reliability::kFuzzMaxVertices) continue;
      const auto finding = reliability::first_finding(reliability::run_every_algorithm(p, reliability::kFuzzWork));
      EXPECT_FALSE(finding) << name << ": " << finding.value_or("");
    }
  }
  EXPECT_GT(replayed, 0u);
}

// m + 1 points from `from` in steps of `step`, the odd ones moved by `bump` across the line.
std::vector<Point> bumped_line(Point from, double step_x, double step_y, std::size_t m, double bump) {
  std::vector<Point> chain;
  for (std::size_t i = 0; i <= m; ++i)
    chain.emplace_back(from.x() + static_cast<double>(i) * step_x, from.y() + static_cast<double>(i) * step_y + (i % 2 ? bump : 0));
  return chain;
}

// An integer step: the chains' unmoved points lie exactly on their line.
double step(double length, std::size_t m) { return std::floor(length / static_cast<double>(m)); }

// A chain of m + 1 vertices on a sloped line through (-2^30, -2^30), every other one one unit off it,
// and an apex far above: the chain's vertices alternate between reflex and convex with angles one
// unit from 180 degrees at 2^30.
Polygon near_collinear_fan(std::size_t m, double bump) {
  std::vector<Point> ring = bumped_line({-k2to30, -k2to30}, step(k2to31, m) + 7, step(k2to30, m) + 3, m, bump);
  ring.emplace_back(0, k2to31 - 1);
  return Polygon::make(ring);
}

// Two such chains `gap` units apart, joined at their ends: a sliver 2^31 long and a few units wide.
Polygon near_collinear_sliver(std::size_t m, double gap) {
  const double sx = step(k2to31, m) + 7, sy = step(k2to30, m) + 3;
  std::vector<Point> ring = bumped_line({-k2to30, -k2to30}, sx, sy, m, 1);
  std::vector<Point> top = bumped_line({-k2to30, -k2to30 + gap}, sx, sy, m, -1);
  ring.insert(ring.end(), top.rbegin(), top.rend());
  return Polygon::make(ring);
}

// A square with corners at (+-2^31, +-2^31) and m notches from its top edge reaching down to one unit
// above its bottom edge.
Polygon notched_square(std::size_t m) {
  std::vector<Point> ring = {{-k2to31, -k2to31}, {k2to31, -k2to31}, {k2to31, k2to31}};
  const double width = 2 * k2to31 / static_cast<double>(2 * m + 1);
  for (std::size_t k = 1; k <= 2 * m; ++k) {
    const double x = k2to31 - static_cast<double>(k) * width;
    ring.emplace_back(x, k % 2 ? -k2to31 + 1 : k2to31);
  }
  ring.emplace_back(-k2to31, k2to31);
  return Polygon::make(ring);
}

// `ring` moved so that its largest x and y are 2^31 - 1 (or its smallest -2^31): small shapes far from
// the origin, where differences of coordinates cancel.
Polygon translated_to_corner(const std::vector<Point>& ring, bool positive) {
  double min_x = ring[0].x(), max_x = min_x, min_y = ring[0].y(), max_y = min_y;
  for (const Point& q : ring) {
    min_x = std::min(min_x, q.x()), max_x = std::max(max_x, q.x());
    min_y = std::min(min_y, q.y()), max_y = std::max(max_y, q.y());
  }
  const double dx = positive ? k2to31 - 1 - max_x : -k2to31 - min_x;
  const double dy = positive ? k2to31 - 1 - max_y : -k2to31 - min_y;
  std::vector<Point> moved;
  for (const Point& q : ring) moved.emplace_back(q.x() + dx, q.y() + dy);
  return Polygon::make(moved);
}

TEST(ExtremeCoordinates, NearCollinearChainsAt2To30) {
  for (std::size_t m : {6, 9, 16, 40})
    for (double bump : {1.0, -1.0}) {
      const Polygon p = near_collinear_fan(m, bump);
      ASSERT_EQ(p.reflex_count(), bump > 0 ? m / 2 : (m - 1) / 2) << "the bumps are the notches";
      expect_every_algorithm_valid(p, "fan m=" + std::to_string(m) + " bump=" + std::to_string(static_cast<int>(bump)));
    }
}

TEST(ExtremeCoordinates, SliversAFewUnitsWide) {
  for (std::size_t m : {5, 8, 15})
    for (double gap : {3.0, 4.0}) {
      const Polygon p = near_collinear_sliver(m, gap);
      EXPECT_GT(p.reflex_count(), 0u);
      expect_every_algorithm_valid(p, "sliver m=" + std::to_string(m) + " gap=" + std::to_string(static_cast<int>(gap)));
    }
}

TEST(ExtremeCoordinates, NotchedSquareWithCornersAt2To31) {
  for (std::size_t m : {1, 3, 8}) {
    const Polygon p = notched_square(m);
    ASSERT_EQ(p.reflex_count(), m);
    expect_every_algorithm_valid(p, "notched square m=" + std::to_string(m));
  }
}

TEST(ExtremeCoordinates, EveryFamilyMovedToTheCorners) {
  for (const Family& f : families())
    for (std::size_t n : {12, 40}) {
      if (f.infeasible(n, f.default_reflex(n))) continue;
      const std::vector<Point> ring = generate(f.name, n, std::nullopt, 1);
      for (bool positive : {true, false})
        expect_every_algorithm_valid(translated_to_corner(ring, positive),
                                     f.name + " n=" + std::to_string(n) + (positive ? " at +2^31" : " at -2^31"));
    }
}

}  // namespace
}  // namespace pd
