// Keil & Snoeyink's Algorithm 1: Keil's dynamic program (engines/keil_snoeyink/narrowest_pairs.h) with stacks in place of
// its search structure. The method of `keil-snoeyink` (its paper, bounds and proof of the stack
// bound: algorithms/keil_snoeyink.cpp), also run by `keil-snoeyink-reduced` on its reduced polygon.
#include "engines/keil_snoeyink/stacks.h"

#include "engines/keil_snoeyink/narrowest_pairs.h"

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

}  // namespace pd
