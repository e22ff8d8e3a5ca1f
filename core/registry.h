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
//
// A file may also register a family of variants, one algorithm per base algorithm it takes (e.g.
// `hertel-mehlhorn[ear-n2]` for every triangulation that adds no Steiner points): REGISTER_VARIANTS
// with a predicate and a function that makes the variant of a base. Each variant is in the registry
// like any algorithm, made when both its family and its base are registered (in either order, plug-ins
// included), and names its base in `variant_of`.
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
  std::string variant_of{};            // a variant's base algorithm; empty for an algorithm of its own file
  RunFn run{};
};

// A family of variants: `takes` says which bases it has a variant of, `make` makes the variant of one.
struct VariantFamily {
  std::string name;  // the family's name, e.g. "hertel-mehlhorn"; a variant is called name[base]
  std::function<bool(const Algorithm& base)> takes;
  std::function<Algorithm(const Algorithm& base)> make;
};

// The name of the variant of `family` over `base`.
inline std::string variant_name(const std::string& family, const std::string& base) {
  return family + "[" + base + "]";
}

inline bool is_peer(const Algorithm& a) { return !a.peer.empty(); }

// Why `a` does not take `p` (one sentence naming the limit), or nothing when it does.
std::optional<std::string> refusal(const Algorithm& a, const Polygon& p);

// The registry as `polydecomp list --json` prints it (docs/CONTRACT.md, "polydecomp list").
std::string algorithms_json();

// All registered algorithms, sorted by name.
inline const std::vector<Algorithm>& algorithms() { return NamedRegistry<Algorithm>::all(); }
// The algorithm called `name`, or nullptr.
inline const Algorithm* find_algorithm(const std::string& name) { return NamedRegistry<Algorithm>::find(name); }
// Adds an algorithm, and its variant in every family that takes it; used by REGISTER_ALGORITHM at
// static-initialisation time and by the plug-ins.
bool register_algorithm(Algorithm a);
// Adds a family of variants, and its variant of every registered algorithm it takes.
bool register_variant_family(VariantFamily family);
// The first name that registering `a` would add (its own, then its variants') that is registered
// already, or nothing: register_algorithm throws std::logic_error for such a name, after adding `a`.
std::optional<std::string> taken_name(const Algorithm& a);

}  // namespace pd

#define REGISTER_ALGORITHM(...) \
  static const bool PD_CONCAT(pd_registered_, __COUNTER__) = ::pd::register_algorithm(__VA_ARGS__)
#define REGISTER_VARIANTS(...) \
  static const bool PD_CONCAT(pd_registered_, __COUNTER__) = ::pd::register_variant_family(__VA_ARGS__)
