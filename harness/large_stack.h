// Runs a program's body on a thread with a large stack.
//
// Some peers recurse once per vertex or so: CGAL 5.5's y_monotone_partition_2 (and greene's
// approximation built on it) overflows the default 8 MiB stack on the `spiral` family at n = 300,000
// (a segmentation fault, not an error a user can act on). The command line and the benchmark run
// everything on a thread whose stack is reserved at 1 GiB; the pages are committed only when touched,
// so this costs nothing until a deep recursion needs it, and the per-call timings are unaffected.
// Where the address space is limited (ulimit -v), the reservation takes at most a quarter of the limit
// (256, 64 or 16 MiB), or failing that the calling thread runs the body; a recursion that then runs out
// of stack ends with one error line (harness/last_resort.h), not a bare segmentation fault.
#pragma once

#include <functional>

namespace pd {

// Calls `body` on a thread with the largest stack of 1 GiB, 256, 64 and 16 MiB that is allowed and can
// be reserved, and returns its result; if none can, calls it on this thread.
int run_on_large_stack(const std::function<int()>& body);

// A benchmark program's main(): `run` on a large stack, an exception escaping it reported as one
// `error:` line and exit status 2.
int benchmark_main(int argc, char** argv, int (*run)(int, char**));

}  // namespace pd
