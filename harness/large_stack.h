// Runs a program's body on a thread with a large stack.
//
// Some peers recurse once per vertex or so: CGAL 5.5's y_monotone_partition_2 (and greene's
// approximation built on it) overflows the default 8 MiB stack on the `spiral` family at n = 300,000
// (a segmentation fault, not an error a user can act on). The command line and the benchmark run
// everything on a thread whose stack is reserved at 1 GiB; the pages are committed only when touched,
// so this costs nothing until a deep recursion needs it, and the per-call timings are unaffected.
#pragma once

#include <functional>

namespace pd {

// Calls `body` on a thread with a 1 GiB stack and returns its result; if that thread cannot be
// created, calls it on this one.
int run_on_large_stack(const std::function<int()>& body);

}  // namespace pd
