// Filtered exact predicates for points an algorithm constructs (exact rationals, core/geometry.h):
// interval arithmetic first, the rationals only when the intervals leave the sign open. Used by
// naive (its Steiner points), the boundary chains' segment search and the geodesics (points on loose
// rays).
#pragma once

#include "core/geometry.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <optional>
#include <utility>

namespace pd {

// Unprotected intervals: each filtered predicate sets the rounding mode once, for all its operations.
using Interval = CGAL::Interval_nt<false>;

struct Box {
  Interval x, y;
};

// The sign of v when v settles it.
inline std::optional<int> certain_sign(const Interval& v) {
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  if (v.inf() == 0 && v.sup() == 0) return 0;
  return std::nullopt;
}

// The orientation of three points in boxes, when the intervals settle it.
inline std::optional<int> interval_orient(const Box& a, const Box& b, const Box& c) {
  CGAL::Protect_FPU_rounding<true> upwards;
  return certain_sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// An exact point with an interval box around it, and whether both its coordinates are doubles (as the
// polygon's vertices are).
struct FilteredPoint {
  explicit FilteredPoint(QPoint p)
      : exact(std::move(p)), box{Interval(CGAL::to_interval(exact.x())), Interval(CGAL::to_interval(exact.y()))},
        in_doubles(box.x.is_point() && box.y.is_point()) {}
  QPoint exact;
  Box box;
  bool in_doubles;
};

// orient() on the doubles when all three points are in doubles (CGAL's filtered predicate), else on the
// intervals when they settle the sign, else on the rationals.
inline int orient(const FilteredPoint& a, const FilteredPoint& b, const FilteredPoint& c) {
  if (a.in_doubles && b.in_doubles && c.in_doubles)
    return orient(Point(a.box.x.inf(), a.box.y.inf()), Point(b.box.x.inf(), b.box.y.inf()),
                  Point(c.box.x.inf(), c.box.y.inf()));
  if (const std::optional<int> sign = interval_orient(a.box, b.box, c.box)) return *sign;
  return orient(a.exact, b.exact, c.exact);
}

}  // namespace pd
