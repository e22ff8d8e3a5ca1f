// cgal-greene: CGAL 5.5 greene_approx_convex_partition_2: Greene's approximation from a y-monotone partition,
// <= 4 OPT pieces, O(n log n). A peer: its results are reported as returned; it gets the polygon
// without its collinear vertices (engines/peers/cgal_partition.cpp says why).
#include "core/registry.h"
#include "engines/peers/cgal_partition.h"

namespace pd {

REGISTER_ALGORITHM({.name = "cgal-greene", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT", .source = "CGAL 5.5 greene_approx_convex_partition_2",
                    .peer = "CGAL 5.5", .run = cgal_greene});

}  // namespace pd
