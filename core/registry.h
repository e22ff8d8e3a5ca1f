// The algorithm registry. Each algorithm file registers itself with REGISTER_ALGORITHM; the command
// line, the benchmark harness and the tests iterate the registry, so a new algorithm is listed,
// benchmarked and validated without edits elsewhere. Algorithm files are built as a CMake OBJECT
// library so that the linker cannot drop their registrations.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pd {

enum class Kind { Triangulation, Partition, Convex, Cut };
const char* kind_name(Kind k);

// An algorithm's own operation counts. Algorithms count in local integers inside hot loops and store
// the totals here once, at the end.
using Counters = std::map<std::string, std::int64_t>;

using RunFn = std::function<Decomposition(const Polygon&, Counters&)>;

struct Algorithm {
  std::string name;
  Kind kind;
  bool steiner;             // may add Steiner points
  bool optimal;             // claims the minimum piece count for its class
  std::string time_bound;   // claimed running time, e.g. "n^2", "n*r^2", "n*log(n)"
  std::string pieces_bound; // claimed piece count, e.g. "== n-2", "<= 4*OPT", "== OPT"
  std::string source;       // paper and section/theorem
  std::size_t size_ceiling; // largest n that sweeps and property tests give it (its budget)
  RunFn run;
};

// All registered algorithms, sorted by name.
const std::vector<Algorithm>& algorithms();
// The algorithm called `name`, or nullptr.
const Algorithm* find_algorithm(const std::string& name);
// Adds an algorithm; used by REGISTER_ALGORITHM at static-initialisation time.
bool register_algorithm(Algorithm a);

}  // namespace pd

#define PD_CONCAT_INNER(a, b) a##b
#define PD_CONCAT(a, b) PD_CONCAT_INNER(a, b)
#define REGISTER_ALGORITHM(...) \
  static const bool PD_CONCAT(pd_registered_, __COUNTER__) = ::pd::register_algorithm(__VA_ARGS__)
