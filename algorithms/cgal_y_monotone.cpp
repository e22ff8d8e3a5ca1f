// cgal-y-monotone: CGAL 5.5 y_monotone_partition_2: the y-monotone partition by plane sweep, O(n log n). A peer:
// its results are reported as returned; it gets the polygon without its collinear vertices
// (engines/peers/cgal_partition.cpp says why).
#include "core/registry.h"
#include "engines/peers/cgal_partition.h"

namespace pd {

REGISTER_ALGORITHM({.name = "cgal-y-monotone", .kind = Kind::Partition, .time_bound = "n*log(n)",
                    .pieces_bound = "<= n", .source = "CGAL 5.5 y_monotone_partition_2", .peer = "CGAL 5.5",
                    .run = cgal_y_monotone});

}  // namespace pd
