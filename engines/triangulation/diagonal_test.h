// The diagonal test of the slides (Rosen, "Polygon Partitioning", 003, "Diagonal-based
// triangulation"), shared by `diagonal-n4` and `diagonal-n3`, and the order in which both pick
// diagonals. Exact: orient() and coordinate comparisons only.
//
// Segment v_i v_j is a diagonal iff it is internal to P in the neighbourhoods of v_i and v_j (strictly
// inside the interior angle at each end) and meets no edge of P that is not incident to v_i or v_j.
// "Meets" is closed: touching counts, so a vertex in the segment's interior (a collinear vertex, say)
// makes it no diagonal; such a vertex has an edge not incident to v_i or v_j, or else it is a
// neighbour of v_i (or v_j) straight ahead, which the angle test refuses.
#pragma once

#include "core/decomposition.h"

#include <algorithm>
#include <cstdint>

namespace pd::diagonal_test {

// The direction from vertex i towards q lies strictly inside the interior angle at i.
inline bool in_cone(const Polygon& p, std::size_t i, const Point& q) {
  const Point &a = p[p.prev(i)], &b = p[i], &c = p[p.next(i)];
  if (orient(a, b, c) >= 0) return orient(a, b, q) > 0 && orient(b, c, q) > 0;
  return orient(a, b, q) > 0 || orient(b, c, q) > 0;
}

// q, collinear with a and b, lies on the closed segment ab.
inline bool within(const Point& a, const Point& b, const Point& q) {
  return std::min(a.x(), b.x()) <= q.x() && q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
         q.y() <= std::max(a.y(), b.y());
}

// The closed segments ab and cd have a point in common. Most pairs are told apart by the first two
// tests (c and d strictly on one side of line ab).
inline bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int abc = orient(a, b, c), abd = orient(a, b, d);
  if (abc * abd > 0) return false;
  const int cda = orient(c, d, a), cdb = orient(c, d, b);
  if (cda * cdb > 0) return false;
  if (abc * abd < 0 && cda * cdb < 0) return true;
  return (abc == 0 && within(a, b, c)) || (abd == 0 && within(a, b, d)) || (cda == 0 && within(c, d, a)) ||
         (cdb == 0 && within(c, d, b));
}

// Whether v_i v_j (non-adjacent) is a diagonal of p; counts the edges it is tested against. The test
// is carried out in full, every edge and both neighbourhoods, as the slides count it (Theta(n) per
// candidate). Stopping at the first crossing edge would tie the cost to how many candidates are
// diagonals, which at a fixed number of notches grows from about n to about n^2/2 with n, so that at
// the sizes these programs can run at they would seem to grow faster than their bounds.
inline bool is_diagonal(const Polygon& p, std::size_t i, std::size_t j, std::int64_t& edge_tests) {
  bool meets_an_edge = false;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t l = p.next(k);
    if (k == i || k == j || l == i || l == j) continue;
    ++edge_tests;
    meets_an_edge |= segments_meet(p[i], p[j], p[k], p[l]);
  }
  return !meets_an_edge && in_cone(p, i, p[j]) && in_cone(p, j, p[i]);
}

// Two distinct diagonals cross unless they share an endpoint (then they cannot overlap: neither has
// a vertex in its interior).
inline bool cross(const Polygon& p, const Cut& s, const Cut& t) {
  if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) return false;
  return segments_meet(p[s.a], p[s.b], p[t.a], p[t.b]);
}

// The order in which both algorithms pick diagonals: shorter first (an exact comparison of squared
// lengths), then by endpoints. Picking the first compatible one each time gives the greedy
// triangulation, the same for both.
inline bool picked_before(const Polygon& p, const Cut& s, const Cut& t) {
  const CGAL::Comparison_result c = Kernel().compare_distance_2_object()(p[s.a], p[s.b], p[t.a], p[t.b]);
  if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
  return std::pair(s.a, s.b) < std::pair(t.a, t.b);
}

}  // namespace pd::diagonal_test
