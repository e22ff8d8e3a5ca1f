// keil-snoeyink: J. M. Keil and J. Snoeyink, "On the time bound for convex decomposition of simple
// polygons" (001), Sec. 3, Algorithm 1, Theorem 2.
//
// Minimum convex decomposition without Steiner points: the fewest convex pieces cut by diagonals.
// Time O(n r^2) and space O(n r^2) (Theorem 2), after the visibility lists of the reflex vertices
// (O(n log n) triangulation + O(n) per reflex vertex, visibility.h). Pre: a simple counter-clockwise
// polygon; collinear vertices allowed (pieces may have 180-degree vertices). Pieces: == OPT.
//
// Keil's dynamic program (narrowest_pairs.h) with its search structure replaced by stacks: the pairs of
// P_ik are one array in increasing order; T_ik pops from the bottom (TypeA, called for increasing k
// with i, j fixed) and S_ik from the top (TypeB, called for decreasing i with j, k fixed), each
// popping a pair only while the next one still keeps p_j convex. Whatever is popped is wider at p_j
// than a pair that already serves every later call (Observation 1), so each pair is popped at most
// once per stack: the pops are bounded by the pushes, at most two per TypeA/TypeB call, and the calls
// by n r^2. Deviation: the two cases narrowest_pairs.h adds for collinear vertices (chains, and
// 180-degree pieces found by binary search), which general-position input never reaches.
#include "algorithms/keil_snoeyink.h"

#include "algorithms/narrowest_pairs.h"

namespace pd {
namespace {

using narrowest::kNone;
using narrowest::Pair;

class Stacks {
 public:
  void reserve(std::size_t links) {
    bottom_.assign(links, 0);
    top_.assign(links, 0);
  }
  void complete(std::int32_t id, std::uint32_t begin, std::uint32_t end) {
    bottom_[id] = begin;
    top_[id] = end > begin ? end - 1 : begin;
  }

  // Pops T_id (from the bottom) while the pair above still keeps p_j convex; the top is then the last
  // pair that does, if any does.
  template <class Keeps>
  std::uint32_t last_keeping_a(std::int32_t id, const std::vector<Pair>& pool, std::uint32_t begin, std::uint32_t end,
                               Keeps keeps) {
    if (begin == end) return kNone;
    std::uint32_t& top = bottom_[id];
    while (top + 1 < end && keeps(pool[top + 1])) ++top, ++pops_;
    return keeps(pool[top]) ? top : kNone;
  }
  // Pops S_id (from the top) while the pair below still keeps p_j convex.
  template <class Keeps>
  std::uint32_t last_keeping_b(std::int32_t id, const std::vector<Pair>& pool, std::uint32_t begin, std::uint32_t end,
                               Keeps keeps) {
    if (begin == end) return kNone;
    std::uint32_t& top = top_[id];
    while (top > begin && keeps(pool[top - 1])) --top, ++pops_;
    return keeps(pool[top]) ? top : kNone;
  }

  void report(Counters& counters) const {
    counters["stack_pushes"] = counters["pair_pushes"];
    counters["stack_pops"] = counters["pair_pops"] + pops_;
  }

 private:
  std::vector<std::uint32_t> bottom_, top_;
  std::int64_t pops_ = 0;
};

}  // namespace

Decomposition keil_snoeyink(const Polygon& p, Counters& counters) {
  return narrowest::Program<Stacks>(p).run(counters);
}

REGISTER_ALGORITHM(Algorithm{"keil-snoeyink", Kind::Convex, false, true, "n*r^2", "== OPT",
                             "Keil & Snoeyink (001) Sec. 3, Alg. 1, Thm 2", 2000, keil_snoeyink});

}  // namespace pd
