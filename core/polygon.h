// The polygon every algorithm receives: one outer ring and any number of holes (docs/CONTRACT.md,
// "Polygons with holes and multipolygons").
//
// A Polygon is made by one checked door, Polygon::make (one ring) or Polygon::make_with_holes (the
// outer ring, then its holes), which refuses what is not a polygon (a ring of fewer than 3 vertices,
// a coordinate that is not finite, a ring that is not simple, a hole that touches or crosses another
// ring or lies outside the outer ring or inside another hole) with a PolygonError naming the rings and
// vertices at fault. It drops a repeated closing vertex and merges a vertex that repeats its
// predecessor (neither changes the geometry), and normalises the orientation: the outer ring
// counter-clockwise, every hole clockwise, so that the polygon's interior is always to the left of an
// edge i -> next(i). Collinear (180-degree) vertices are kept.
//
// Vertices are numbered ring after ring (the outer ring first, then the holes in input order); next()
// and prev() stay inside a vertex's ring. The input order is remembered: input_index() gives a vertex's
// index among the input's vertices in file order (merged vertices included), and merged() the input
// vertices that were merged.
#pragma once

#include "core/geometry.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pd {

// A polygon the tool cannot accept; what() is the one-line reason (without the "error: " prefix).
class PolygonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Ring = std::vector<Point>;
using Rings = std::vector<Ring>;  // the outer ring, then its holes, each as written

class Polygon {
 public:
  // The checked doors. The rings' simplicity and layout are checked in O(n log n).
  static Polygon make(Ring outer);
  static Polygon make_with_holes(Rings rings);

  std::size_t size() const { return v_.size(); }
  const Point& operator[](std::size_t i) const { return v_[i]; }
  const std::vector<Point>& vertices() const { return v_; }
  std::size_t next(std::size_t i) const {
    if (ring_of_.empty()) return i + 1 == v_.size() ? 0 : i + 1;
    const std::size_t k = ring_of_[i];
    return i + 1 == ring_start_[k + 1] ? ring_start_[k] : i + 1;
  }
  std::size_t prev(std::size_t i) const {
    if (ring_of_.empty()) return i == 0 ? v_.size() - 1 : i - 1;
    const std::size_t k = ring_of_[i];
    return i == ring_start_[k] ? ring_start_[k + 1] - 1 : i - 1;
  }

  // Rings: 0 is the outer ring, 1..hole_count() the holes; ring k holds vertices
  // ring_begin(k) .. ring_end(k)-1.
  std::size_t ring_count() const { return ring_start_.size() - 1; }
  std::size_t hole_count() const { return ring_count() - 1; }
  std::size_t ring_begin(std::size_t k) const { return ring_start_[k]; }
  std::size_t ring_end(std::size_t k) const { return ring_start_[k + 1]; }
  std::size_t ring_of(std::size_t i) const { return ring_of_.empty() ? 0 : ring_of_[i]; }

  // Interior angle (inside the polygon) strictly greater than 180 degrees: a notch of the outer ring,
  // or a convex corner of a hole. Collinear vertices are not reflex.
  bool is_reflex(std::size_t i) const { return orient(v_[prev(i)], v_[i], v_[next(i)]) < 0; }
  std::size_t reflex_count() const;
  // The lowest-numbered reflex vertex, or size() when there is none.
  std::size_t first_reflex() const;

  // Index among the input's vertices (file order, merged vertices counted) of vertex i. Each ring's
  // first vertex keeps its place; when the ring was turned round, the rest run backwards.
  std::size_t input_index(std::size_t i) const;
  // How many vertices the input gave (the repeated closing vertices not counted, merged ones counted).
  std::size_t input_size() const { return v_.size() + merged_.size(); }
  // The merged input vertices: (input index, input index of the vertex it repeats), in file order.
  const std::vector<std::pair<std::size_t, std::size_t>>& merged() const { return merged_; }
  // Each ring's vertices in order (the outer ring counter-clockwise, the holes clockwise).
  Rings rings() const;
  // The input's vertices in file order (merged ones included).
  std::vector<Point> input_points() const;
  bool input_was_clockwise() const { return ring_reversed_[0]; }
  bool ring_was_reversed(std::size_t k) const { return ring_reversed_[k]; }

 private:
  Polygon() = default;
  std::vector<Point> v_;
  std::vector<std::size_t> ring_start_;  // ring_count() + 1 entries
  std::vector<std::uint32_t> ring_of_;   // per vertex; empty when there are no holes
  std::vector<char> ring_reversed_;      // per ring: turned round to the normal orientation
  std::vector<std::uint32_t> file_of_;   // file-order position -> input index; empty when nothing merged
  std::vector<std::pair<std::size_t, std::size_t>> merged_;
};

// Totals over a multipolygon's parts, as the reports give them: input vertices (merged ones
// counted), reflex vertices, holes and merged vertices.
struct PolygonTotals {
  std::size_t n = 0, reflex = 0, holes = 0, merged = 0;
  void add(const Polygon& p) {
    n += p.input_size();
    reflex += p.reflex_count();
    holes += p.hole_count();
    merged += p.merged().size();
  }
};

// A multipolygon's parts through the same door: each part checked as make_with_holes checks it, and
// no two parts touching, crossing or overlapping (one part may lie in another's hole).
std::vector<Polygon> make_parts(std::vector<Rings> parts);

// Twice the signed area of the cycle, exact (positive for counter-clockwise).
Rational twice_signed_area(const std::vector<Point>& cycle);

// Whether the closed chain through `cycle` is simple: no two non-adjacent edges meet, adjacent edges
// meet only at their shared vertex, no vertex repeats. O(n log n). On failure, `why` names a witness.
bool is_simple_cycle(const std::vector<Point>& cycle, std::string* why);
bool is_simple_cycle(const std::vector<QPoint>& cycle, std::string* why);

}  // namespace pd
