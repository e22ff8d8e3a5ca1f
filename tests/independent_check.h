// An exact tiling check that shares no code with core/validate: used to show that the validator's
// verdict (and so `run --json`'s "valid") agrees with a second, differently built judgement.
//
// The polygon is given by its rings: the outer ring counter-clockwise, the holes clockwise. For convex
// pieces it checks: each piece convex and counter-clockwise (every vertex left of or on every edge
// line), pairwise separated by an edge line, inside the polygon (no ring vertex and no ring edge's
// midpoint strictly inside a piece, no piece edge properly crossing a ring edge, an interior point
// inside the polygon), the areas add up, and sample points strictly inside the polygon lie strictly
// inside exactly one piece. For other pieces (y-monotone) it checks simplicity by brute force, the
// areas and the samples. Quadratic and worse (bounding boxes prune the pairs they decide): for small
// polygons only.
#pragma once

#include "core/geometry.h"
#include "core/polygon.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
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

// The polygon's rings, exact: the outer ring counter-clockwise, the holes clockwise.
inline std::vector<Cycle> rings_of(const Polygon& p) {
  std::vector<Cycle> rings;
  for (const Ring& ring : p.rings()) {
    Cycle c;
    for (const Point& q : ring) c.push_back(to_exact(q));
    rings.push_back(c);
  }
  return rings;
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
    const bool above_a = a.y() > q.y(), above_b = b.y() > q.y();
    // on_segment needs q within the edge's box: the y test first, as most edges fail it
    const bool in_y_range = (a.y() >= q.y() || b.y() >= q.y()) && (a.y() <= q.y() || b.y() <= q.y());
    if (in_y_range && on_segment(a, b, q)) return 0;
    if (above_a != above_b) {
      const int t = turn(a, b, q);
      if ((b.y() > a.y() && t > 0) || (b.y() < a.y() && t < 0)) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// The same for the polygon with holes: +1 inside the outer ring and outside every hole.
inline int locate_in(const std::vector<Cycle>& rings, const QPoint& q) {
  int where = locate(rings[0], q);
  for (std::size_t k = 1; k < rings.size() && where == 1; ++k) {
    Cycle hole(rings[k].rbegin(), rings[k].rend());
    const int in_hole = locate(hole, q);
    where = in_hole == 1 ? -1 : in_hole == 0 ? 0 : 1;
  }
  return where;
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

// The closed bounding box of a cycle: a point outside it is outside the cycle, and two cycles with
// disjoint boxes share no point. The checks below skip pairs that their boxes already decide.
struct Box {
  Rational x0, x1, y0, y1;
};

inline Box box_of(const Cycle& c) {
  Box b{c[0].x(), c[0].x(), c[0].y(), c[0].y()};
  for (const QPoint& q : c) {
    b.x0 = std::min(b.x0, q.x()), b.x1 = std::max(b.x1, q.x());
    b.y0 = std::min(b.y0, q.y()), b.y1 = std::max(b.y1, q.y());
  }
  return b;
}

inline bool contains(const Box& b, const QPoint& q) {
  return b.x0 <= q.x() && q.x() <= b.x1 && b.y0 <= q.y() && q.y() <= b.y1;
}

inline bool disjoint(const Box& a, const Box& b) { return a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0; }

inline std::vector<Box> boxes_of(const std::vector<Cycle>& cycles) {
  std::vector<Box> boxes;
  for (const Cycle& c : cycles) boxes.push_back(box_of(c));
  return boxes;
}

inline QPoint centroid(const Cycle& c) {
  Rational x = 0, y = 0;
  for (const QPoint& q : c) x += q.x(), y += q.y();
  return QPoint(x / Rational(c.size()), y / Rational(c.size()));
}

inline bool samples_covered_once(const std::vector<Cycle>& rings, const std::vector<Cycle>& pieces) {
  const Box outline = box_of(rings[0]);
  const Rational &x0 = outline.x0, &x1 = outline.x1, &y0 = outline.y0, &y1 = outline.y1;
  const std::vector<Box> boxes = boxes_of(pieces);
  const int steps = 23;
  for (int i = 1; i < steps; ++i)
    for (int j = 1; j < steps; ++j) {
      const QPoint q(x0 + (x1 - x0) * Rational(2 * i + 1, 2 * steps + 3), y0 + (y1 - y0) * Rational(2 * j + 1, 2 * steps + 5));
      const int where = locate_in(rings, q);
      if (where == 0) continue;
      int strictly = 0, touching = 0;
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (!contains(boxes[k], q)) continue;
        const int w = locate(pieces[k], q);
        strictly += w == 1, touching += w == 0;
      }
      if (touching) continue;
      if (strictly != (where == 1 ? 1 : 0)) return false;
    }
  return true;
}

inline bool tiles(const std::vector<Cycle>& rings, const std::vector<Cycle>& pieces, bool convex) {
  Rational total = 0, polygon_area = 0;
  for (const Cycle& piece : pieces) {
    if (piece.size() < 3) return false;
    if (convex ? !convex_ccw(piece) : !simple_brute(piece)) return false;
    total += area2(piece);
  }
  for (const Cycle& ring : rings) polygon_area += area2(ring);
  if (total != polygon_area) return false;
  if (!samples_covered_once(rings, pieces)) return false;
  if (!convex) return true;
  // Two convex pieces with disjoint boxes are disjoint, and then one of their edge lines separates them
  // (the separating axis theorem), so `separated` would hold; a vertex outside a piece's box is not
  // inside it, and an edge whose box misses the piece's cannot cross it.
  const std::vector<Box> boxes = boxes_of(pieces);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      if (!disjoint(boxes[i], boxes[j]) && !separated(pieces[i], pieces[j])) return false;
    if (locate_in(rings, centroid(pieces[i])) != 1) return false;
    for (const Cycle& ring : rings)
      for (std::size_t b = 0; b < ring.size(); ++b) {
        const QPoint &e0 = ring[b], &e1 = ring[(b + 1) % ring.size()];
        const QPoint middle((e0.x() + e1.x()) / 2, (e0.y() + e1.y()) / 2);
        for (const QPoint& v : {e0, middle})
          if (contains(boxes[i], v) && locate(pieces[i], v) == 1) return false;
        if (disjoint(boxes[i], box_of({e0, e1}))) continue;
        for (std::size_t a = 0; a < pieces[i].size(); ++a)
          if (proper_cross(pieces[i][a], pieces[i][(a + 1) % pieces[i].size()], e0, e1)) return false;
      }
  }
  return true;
}

// A cycle as text, from its least point on, so that the same cycle from any starting vertex reads the
// same.
inline std::string canonical_text(const Cycle& c) {
  const auto least = std::min_element(c.begin(), c.end(), [](const QPoint& a, const QPoint& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::ostringstream text;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const QPoint& q = c[(static_cast<std::size_t>(least - c.begin()) + i) % c.size()];
    text << q.x() << ' ' << q.y() << ';';
  }
  return text.str();
}

// `tiles`, computed once per (polygon, piece set) in a process: the same pieces of the same polygon,
// whichever algorithm, rotation or vertex order produced them, are checked once.
inline bool tiles_once(const std::vector<Cycle>& rings, const std::vector<Cycle>& pieces, bool convex) {
  static std::map<std::string, bool> known;
  std::vector<std::string> piece_texts;
  for (const Cycle& piece : pieces) piece_texts.push_back(canonical_text(piece));
  std::sort(piece_texts.begin(), piece_texts.end());
  std::string key;
  for (const Cycle& ring : rings) key += canonical_text(ring) + "/";
  key += convex ? "|convex|" : "|any|";
  for (const std::string& t : piece_texts) key += t + "|";
  const auto found = known.find(key);
  if (found != known.end()) return found->second;
  return known[key] = tiles(rings, pieces, convex);
}

}  // namespace pd::independent
