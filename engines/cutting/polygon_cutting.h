// The polygon-cutting theorem (Chazelle, "How to Divide a Polygon Fairly", CMU 1982, paper 004):
// machinery shared by `polydecomp cut`, cutting-convex and cutting-tri. See polygon_cutting.cpp for the
// construction and its bounds, docs/algorithms/polygon-cutting.md for what was reconstructed where the
// paper is unclear.
//
// Weights are 0/1 per vertex; C is their sum. A fair cut is a diagonal (a segment between two vertices
// whose interior lies inside the polygon and meets no vertex) that splits the polygon into two parts
// each weighing at most 2C/3, the diagonal's endpoints weighing 0 in both parts. It exists and is found
// when n >= 4 and C != 1 (Theorem 1 assumes C > 2; the construction also covers C = 0 and C = 2). With
// C = 1 the cut must end at the one weighted vertex, and that vertex may have no diagonal at all (the
// tips of a dart), so it is refused.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pd {

// Why no fair cut is promised for a polygon of n vertices weighing C, or nothing when one is.
std::optional<std::string> why_no_fair_cut(std::size_t n, std::int64_t C);

class NoFairCut : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

enum class WeightRule { Reflex, All };
// 1 for each reflex vertex (strictly: orient < 0) or for every vertex; in counter-clockwise order.
std::vector<int> vertex_weights(const Polygon& p, WeightRule rule);

// Theorem 1: a fair cut between counter-clockwise vertices a and b. C1 weighs the vertices strictly
// between a and b counter-clockwise from a, C2 those strictly between b and a.
struct FairCut {
  std::size_t a, b;
  std::int64_t C, C1, C2;
};

// Theorem 3: a chord AB of the polygon on a vertical line (docs/algorithms/polygon-cutting.md, item 1:
// the tilt for the paper's "no two vertices share an x-coordinate"), A inside edge (edge_a, edge_a+1);
// B inside edge (edge_b, edge_b+1), or, when b_is_vertex, B is vertex edge_b (weighing 0 on both
// sides). C1 weighs the vertices from edge_a+1 on to B counter-clockwise, C2 those from B on to edge_a,
// B excluded; both are at most 2C/3.
struct VerticalCut {
  QPoint A, B;
  std::size_t edge_a, edge_b;
  bool b_is_vertex;
  std::int64_t C, C1, C2;
};

// Both throw NoFairCut when why_no_fair_cut names a reason. O(n log n): the preprocessing, then O(n).
FairCut fair_cut(const Polygon& p, const std::vector<int>& weights, Counters& counters);
VerticalCut vertical_cut(const Polygon& p, const std::vector<int>& weights, Counters& counters);

namespace cutting {

using Id = std::uint32_t;  // a vertex of the top polygon, in its counter-clockwise order

// A sub-polygon of the top polygon cut off by diagonals: its vertices as a counter-clockwise cycle of
// top-polygon ids (consecutive ids are joined by a top edge or by a diagonal), with the two lists of
// the preprocessing restricted to it: LH, its vertices in (x, y) order, and LV, its top edges (an edge
// named by its first vertex) in vertical order.
struct Part {
  std::vector<Id> cycle, lh, lv;
};

// The per-cut operation counts: `visits` counts list elements, boundary nodes and candidate vertices
// touched, `levels` the rounds of the median-line recursion of Theorem 3.
struct CutWork {
  std::int64_t visits = 0, levels = 0;
};

// A diagonal between part positions a and b, with the weights strictly inside its two parts.
struct Diagonal {
  std::size_t a, b;
  std::int64_t C1, C2;
};

// Theorem 3's separator on a part: from a point A inside edge `edge` (a position) to a point B inside
// edge `end`, both on a median line (vertices of rank below `split` lie on its left); or, when
// `at_vertex`, to the vertex at position `end`, on the line through it (split is then its rank).
struct Chord {
  std::size_t edge, end;
  bool at_vertex;
  std::uint32_t split;
};

// Section 2's preprocessing of one top polygon (LP is the polygon itself, LH and LV are computed here,
// O(n log n)), and Theorems 1 and 3 on any part of it in time linear in the part's size.
class Cutter {
 public:
  explicit Cutter(const Polygon& top);

  Part whole() const;
  // The two parts on either side of the diagonal between part positions i and j, lists restricted in
  // O(size): cycle[i..j] and cycle[j..i].
  std::pair<Part, Part> split(const Part& part, std::size_t i, std::size_t j);

  // Preconditions (checked by the public functions): part.cycle.size() >= 4, C = sum(weights) != 1.
  // weights[k] belongs to part position k.
  Chord vertical_chord(const Part& part, const std::vector<int>& weights, CutWork& work);
  Diagonal fair_diagonal(const Part& part, const std::vector<int>& weights, CutWork& work);
  // The chord's endpoints as exact points.
  std::pair<QPoint, QPoint> chord_points(const Part& part, const Chord& chord) const;

 private:
  friend class SeparatorSearch;
  friend class SleeveSearch;

  void index(const Part& part);  // pos_[id] = position of id in part.cycle
  bool edge_below(Id p, Id q, Id r, Id s) const;
  struct Line;
  Line median_line(std::uint32_t split) const;
  Line line_through(std::uint32_t rank) const;
  Line tilted_line(const Point& at, const Rational& my, std::uint32_t rank) const;

  const Polygon& top_;
  std::vector<Id> lh_, lv_;
  std::vector<std::uint32_t> rank_;
  // Per rank: the last rank with a smaller x and the first with a larger x (-1 / n when none).
  std::vector<std::int64_t> lower_x_, higher_x_;
  double y_min_, y_max_;
  std::vector<std::uint32_t> pos_;
  std::vector<std::uint8_t> side_;
};

}  // namespace cutting
}  // namespace pd
