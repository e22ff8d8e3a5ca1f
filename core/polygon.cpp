#include "core/polygon.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace pd {
namespace {

std::string edge_name(std::size_t i, std::size_t n) {
  return std::to_string(i) + "-" + std::to_string((i + 1) % n);
}

template <class P>
bool on_closed_segment(const P& a, const P& b, const P& p) {
  return orient(a, b, p) == 0 && CGAL::collinear_are_ordered_along_line(a, p, b);
}

template <class P>
bool closed_segments_meet(const P& a, const P& b, const P& c, const P& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_closed_segment(a, b, c) || on_closed_segment(a, b, d) || on_closed_segment(c, d, a) ||
         on_closed_segment(c, d, b);
}

// Adjacent edges (a,b), (b,c) of a simple chain meet only at b: they fail when c folds back onto ab.
template <class P>
bool folds_back(const P& a, const P& b, const P& c) {
  return orient(a, b, c) == 0 && !CGAL::collinear_are_ordered_along_line(a, b, c);
}

template <class P>
std::string duplicate_vertices(const std::vector<P>& cycle) {
  std::vector<std::size_t> order(cycle.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return cycle[i] < cycle[j] || (cycle[i] == cycle[j] && i < j);
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (cycle[order[k - 1]] == cycle[order[k]])
      return "vertices " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) +
             " coincide";
  return {};
}

// Names a pair of edges that meet where they should not. Called only once the polygon is known not to
// be simple; edges are swept by their smallest x so that most pairs are never compared.
template <class P>
std::string crossing_witness(const std::vector<P>& cycle) {
  const std::size_t n = cycle.size();
  for (std::size_t i = 0; i < n; ++i)
    if (folds_back(cycle[i], cycle[(i + 1) % n], cycle[(i + 2) % n]))
      return "edges " + edge_name(i, n) + " and " + edge_name((i + 1) % n, n) + " overlap";
  auto lo = [&](std::size_t e) { return std::min(cycle[e].x(), cycle[(e + 1) % n].x()); };
  auto hi = [&](std::size_t e) { return std::max(cycle[e].x(), cycle[(e + 1) % n].x()); };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  std::vector<std::size_t> active;
  for (std::size_t e : order) {
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t f) { return hi(f) < lo(e); }),
                 active.end());
    for (std::size_t f : active) {
      const bool adjacent = (e + 1) % n == f || (f + 1) % n == e;
      if (adjacent) continue;
      if (closed_segments_meet(cycle[e], cycle[(e + 1) % n], cycle[f], cycle[(f + 1) % n])) {
        const auto [a, b] = std::minmax(e, f);
        return "edge " + edge_name(a, n) + " crosses edge " + edge_name(b, n);
      }
    }
    active.push_back(e);
  }
  return "edges meet";
}

std::size_t lowest_vertex(const std::vector<Point>& v) {
  return static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
}

}  // namespace

Rational twice_signed_area(const std::vector<Point>& cycle) {
  Rational sum = 0;
  for (std::size_t i = 0, n = cycle.size(); i < n; ++i) {
    const Point& a = cycle[i];
    const Point& b = cycle[(i + 1) % n];
    sum += Rational(a.x()) * Rational(b.y()) - Rational(b.x()) * Rational(a.y());
  }
  return sum;
}

template <class P, class K>
bool simple_cycle(const std::vector<P>& cycle, std::string* why) {
  if (std::string dup = duplicate_vertices(cycle); !dup.empty()) {
    if (why) *why = dup;
    return false;
  }
  if (CGAL::is_simple_2(cycle.begin(), cycle.end(), K())) return true;
  if (why) *why = crossing_witness(cycle);
  return false;
}

bool is_simple_cycle(const std::vector<Point>& cycle, std::string* why) {
  return simple_cycle<Point, Kernel>(cycle, why);
}
bool is_simple_cycle(const std::vector<QPoint>& cycle, std::string* why) {
  return simple_cycle<QPoint, ExactKernel>(cycle, why);
}

std::size_t Polygon::reflex_count() const {
  std::size_t r = 0;
  for (std::size_t i = 0; i < v_.size(); ++i) r += is_reflex(i);
  return r;
}

std::size_t Polygon::first_reflex() const {
  for (std::size_t i = 0; i < v_.size(); ++i)
    if (is_reflex(i)) return i;
  return v_.size();
}

Polygon Polygon::make(std::vector<Point> input) {
  for (std::size_t i = 0; i < input.size(); ++i)
    if (!std::isfinite(input[i].x()) || !std::isfinite(input[i].y()))
      throw PolygonError("vertex " + std::to_string(i) + " has a coordinate that is not finite");
  if (input.size() >= 2 && input.front() == input.back()) input.pop_back();
  if (input.size() < 3)
    throw PolygonError(std::to_string(input.size()) + (input.size() == 1 ? " vertex" : " vertices") +
                       "; a polygon needs at least 3");
  std::string why;
  if (!is_simple_cycle(input, &why)) throw PolygonError("not simple: " + why);
  // The lowest-leftmost vertex of a simple polygon is strictly convex, so its turn gives the orientation.
  const std::size_t n = input.size(), m = lowest_vertex(input);
  const bool clockwise = orient(input[(m + n - 1) % n], input[m], input[(m + 1) % n]) < 0;
  if (clockwise) std::reverse(input.begin() + 1, input.end());
  return Polygon(std::move(input), clockwise);
}

}  // namespace pd
