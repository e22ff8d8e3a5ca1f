// The simple polygon every algorithm receives.
//
// A Polygon is made by one checked constructor, Polygon::make, which rejects what is not a simple
// polygon (fewer than 3 vertices, non-finite coordinates, self-intersection, repeated vertices) with a
// PolygonError naming the problem, drops a repeated closing vertex, and normalises the orientation to
// counter-clockwise. Collinear (180-degree) vertices are kept. The input order is remembered so that
// output can be given in the file's indices.
#pragma once

#include "core/geometry.h"

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace pd {

// A polygon the tool cannot accept; what() is the one-line reason (without the "error: " prefix).
class PolygonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Polygon {
 public:
  // The one checked constructor. Simplicity is checked in O(n log n).
  static Polygon make(std::vector<Point> input);

  std::size_t size() const { return v_.size(); }
  const Point& operator[](std::size_t i) const { return v_[i]; }
  const std::vector<Point>& vertices() const { return v_; }
  std::size_t next(std::size_t i) const { return i + 1 == v_.size() ? 0 : i + 1; }
  std::size_t prev(std::size_t i) const { return i == 0 ? v_.size() - 1 : i - 1; }

  // Interior angle strictly greater than 180 degrees (a notch). Collinear vertices are not reflex.
  bool is_reflex(std::size_t i) const { return orient(v_[prev(i)], v_[i], v_[next(i)]) < 0; }
  std::size_t reflex_count() const;
  // The lowest-numbered reflex vertex, or size() when the polygon is convex.
  std::size_t first_reflex() const;

  // Index in the input file of counter-clockwise vertex i. Vertex 0 is always input vertex 0; when the
  // input was clockwise the rest run backwards.
  std::size_t input_index(std::size_t i) const { return reversed_ && i != 0 ? v_.size() - i : i; }
  bool input_was_clockwise() const { return reversed_; }

 private:
  Polygon(std::vector<Point> v, bool reversed) : v_(std::move(v)), reversed_(reversed) {}
  std::vector<Point> v_;
  bool reversed_;
};

// Twice the signed area of the cycle, exact (positive for counter-clockwise).
Rational twice_signed_area(const std::vector<Point>& cycle);

// Whether the closed chain through `cycle` is simple: no two non-adjacent edges meet, adjacent edges
// meet only at their shared vertex, no vertex repeats. O(n log n). On failure, `why` names a witness.
bool is_simple_cycle(const std::vector<Point>& cycle, std::string* why);
bool is_simple_cycle(const std::vector<QPoint>& cycle, std::string* why);

}  // namespace pd
