// Exact geometry for polydecomp.
//
// Input vertices are doubles and every predicate on them is exact (CGAL's filtered
// Exact_predicates_inexact_constructions_kernel). Points an algorithm constructs (Steiner points,
// ray hits) are exact rationals (CGAL::Exact_rational, GMP's mpq), never rounded.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <string>

namespace pd {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

using Rational = CGAL::Exact_rational;
using ExactKernel = CGAL::Simple_cartesian<Rational>;
using QPoint = ExactKernel::Point_2;

inline QPoint to_exact(const Point& p) { return QPoint(Rational(p.x()), Rational(p.y())); }

// Sign of the turn p -> q -> r: +1 left (counter-clockwise), -1 right, 0 collinear. Exact. For input
// points, inline: the determinant in doubles decides when it exceeds (3 + 16 eps) eps times the sum of
// its two products' magnitudes (Shewchuk 1997, orient2d's first stage, with eps = 2^-53); CGAL's exact
// predicate decides the rest, and whenever a sum so small that products may have underflowed, an
// overflow or a non-finite input leaves the comparison false.
inline int orient(const Point& p, const Point& q, const Point& r) {
  constexpr double kErrorBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
  constexpr double kSmallestSum = 0x1p-900;
  const double left = (p.x() - r.x()) * (q.y() - r.y());
  const double right = (p.y() - r.y()) * (q.x() - r.x());
  const double det = left - right;
  const double sum = std::fabs(left) + std::fabs(right);
  if (sum >= kSmallestSum && std::fabs(det) > kErrorBound * sum) return det > 0 ? 1 : -1;
  return static_cast<int>(CGAL::orientation(p, q, r));
}
inline int orient(const QPoint& p, const QPoint& q, const QPoint& r) {
  return static_cast<int>(CGAL::orientation(p, q, r));
}

// Whether the closed segments ab and cd share a point. Exact, for input points and exact points alike.
template <class P>
bool closed_segments_meet(const P& a, const P& b, const P& c, const P& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d);
  if (o1 * o2 > 0) return false;  // c and d strictly on one side of ab: the common case, decided here
  const int o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o3 * o4 > 0) return false;
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && CGAL::collinear_are_ordered_along_line(a, c, b)) ||
         (o2 == 0 && CGAL::collinear_are_ordered_along_line(a, d, b)) ||
         (o3 == 0 && CGAL::collinear_are_ordered_along_line(c, a, d)) ||
         (o4 == 0 && CGAL::collinear_are_ordered_along_line(c, b, d));
}

// Exact decimal or "p/q" text of a rational; a double-representable value prints as a JSON number
// that round-trips exactly.
std::string rational_text(const Rational& v);
// True when v is exactly a double (then JSON may carry it as a number).
bool is_double(const Rational& v);
// Shortest decimal text that parses back to exactly d.
std::string double_text(double d);

}  // namespace pd
