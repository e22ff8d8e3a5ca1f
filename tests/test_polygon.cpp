// The checked constructor: what it rejects, what it accepts, and how it normalises.
#include "core/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

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

// The quadratic definition, in integers (independent of the predicates under test): distinct
// vertices, edges that share a vertex meet only there, other edges not at all.
long long cross(const Point& o, const Point& a, const Point& b) {
  const auto x = [](double v) { return static_cast<long long>(v); };
  return (x(a.x()) - x(o.x())) * (x(b.y()) - x(o.y())) - (x(a.y()) - x(o.y())) * (x(b.x()) - x(o.x()));
}
int sign(long long v) { return (v > 0) - (v < 0); }
bool between(const Point& a, const Point& b, const Point& p) {  // p on the closed segment ab, given collinear
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}
bool on_segment(const Point& a, const Point& b, const Point& p) { return cross(a, b, p) == 0 && between(a, b, p); }
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (sign(cross(a, b, c)) * sign(cross(a, b, d)) < 0 && sign(cross(c, d, a)) * sign(cross(c, d, b)) < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

bool simple_by_brute_force(const std::vector<Point>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (v[i] == v[j]) return false;
      const Point &a = v[i], &b = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
      if (j == i + 1) {
        if (on_segment(a, b, d) || on_segment(c, d, a)) return false;
      } else if (i == 0 && j == n - 1) {
        if (on_segment(a, b, c) || on_segment(c, d, b)) return false;
      } else if (segments_meet(a, b, c, d)) {
        return false;
      }
    }
  return true;
}

std::vector<QPoint> exact(const std::vector<Point>& v) {
  std::vector<QPoint> out;
  for (const Point& p : v) out.push_back(to_exact(p));
  return out;
}

// The sweep (core/sweep.h) on random cycles of a small lattice, where collinear edges, vertices on
// edges and coincident vertices are everywhere, for input and exact points alike.
TEST(Polygon, SimplicitySweepAgreesWithTheBruteForce) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coordinate(0, 4), size(3, 9);
  std::size_t simple = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    std::vector<Point> v(static_cast<std::size_t>(size(rng)));
    for (Point& p : v) p = Point(coordinate(rng), coordinate(rng));
    const bool expected = simple_by_brute_force(v);
    simple += expected;
    ASSERT_EQ(is_simple_cycle(v, nullptr), expected) << "trial " << trial;
    ASSERT_EQ(is_simple_cycle(exact(v), nullptr), expected) << "trial " << trial;
  }
  EXPECT_GT(simple, 2000u);
}

// orient's inline filter (core/geometry.h) against CGAL's exact predicate where the filter must give
// up or decide close to its bound: points a few units in the last place off a line, at magnitudes from
// the subnormals to 1e300, and exactly collinear points.
TEST(Geometry, OrientAgreesWithTheExactPredicateNearDegeneracy) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> ulps(-3, 3);
  std::size_t zero = 0;
  for (const double scale : {1e-310, 1e-300, 1e-150, 1e-8, 1.0, 3.0, 1e8, 1e150, 1e300}) {
    for (int trial = 0; trial < 3000; ++trial) {
      const Point p(unit(rng) * scale, unit(rng) * scale), q(unit(rng) * scale, unit(rng) * scale);
      const double t = unit(rng);
      double x = p.x() + t * (q.x() - p.x()), y = p.y() + t * (q.y() - p.y());
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) y = std::nextafter(y, k > 0 ? HUGE_VAL : -HUGE_VAL);
      const Point r(x, y);
      const int exact = static_cast<int>(CGAL::orientation(p, q, r));
      zero += exact == 0;
      ASSERT_EQ(orient(p, q, r), exact) << "scale " << scale << " trial " << trial;
      ASSERT_EQ(orient(q, r, p), exact);
      ASSERT_EQ(orient(r, q, p), -exact);
    }
  }
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (const double scale : {0x1p-1060, 0x1p-500, 1.0, 0x1p500, 0x1p1000}) {  // exactly collinear
    for (int trial = 0; trial < 1000; ++trial) {
      const int i = small(rng), j = small(rng), k = small(rng), l = small(rng);
      const Point p(i * scale, j * scale), q(k * scale, l * scale), r((2 * k - i) * scale, (2 * l - j) * scale);
      ASSERT_EQ(static_cast<int>(CGAL::orientation(p, q, r)), 0);
      ASSERT_EQ(orient(p, q, r), 0) << "scale " << scale;
      ++zero;
    }
  }
  EXPECT_GE(zero, 5000u);
  const Point a(0, 0), b(1e300, 1e300), c(-1e300, -1e300), far(1.7e308, -1.7e308);
  EXPECT_EQ(orient(a, b, c), 0);
  EXPECT_EQ(orient(c, b, far), static_cast<int>(CGAL::orientation(c, b, far)));
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
