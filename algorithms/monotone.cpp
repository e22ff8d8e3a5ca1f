// monotone: triangulation by monotone partition and monotone triangulation (Rosen slides 003,
// "Polygon triangulation", "Triangulation of monotone polygon"; Garey, Johnson, Preparata, Tarjan 1978;
// de Berg, Cheong, van Kreveld, Overmars, Computational Geometry, Sec. 3.2-3.3).
//
// Time O(n log n) (the sweep, engines/triangulation/monotone_partition.cpp; the rest is linear apart
// from sorting the few diagonals around their endpoints), space O(n). Pre: a polygon, with h >= 0 holes
// (the sweep takes them unchanged: a hole's top vertex is a split vertex, its bottom a merge vertex; de
// Berg et al. Sec. 3.2); collinear (180-degree) vertices and horizontal edges allowed. Output: n+3h-3
// diagonals, n+2h-2 non-degenerate triangles, no Steiner points.
#include "core/registry.h"
#include "engines/triangulation/monotone.h"

namespace pd {

REGISTER_ALGORITHM({.name = "monotone", .kind = Kind::Triangulation, .time_bound = "n*log(n)",
                    .pieces_bound = "== n+2*h-2",
                    .source = "Rosen slides (003), monotone partition + monotone triangulation; de Berg et al. 3.2-3.3",
                    .accepts = {.holes = true}, .run = triangulate_monotone});

}  // namespace pd
