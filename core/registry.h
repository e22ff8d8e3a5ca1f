// The algorithm registry. Each file in algorithms/ registers one algorithm with REGISTER_ALGORITHM and
// named fields:
//
//   REGISTER_ALGORITHM({.name = "keil-snoeyink", .kind = Kind::Convex, .optimal = true,
//                       .time_bound = "n*r^2", .pieces_bound = "== OPT", .source = "001 Thm 2",
//                       .size_ceiling = 2000, .run = keil_snoeyink});
//
// The command line, the benchmark harness and the tests iterate the registry, so a new algorithm is
// listed, benchmarked and validated without edits elsewhere. Algorithm files are built as a CMake
// OBJECT library so that the linker cannot drop their registrations.
#pragma once

#include "core/decomposition.h"
#include "core/named_registry.h"
#include "core/polygon.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pd {

using RunFn = std::function<Decomposition(const Polygon&, Counters&)>;

// The input an algorithm takes. The command line refuses any other before running (exit 3), the
// harness skips it with the reason, and the tests and fuzz targets give it none.
struct Accepts {
  bool holes = false;            // polygons with holes
  bool convex_only = false;      // only polygons without reflex vertices
  std::size_t max_vertices = 0;  // at most this many vertices; 0 for no limit
};

struct Algorithm {
  std::string name;
  Kind kind = Kind::Convex;
  bool steiner = false;                // may add Steiner points
  bool optimal = false;                // claims the minimum piece count for its class
  std::string time_bound{};            // claimed running time, e.g. "n^2", "n*r^2", "n*log(n)"
  std::string pieces_bound{};          // claimed piece count, e.g. "== n-2", "<= 4*OPT", "== OPT"
  std::string source{};                // paper and section/theorem
  std::string peer{};                  // whose code it is: empty for polydecomp's own, else the library
  Accepts accepts{};                   // the input it takes
  std::size_t size_ceiling = 1000000;  // largest n that sweeps and property tests give it (its budget)
  bool times_itself = false;           // run reports its own timing (Decomposition::own_seconds)
  RunFn run{};
};

inline bool is_peer(const Algorithm& a) { return !a.peer.empty(); }

// Why `a` does not take `p` (one sentence naming the limit), or nothing when it does.
std::optional<std::string> refusal(const Algorithm& a, const Polygon& p);

// The registry as `polydecomp list --json` prints it (docs/CONTRACT.md, "polydecomp list").
std::string algorithms_json();

// All registered algorithms, sorted by name.
inline const std::vector<Algorithm>& algorithms() { return NamedRegistry<Algorithm>::all(); }
// The algorithm called `name`, or nullptr.
inline const Algorithm* find_algorithm(const std::string& name) { return NamedRegistry<Algorithm>::find(name); }
// Adds an algorithm; used by REGISTER_ALGORITHM at static-initialisation time.
inline bool register_algorithm(Algorithm a) { return NamedRegistry<Algorithm>::add(std::move(a)); }

}  // namespace pd

#define REGISTER_ALGORITHM(...) \
  static const bool PD_CONCAT(pd_registered_, __COUNTER__) = ::pd::register_algorithm(__VA_ARGS__)
