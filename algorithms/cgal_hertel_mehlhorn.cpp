// cgal-hertel-mehlhorn: CGAL 5.5 approx_convex_partition_2: Hertel-Mehlhorn's diagonal removal on a triangulation,
// <= 4 OPT pieces, O(n log n). A peer: its results are reported as returned.
#include "core/registry.h"
#include "engines/peers/cgal_partition.h"

namespace pd {

REGISTER_ALGORITHM({.name = "cgal-hertel-mehlhorn", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT",
                    .source = "CGAL 5.5 approx_convex_partition_2 (Hertel-Mehlhorn)", .peer = "CGAL 5.5",
                    .run = cgal_hertel_mehlhorn});

}  // namespace pd
