// Monotone partition and monotone triangulation, shared by `y-monotone`, `monotone` and `seidel`, and
// called by algorithms that start from a triangulation (Hertel-Mehlhorn).
//
// Every function here orders vertices by the sweep order `above` (de Berg et al., Computational
// Geometry, Sec. 3.2): a is above b when a.y > b.y, or a.y == b.y and a.x < b.x. This total order on
// distinct points is the vertical order after an infinitesimal shear y' = y - eps*x, an affine map that
// keeps orientations and incidences, so horizontal edges and equal heights need no cases of their own:
// every statement about "monotone" below is in the sheared plane, and a polygon monotone there is
// weakly y-monotone in the plane (every horizontal line meets it in one interval, or not at all).
#pragma once

#include "core/decomposition.h"

#include <vector>

namespace pd {

inline bool above(const Point& a, const Point& b) { return a.y() > b.y() || (a.y() == b.y() && a.x() < b.x()); }

// The diagonals of the plane-sweep partition of p into monotone pieces (de Berg et al. Sec. 3.2): one
// diagonal from every split vertex up and from every merge vertex down. O(n log n). Counts
// "tree_operations" and "tree_comparisons" (the balanced search tree keyed on the sweep line) into
// `counters`.
std::vector<Cut> y_monotone_diagonals(const Polygon& p, Counters& counters);

// Triangulates every piece of p cut by `diagonals` (which must split p into pieces monotone in the
// sweep order) by the linear stack algorithm (Garey, Johnson, Preparata, Tarjan 1978; de Berg et al.
// Sec. 3.3). Returns the diagonals followed by the triangulation's own: n-3 cuts, n-2 non-degenerate
// triangles. O(n + k log k) for k diagonals (sorting them around their endpoints). Counts "pieces" and
// "stack_steps" into `counters`.
Decomposition triangulate_monotone_pieces(const Polygon& p, const std::vector<Cut>& diagonals, Counters& counters);

// The `monotone` triangulation: y_monotone_diagonals, then triangulate_monotone_pieces. O(n log n)
// time, O(n) space. Pre: a simple counter-clockwise polygon, collinear vertices allowed. No Steiner
// points.
Decomposition triangulate_monotone(const Polygon& p, Counters& counters);

}  // namespace pd
