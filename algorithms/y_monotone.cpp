// y-monotone: partition into y-monotone pieces by plane sweep (de Berg, Cheong, van Kreveld, Overmars,
// Computational Geometry, Sec. 3.2, MakeMonotone; Rosen slides 003, "Partitioning into monotone
// polygons", "Sweep idea", "Forming trapezoids").
//
// Time O(n log n), space O(n). Pre: a polygon, with h >= 0 holes (a hole's top vertex is a split
// vertex, its bottom a merge vertex, as de Berg et al. note in Sec. 3.2); collinear (180-degree)
// vertices and horizontal edges allowed. Output: diagonals only, one from every split vertex up and one
// from every merge vertex down (one diagonal may serve both ends), so at most r+1-h pieces (each of the
// first h diagonals that reach a hole joins two rings instead of splitting a piece), each weakly
// y-monotone. No Steiner points.
#include "core/registry.h"
#include "engines/triangulation/monotone.h"

namespace pd {
namespace {

Decomposition y_monotone(const Polygon& p, Counters& counters) {
  Decomposition d;
  d.cuts = y_monotone_diagonals(p, counters);
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "y-monotone", .kind = Kind::Partition, .time_bound = "n*log(n)",
                    .pieces_bound = "<= r+1-h",
                    .source = "de Berg et al. Sec. 3.2 (MakeMonotone); Rosen slides (003), monotone partitioning",
                    .accepts = {.holes = true}, .run = y_monotone});

}  // namespace pd
