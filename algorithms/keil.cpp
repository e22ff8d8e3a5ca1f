// keil: J. M. Keil's dynamic program for the minimum convex decomposition without Steiner points (SIAM
// J. Comput. 14, 1985), as described in Keil & Snoeyink (001), Sec. 3.
//
// The fewest convex pieces cut by diagonals. Time O(n r^2 log r), space O(n r^2), after the visibility
// lists of the reflex vertices (visibility.h). Pre: a simple counter-clockwise polygon; collinear
// vertices allowed. Pieces: == OPT.
//
// The same subproblems and combinations as keil-snoeyink (engines/keil_snoeyink/narrowest_pairs.h), but each subproblem's
// narrowest pairs are kept as a search structure: a sorted array, searched by bisection for the last
// pair that keeps p_j convex (the pairs that do form a prefix in TypeA and a suffix in TypeB, by
// Observation 1). Nothing is popped, so each TypeA/TypeB call costs O(log) instead of O(1) amortised:
// this is the log factor that Keil & Snoeyink remove with stacks. Deviation: the two cases
// engines/keil_snoeyink/narrowest_pairs.h adds for collinear vertices.
#include "core/registry.h"
#include "engines/keil_snoeyink/narrowest_pairs.h"

namespace pd {
namespace {

using narrowest::kNone;
using narrowest::Pair;

class SearchStructure {
 public:
  void reserve(std::size_t) {}
  void complete(std::int32_t, std::uint32_t, std::uint32_t) {}

  template <class Keeps>
  std::uint32_t last_keeping_a(std::int32_t, const std::vector<Pair>& pool, std::uint32_t begin, std::uint32_t end,
                               Keeps keeps) {
    std::uint32_t lo = begin, hi = end;  // keeps() holds on [begin, lo) and fails on [hi, end)
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      ++probes_;
      if (keeps(pool[mid])) lo = mid + 1;
      else hi = mid;
    }
    return lo > begin ? lo - 1 : kNone;
  }
  template <class Keeps>
  std::uint32_t last_keeping_b(std::int32_t, const std::vector<Pair>& pool, std::uint32_t begin, std::uint32_t end,
                               Keeps keeps) {
    std::uint32_t lo = begin, hi = end;  // keeps() fails on [begin, lo) and holds on [hi, end)
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      ++probes_;
      if (keeps(pool[mid])) hi = mid;
      else lo = mid + 1;
    }
    return lo < end ? lo : kNone;
  }

  void report(Counters& counters) const { counters["search_probes"] = probes_; }

 private:
  std::int64_t probes_ = 0;
};

Decomposition keil(const Polygon& p, Counters& counters) {
  return narrowest::Program<SearchStructure>(p).run(counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "keil", .kind = Kind::Convex, .optimal = true, .time_bound = "n*r^2*log(r)",
                    .pieces_bound = "== OPT", .source = "Keil 1985 as in Keil & Snoeyink (001) Sec. 3",
                    .size_ceiling = 2000, .run = keil});

}  // namespace pd
