// Segments against the convex chains of a polygon's boundary (engines/search/boundary_chains.h), against
// testing every edge: on every generator family, for segments between vertices (along edges and
// through collinear vertices on the axis-parallel families), points on edges and points in the
// bounding box, with and without the edges at a vertex left out.
#include "engines/search/boundary_chains.h"
#include "generators/family.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace pd {
namespace {

using ExactSegment = ExactKernel::Segment_2;

bool meets_by_every_edge(const Polygon& p, const std::vector<QPoint>& x, const QPoint& s, const QPoint& t, VertexId skip) {
  const ExactSegment st(s, t);
  for (std::size_t e = 0; e < p.size(); ++e) {
    const std::size_t e1 = p.next(e);
    if (e == skip || e1 == skip) continue;
    if (CGAL::do_intersect(st, ExactSegment(x[e], x[e1]))) return true;
  }
  return false;
}

QPoint along(const QPoint& a, const QPoint& b, const Rational& f) {
  return QPoint(a.x() + f * (b.x() - a.x()), a.y() + f * (b.y() - a.y()));
}

// Endpoints that meet the boundary in every way: vertices, points on edges, points spread over the
// bounding box.
std::vector<QPoint> endpoints(const Polygon& p, const std::vector<QPoint>& x, std::mt19937_64& rng) {
  std::vector<QPoint> out(x);
  for (std::size_t e = 0; e < p.size(); ++e) out.push_back(along(x[e], x[p.next(e)], Rational(1, 2 + e % 3)));
  Rational lo_x = x[0].x(), hi_x = lo_x, lo_y = x[0].y(), hi_y = lo_y;
  for (const QPoint& q : x)
    lo_x = std::min(lo_x, q.x()), hi_x = std::max(hi_x, q.x()), lo_y = std::min(lo_y, q.y()), hi_y = std::max(hi_y, q.y());
  std::uniform_int_distribution<int> step(0, 64);
  const auto fraction = [&] {
    Rational f(step(rng), 64);
    f.canonicalize();  // GMP's arithmetic expects its operands in lowest terms
    return f;
  };
  for (std::size_t k = 0; k < p.size(); ++k)
    out.emplace_back(lo_x + (hi_x - lo_x) * fraction(), lo_y + (hi_y - lo_y) * fraction());
  return out;
}

// A polygon of each family at n = 40 and at 160 (where the family can make it), with its vertices as
// rationals.
struct Case {
  std::string label;
  Polygon p;
  std::vector<QPoint> x;
};

std::vector<Case> cases(std::uint64_t seed) {
  std::vector<Case> out;
  for (const Family& family : families())
    for (std::size_t n : {40, 160}) {
      std::vector<Point> ring;
      try {
        ring = generate(family.name, n, std::nullopt, seed);
      } catch (const GeneratorError&) {
        continue;
      }
      Case c{family.name + " n=" + std::to_string(n), Polygon::make(ring), {}};
      for (const Point& v : c.p.vertices()) c.x.push_back(to_exact(v));
      out.push_back(std::move(c));
    }
  return out;
}

TEST(BoundaryChains, SegmentSearchAgreesWithEveryEdge) {
  std::mt19937_64 rng(7);
  int meeting = 0, missing = 0;
  const std::vector<Case> all = cases(3);
  for (const auto& [label, p, x] : all) {
    boundary::SegmentSearch search(p, x);
    const std::vector<QPoint> ends = endpoints(p, x, rng);
    std::uniform_int_distribution<std::size_t> pick(0, ends.size() - 1), vertex(0, p.size() - 1);
    for (int k = 0; k < 3000; ++k) {
      const bool from_vertex = k % 2 == 0;
      const VertexId skip = from_vertex ? static_cast<VertexId>(vertex(rng)) : boundary::SegmentSearch::kNoVertex;
      const QPoint s = from_vertex ? x[skip] : ends[pick(rng)], t = ends[pick(rng)];
      if (s == t) continue;
      const bool expected = meets_by_every_edge(p, x, s, t, skip);
      ASSERT_EQ(search.meets_boundary(s, t, skip), expected) << label << " s=" << s << " t=" << t << " skip=" << skip;
      (expected ? meeting : missing) += 1;
    }
  }
  EXPECT_GE(all.size(), 10u);
  EXPECT_GT(meeting, 1000);
  EXPECT_GT(missing, 1000);
}

}  // namespace
}  // namespace pd
