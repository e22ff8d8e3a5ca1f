// naive_complete_chains (naive.h): the naive decomposition with the boundary searched through its
// convex chains, the method of `naive-chains` (its paper, bounds and guarantees:
// algorithms/naive_chains.cpp) and of Chazelle-Dobkin's STEP 5.
//
// Reconstructed: Chapter 4, where the thesis intersects a line with a convex chain in O(log k), is not
// part of the text we have. The chain's edge directions turn counter-clockwise through less than a
// full turn, so, measured from the chain's first edge, they are sorted by angle: two binary searches
// find the edges where the direction passes the ray's direction and its opposite, i.e. the chain's
// vertices farthest left and right of the ray's line. Between them the signed distance to that line
// is monotone, and a binary search in each of the at most three runs finds where the chain crosses the
// perturbed ray (at most once per run) and the vertices it has exactly on the line. All of it with
// exact predicates on the input points.
//
// The chains are the thesis's (greedy, maximal); building them skips the tests of the closing angles
// where they provably pass (see boundary_chains.cpp), so that the O(n) pass costs about one predicate per
// vertex: it is what this algorithm spends most of its time on when r is small.
#include "engines/naive/naive.h"
#include "engines/search/boundary_chains.h"

#include <algorithm>
#include <utility>

namespace pd {
namespace {

using boundary::Chain;
using boundary::cross_sign;
using boundary::dot_sign;

// The O(log k) intersection of a shot's perturbed ray with every convex chain.
class ChainSearch : public naive::BoundarySearch {
 public:
  ChainSearch(const Polygon& p, std::vector<Chain> chains) : p_(p), chains_(std::move(chains)) {}

  void search(naive::Shot& shot) override {
    shot_ = &shot;
    a_ = &shot.from(), v_ = &shot.origin();
    for (const Chain& c : chains_) {
      chain_ = &c;
      // The notch's own edges are not searched: they are the first edge of one chain and the last of
      // another.
      const std::size_t lo = c.start == shot.notch() ? 1 : 0;
      const std::size_t hi = boundary::chain_vertex(c, c.edges) == shot.notch() ? c.edges - 1 : c.edges;
      if (lo < hi) search_chain(lo, hi);
    }
  }

  std::int64_t steps() const { return steps_; }
  std::int64_t searches() const { return searches_; }

 private:
  std::size_t id(std::size_t j) const { return boundary::chain_vertex(*chain_, j); }
  const Point& x(std::size_t j) const { return p_[id(j)]; }

  void search_chain(std::size_t lo, std::size_t hi) {
    ++searches_;
    if (hi - lo <= kShortChain) return scan(lo, hi);
    std::size_t cuts[4] = {lo, first_edge_reaching(lo, hi, 1), first_edge_reaching(lo, hi, -1), hi};
    std::sort(cuts + 1, cuts + 3);
    for (int k = 0; k < 3; ++k)
      if (cuts[k] < cuts[k + 1]) search_run(cuts[k], cuts[k + 1]);
  }

  // A short chain is tested edge by edge, as `naive` does: cheaper than setting up the searches, and
  // still O(1) per chain.
  static constexpr std::size_t kShortChain = 8;
  void scan(std::size_t lo, std::size_t hi) {
    naive::Place before = shot_->place(id(lo));
    if (before == naive::Place::Ahead) shot_->offer_ahead(id(lo));
    for (std::size_t j = lo + 1; j <= hi; ++j) {
      ++steps_;
      const naive::Place at = shot_->place(id(j));
      if (at == naive::Place::Ahead) shot_->offer_ahead(id(j));
      if (naive::side_of(before) != naive::side_of(at)) shot_->offer_edge(id(j - 1), naive::side_of(before) < 0);
      before = at;
    }
  }

  // The first edge in [lo, hi) whose direction is at or past the direction `sense` * (v - a) in the
  // order around d0; hi when there is none. The directions are sorted in that order (the chain turns
  // left by less than a full turn), so this is a binary search.
  std::size_t first_edge_reaching(std::size_t lo, std::size_t hi, int sense) {
    const int c = sense * cross_sign(x(0), x(1), *a_, *v_);
    const bool ahead_of_d0 = sense * dot_sign(x(0), x(1), *a_, *v_) > 0;
    const int half_u = c > 0 ? 0 : c < 0 ? 1 : ahead_of_d0 ? 0 : 1;
    auto before_u = [&](std::size_t j) {
      ++steps_;
      const int h = boundary::half_of_edge(p_, *chain_, j);
      if (h != half_u) return h < half_u;
      return sense * cross_sign(x(j), x(j + 1), *a_, *v_) > 0;
    };
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (before_u(mid)) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  int side_of_line(std::size_t j) {
    ++steps_;
    return orient(*a_, *v_, x(j));
  }

  // First j in [lo, hi] with pred(j), hi + 1 if none; pred is monotone (false, then true).
  template <class Pred>
  std::size_t first(std::size_t lo, std::size_t hi, Pred pred) {
    ++hi;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (pred(mid)) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  }

  // Vertices lo..hi, along which the signed distance to the ray's line is monotone.
  void search_run(std::size_t lo, std::size_t hi) {
    const int rising = cross_sign(*a_, *v_, x(lo), x(hi));
    const int dir = rising == 0 ? 1 : rising;
    // Along the run, dir * side goes -1, 0, +1: [lo, zero) below, [zero, above) on the line.
    const std::size_t zero = first(lo, hi, [&](std::size_t j) { return dir * side_of_line(j) >= 0; });
    const std::size_t above = first(zero, hi, [&](std::size_t j) { return dir * side_of_line(j) > 0; });
    bool on_line_ahead = false;
    if (zero < above) {
      on_line_ahead = shot_->place(id(zero)) == naive::Place::Ahead;
      if (on_line_ahead) shot_->offer_ahead(id(zero)), shot_->offer_ahead(id(above - 1));
    }
    // The perturbed ray puts vertices on the line ahead to the right, those behind to the left.
    const bool left_grows = dir > 0;
    const std::size_t change = left_grows == on_line_ahead ? above : zero;
    if (lo < change && change <= hi) shot_->offer_edge(id(change - 1), left_grows);
  }

  const Polygon& p_;
  std::vector<Chain> chains_;
  naive::Shot* shot_ = nullptr;
  const Point *a_ = nullptr, *v_ = nullptr;
  const Chain* chain_ = nullptr;
  std::int64_t steps_ = 0, searches_ = 0;
};

}  // namespace

Decomposition naive_complete_chains(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                                    Counters& counters) {
  std::vector<VertexId> all_notches;
  std::vector<Chain> chains;
  boundary::split_into_chains(p, all_notches, chains);
  const std::int64_t pseudo_notches = static_cast<std::int64_t>(chains.size());
  ChainSearch search(p, std::move(chains));
  Decomposition out = naive::resolve(p, std::move(d), notches, search, counters);
  counters["pseudo_notches"] = pseudo_notches;
  counters["chain_searches"] = search.searches();
  counters["binary_search_steps"] = search.steps();
  return out;
}

}  // namespace pd
