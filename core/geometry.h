// Exact geometry for polydecomp.
//
// Input vertices are doubles and every predicate on them is exact (CGAL's filtered
// Exact_predicates_inexact_constructions_kernel). Points an algorithm constructs (Steiner points,
// ray hits) are exact rationals (CGAL::Exact_rational, GMP's mpq), never rounded.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <string>

namespace pd {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

using Rational = CGAL::Exact_rational;
using ExactKernel = CGAL::Simple_cartesian<Rational>;
using QPoint = ExactKernel::Point_2;

inline QPoint to_exact(const Point& p) { return QPoint(Rational(p.x()), Rational(p.y())); }

// Sign of the turn p -> q -> r: +1 left (counter-clockwise), -1 right, 0 collinear. Exact.
inline int orient(const Point& p, const Point& q, const Point& r) {
  return static_cast<int>(CGAL::orientation(p, q, r));
}
inline int orient(const QPoint& p, const QPoint& q, const QPoint& r) {
  return static_cast<int>(CGAL::orientation(p, q, r));
}

// Exact decimal or "p/q" text of a rational; a double-representable value prints as a JSON number
// that round-trips exactly.
std::string rational_text(const Rational& v);
// True when v is exactly a double (then JSON may carry it as a number).
bool is_double(const Rational& v);
// Shortest decimal text that parses back to exactly d.
std::string double_text(double d);

}  // namespace pd
