// An exact tiling check that shares no code with core/validate: used to show that the validator's
// verdict (and so `run --json`'s "valid") agrees with a second, differently built judgement.
//
// For convex pieces it is complete: each piece convex and counter-clockwise (every vertex left of or on
// every edge line), pairwise separated by an edge line, inside the polygon (no polygon vertex strictly
// inside a piece, no piece edge properly crossing a polygon edge, an interior point inside the
// polygon), and the areas add up. For other pieces (y-monotone) it checks simplicity by brute force,
// the areas, and that sample points strictly inside the polygon lie strictly inside exactly one piece.
// Quadratic and worse: for small polygons only.
#pragma once

#include "core/geometry.h"

#include <vector>

namespace pd::independent {

using Cycle = std::vector<QPoint>;

inline int sgn(const Rational& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

inline int turn(const QPoint& a, const QPoint& b, const QPoint& c) {
  return sgn((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

inline Rational area2(const Cycle& c) {
  Rational s = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    s += c[i].x() * c[(i + 1) % c.size()].y() - c[(i + 1) % c.size()].x() * c[i].y();
  return s;
}

inline bool convex_ccw(const Cycle& c) {
  if (area2(c) <= 0) return false;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (const QPoint& q : c)
      if (turn(c[i], c[(i + 1) % c.size()], q) < 0) return false;
  return true;
}

// Some edge line of a or b has all of the other on its outer side (or on it).
inline bool separated(const Cycle& a, const Cycle& b) {
  for (const Cycle* s : {&a, &b}) {
    const Cycle& t = s == &a ? b : a;
    for (std::size_t i = 0; i < s->size(); ++i) {
      bool all_out = true;
      for (const QPoint& q : t) all_out = all_out && turn((*s)[i], (*s)[(i + 1) % s->size()], q) <= 0;
      if (all_out) return true;
    }
  }
  return false;
}

inline bool proper_cross(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  return turn(a, b, c) * turn(a, b, d) < 0 && turn(c, d, a) * turn(c, d, b) < 0;
}

inline bool on_segment(const QPoint& a, const QPoint& b, const QPoint& q) {
  return turn(a, b, q) == 0 && (a.x() - q.x()) * (b.x() - q.x()) <= 0 && (a.y() - q.y()) * (b.y() - q.y()) <= 0;
}

// +1 strictly inside, 0 on the boundary, -1 outside (crossing number, exact).
inline int locate(const Cycle& c, const QPoint& q) {
  bool inside = false;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const QPoint &a = c[i], &b = c[(i + 1) % c.size()];
    if (on_segment(a, b, q)) return 0;
    if ((a.y() > q.y()) != (b.y() > q.y())) {
      const int t = turn(a, b, q);
      if ((b.y() > a.y() && t > 0) || (b.y() < a.y() && t < 0)) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

inline bool simple_brute(const Cycle& c) {
  const std::size_t m = c.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      if (c[i] == c[j]) return false;
      const bool adjacent = j == i + 1 || (i == 0 && j == m - 1);
      if (!adjacent && (proper_cross(c[i], c[(i + 1) % m], c[j], c[(j + 1) % m]) ||
                        on_segment(c[i], c[(i + 1) % m], c[j]) || on_segment(c[j], c[(j + 1) % m], c[i])))
        return false;
    }
  return area2(c) > 0;
}

inline QPoint centroid(const Cycle& c) {
  Rational x = 0, y = 0;
  for (const QPoint& q : c) x += q.x(), y += q.y();
  return QPoint(x / Rational(c.size()), y / Rational(c.size()));
}

inline bool samples_covered_once(const Cycle& polygon, const std::vector<Cycle>& pieces) {
  Rational x0 = polygon[0].x(), x1 = x0, y0 = polygon[0].y(), y1 = y0;
  for (const QPoint& q : polygon) x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x()), y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
  const int steps = 23;
  for (int i = 1; i < steps; ++i)
    for (int j = 1; j < steps; ++j) {
      const QPoint q(x0 + (x1 - x0) * Rational(2 * i + 1, 2 * steps + 3), y0 + (y1 - y0) * Rational(2 * j + 1, 2 * steps + 5));
      const int where = locate(polygon, q);
      if (where == 0) continue;
      int strictly = 0, touching = 0;
      for (const Cycle& piece : pieces) {
        const int w = locate(piece, q);
        strictly += w == 1, touching += w == 0;
      }
      if (touching) continue;
      if (strictly != (where == 1 ? 1 : 0)) return false;
    }
  return true;
}

inline bool tiles(const Cycle& polygon, const std::vector<Cycle>& pieces, bool convex) {
  Rational total = 0;
  for (const Cycle& piece : pieces) {
    if (piece.size() < 3) return false;
    if (convex ? !convex_ccw(piece) : !simple_brute(piece)) return false;
    total += area2(piece);
  }
  if (total != area2(polygon)) return false;
  if (!samples_covered_once(polygon, pieces)) return false;
  if (!convex) return true;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      if (!separated(pieces[i], pieces[j])) return false;
    if (locate(polygon, centroid(pieces[i])) != 1) return false;
    for (const QPoint& v : polygon)
      if (locate(pieces[i], v) == 1) return false;
    for (std::size_t a = 0; a < pieces[i].size(); ++a)
      for (std::size_t b = 0; b < polygon.size(); ++b)
        if (proper_cross(pieces[i][a], pieces[i][(a + 1) % pieces[i].size()], polygon[b], polygon[(b + 1) % polygon.size()]))
          return false;
  }
  return true;
}

}  // namespace pd::independent
