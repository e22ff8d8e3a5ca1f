// hertel-mehlhorn-greedy: Hertel and Mehlhorn's diagonal removal (as in `hertel-mehlhorn`: Keil-Snoeyink
// (001), Sec. 2; slides (003)) over the `monotone` triangulation, with the diagonals taken in a greedy
// order instead of the triangulation's. A deviation of ours, not the paper's: the paper removes the
// diagonals in any order, and any order leaves only essential diagonals, but which ones are left
// depends on it.
//
// The order: a reflex vertex needs at least one diagonal kept at it, and a diagonal that alone splits
// its reflex angle into two convex ones (each side at most 180 degrees) can be the only one. Such a
// diagonal "resolves" that endpoint. The diagonals resolving no endpoint are tried first, those
// resolving one next, those resolving both ends last, each group in the triangulation's order (a
// stable counting sort): removals first spend the diagonals no reflex vertex needs, so that what is
// left at a reflex vertex tends to be one resolving diagonal, shared with the reflex vertex at its
// other end where the triangulation has one. No bound better than Hertel-Mehlhorn's is claimed.
//
// Time O(n) after the triangulation (two orientation tests per diagonal end, the counting sort, the
// O(1) removal tests of engines/convex/essential_diagonals.h; O(n log n) with holes, whose removal
// sorts each vertex's diagonals by angle), O(n log n) with it; space O(n). Pre: a polygon, with h >= 0
// holes; collinear vertices allowed. Output: diagonals only, every one
// essential, at most 2r + 1 - h pieces, at most 4 OPT without holes.
#include "core/registry.h"
#include "engines/convex/essential_diagonals.h"
#include "engines/triangulation/monotone.h"

#include <array>

namespace pd {
namespace {

// Whether diagonal v-w alone leaves convex angles on both its sides at reflex vertex v.
bool resolves(const Polygon& p, std::size_t v, std::size_t w) {
  return p.is_reflex(v) && orient(p[v], p[p.next(v)], p[w]) >= 0 && orient(p[v], p[w], p[p.prev(v)]) >= 0;
}

// The diagonals by the number of ends they resolve (0, 1, 2), each group in the given order.
std::vector<Cut> greedy_order(const Polygon& p, const std::vector<Cut>& diagonals, Counters& counters) {
  std::vector<int> resolved(diagonals.size());
  std::array<std::size_t, 4> start{};
  for (std::size_t k = 0; k < diagonals.size(); ++k) {
    const Cut& c = diagonals[k];
    resolved[k] = resolves(p, c.a, c.b) + resolves(p, c.b, c.a);
    ++start[resolved[k] + 1];
  }
  counters["resolving_one_end"] = static_cast<std::int64_t>(start[2]);
  counters["resolving_both_ends"] = static_cast<std::int64_t>(start[3]);
  for (std::size_t g = 1; g < start.size(); ++g) start[g] += start[g - 1];
  std::vector<Cut> ordered(diagonals.size());
  for (std::size_t k = 0; k < diagonals.size(); ++k) ordered[start[resolved[k]]++] = diagonals[k];
  return ordered;
}

Decomposition hertel_mehlhorn_greedy(const Polygon& p, Counters& counters) {
  Counters triangulation;
  const std::vector<Cut> diagonals = greedy_order(p, triangulate_monotone(p, triangulation).cuts, counters);
  return essential::removal_result(p, diagonals, triangulation, counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "hertel-mehlhorn-greedy", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT",
                    .source = "Hertel-Mehlhorn (001 Sec. 2, slides 003) over monotone; greedy removal order (ours)",
                    .accepts = {.holes = true}, .run = hertel_mehlhorn_greedy});

}  // namespace pd
