// naive-chains: Chazelle's naive decomposition searched through convex chains (B. Chazelle,
// Computational Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.2.2, Figure 2.6, Theorems 3
// and 4).
//
// Time O(n + r^2 log(n/r)), space O(n) (Theorem 4): an O(n) pass finds the notches and cuts each
// ring between consecutive notches into maximal convex chains, whose m endpoints are the
// pseudo-notches, m <= 2(1 + r) (Theorem 3, counted as "pseudo_notches"); then each of the r shots
// intersects its ray with every chain in O(log k) for a chain of k edges, and with the O(r) segments
// drawn before. Pre: a polygon with h >= 0 holes (a hole's convex corners are notches; a ring without
// a notch, the outer one at most, is one chain, and a hole's ring turns right by a full turn in all,
// so Theorem 3's count holds ring by ring); collinear vertices allowed. Output: the same guarantees
// as `naive` (algorithms/naive.cpp): exactly r + 1 - h convex pieces, r exact Steiner points, every
// vertex of degree 2 or 3; with the same shots in the same order, the same decomposition as `naive`.
//
// The chain searches are reconstructed (the thesis's Chapter 4 is not part of the text we have); how,
// in engines/naive/naive_chains.cpp.
#include "core/registry.h"
#include "engines/naive/naive.h"

namespace pd {
namespace {

Decomposition naive_chains(const Polygon& p, Counters& counters) {
  return naive_complete_chains(p, Decomposition{}, naive::notches_of(p), counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "naive-chains", .kind = Kind::Convex, .steiner = true,
                    .time_bound = "n+r^2*log(n/r)", .pieces_bound = "== r+1-h",
                    .source = "Chazelle thesis (000) Sec. 2.2.2, Thms 3-4", .accepts = {.holes = true},
                    .run = naive_chains});

}  // namespace pd
