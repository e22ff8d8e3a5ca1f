// The CGAL Partition_2 peers' calls (cgal_partition.cpp says what each gets and why), registered by
// algorithms/cgal_optimal.cpp, cgal_hertel_mehlhorn.cpp, cgal_greene.cpp and cgal_y_monotone.cpp.
#pragma once

#include "core/decomposition.h"

namespace pd {

Decomposition cgal_optimal(const Polygon& p, Counters& counters);
Decomposition cgal_hertel_mehlhorn(const Polygon& p, Counters& counters);
Decomposition cgal_greene(const Polygon& p, Counters& counters);
Decomposition cgal_y_monotone(const Polygon& p, Counters& counters);

}  // namespace pd
