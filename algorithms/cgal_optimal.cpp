// cgal-optimal: CGAL 5.5 optimal_convex_partition_2 (Hert and Schirra): Greene's O(n^4) dynamic program for the
// minimum convex decomposition without Steiner points, as CGAL implements it. A peer: its results are
// reported as returned; CGAL issue 4398 (the result depends on the starting vertex) and invalid or
// non-minimal results on some simple polygons are known.
#include "core/registry.h"
#include "engines/peers/cgal_partition.h"

namespace pd {

REGISTER_ALGORITHM({.name = "cgal-optimal", .kind = Kind::Convex, .optimal = true, .time_bound = "n^4",
                    .pieces_bound = "== OPT",
                    .source = "CGAL 5.5 optimal_convex_partition_2 (Greene's dynamic program)",
                    .peer = "CGAL 5.5", .size_ceiling = 400, .run = cgal_optimal});

}  // namespace pd
