// The Shamos-Hoey sweep (Shamos and Hoey 1976) behind the simplicity check of a ring (core/polygon.cpp)
// and the layout of rings (core/ring_layout.cpp). Segments are swept left to right in lexicographic
// order of their end points (so a vertical segment runs upwards); the segments the sweep line crosses
// are kept ordered bottom to top, and any two that become neighbours are tested for a common point.
// If some two segments meet, a pair of neighbours meets at or before the leftmost meeting point.
// Every predicate is exact (orient, filtered for input points): nothing is decided by an epsilon.
#pragma once

#include "core/geometry.h"

#include <cstdint>
#include <algorithm>
#include <iterator>
#include <memory_resource>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace pd {

// Where segment f = (flo, fhi) lies against segment e = (elo, ehi), lo < hi, both on the sweep line
// where the later of them starts: +1 above, -1 below, 0 when the order cannot separate them there
// (then they meet).
template <class P>
int side_in_sweep(const P& elo, const P& ehi, const P& flo, const P& fhi) {
  if (elo == flo) return orient(elo, ehi, fhi);
  if (elo < flo) return orient(elo, ehi, flo);
  return -orient(flo, fhi, elo);
}

// The edges the sweep line crosses, bottom to top by `Below` (which may throw to stop the sweep), with
// each edge's place. Inserting or removing an edge calls test(below, above) on each pair of edges
// that become neighbours (which may throw too). The nodes come from a pool: an insertion and a removal
// at every vertex would otherwise be a malloc and a free each.
//
// An insertion may name a place to try first: where an edge just left (at most vertices one edge
// ends where the next starts, and takes its place) or where the other edge of its vertex went in.
// std::set checks a hint against its two neighbours and searches only when it is wrong, so the order
// is the same as without it, at two comparisons instead of log n.
template <class Below, class Test>
class SweepStatus {
  using Active = std::pmr::set<std::uint32_t, Below>;

 public:
  using Place = typename Active::iterator;

  SweepStatus(std::size_t edges, Below below, Test test) : active_(below, &pool_), where_(edges), test_(test) {}

  Place insert(std::uint32_t e, std::optional<Place> hint = std::nullopt) {
    const auto it = hint ? active_.insert(*hint, e) : active_.insert(e).first;
    where_[e] = it;
    if (it != active_.begin()) test_(*std::prev(it), e);
    if (std::next(it) != active_.end()) test_(e, *std::next(it));
    return it;
  }
  // Returns the place e leaves: the edge above it, or the end.
  Place remove(std::uint32_t e) {
    const auto it = where_[e];
    const auto above = std::next(it);
    if (it != active_.begin() && above != active_.end()) test_(*std::prev(it), *above);
    return active_.erase(it);
  }
  // The edge just below e, which is in the order, if there is one.
  std::optional<std::uint32_t> below(std::uint32_t e) const {
    const auto it = where_[e];
    if (it == active_.begin()) return std::nullopt;
    return *std::prev(it);
  }

 private:
  std::pmr::unsynchronized_pool_resource pool_;
  Active active_;
  std::vector<typename Active::iterator> where_;
  Test test_;
};

// Whether a closed cycle is simple, and if not two edges that meet, given its vertex indices in
// lexicographic order of their points, which must be pairwise distinct, and no edge folding back onto
// the one before it. O(n log n) time, O(n) space; the sweep structure holds only the edges the sweep
// line crosses.
template <class P>
class CycleSweep {
 public:
  CycleSweep(const std::vector<P>& cycle, const std::vector<std::uint32_t>& order)
      : cycle_(cycle), order_(order), forward_(cycle.size()), active_(cycle.size(), Below{this}, Test{this}) {
    for (std::size_t e = 0; e < cycle.size(); ++e) forward_[e] = cycle[e] < cycle[next(e)];
  }

  // Two edges (by their first vertex, the smaller first) that meet, or nothing when the cycle is simple.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> meeting() {
    try {
      for (const std::uint32_t v : order_) visit(v);
    } catch (const Meeting& m) {
      return std::minmax(m.a, m.b);
    }
    return std::nullopt;
  }

 private:
  struct Meeting {
    std::uint32_t a, b;
  };
  struct Below {
    const CycleSweep* sweep;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      if (a == b) return false;
      const int side = side_in_sweep(sweep->lo(a), sweep->hi(a), sweep->lo(b), sweep->hi(b));
      if (side == 0) throw Meeting{a, b};
      return side > 0;
    }
  };
  struct Test {
    const CycleSweep* sweep;
    void operator()(std::uint32_t a, std::uint32_t b) const { sweep->test(a, b); }
  };

  std::size_t next(std::size_t e) const { return e + 1 == cycle_.size() ? 0 : e + 1; }
  const P& lo(std::uint32_t e) const { return forward_[e] ? cycle_[e] : cycle_[next(e)]; }
  const P& hi(std::uint32_t e) const { return forward_[e] ? cycle_[next(e)] : cycle_[e]; }

  // At vertex v its edge that ends here leaves the order before the one that starts here joins it,
  // tried first at the place the other left (or, at a vertex where both start, beside the first).
  void visit(std::uint32_t v) {
    const std::uint32_t edges[2] = {v == 0 ? static_cast<std::uint32_t>(cycle_.size() - 1) : v - 1, v};
    std::optional<typename Status::Place> place;
    for (const std::uint32_t e : edges)
      if (&hi(e) == &cycle_[v]) place = active_.remove(e);
    for (const std::uint32_t e : edges)
      if (&lo(e) == &cycle_[v]) place = active_.insert(e, place);
  }
  // Edges that share a vertex meet only there (no fold-backs, distinct points); others must not meet.
  void test(std::uint32_t a, std::uint32_t b) const {
    if (next(a) == b || next(b) == a) return;
    if (closed_segments_meet(lo(a), hi(a), lo(b), hi(b))) throw Meeting{a, b};
  }

  const std::vector<P>& cycle_;
  const std::vector<std::uint32_t>& order_;
  using Status = SweepStatus<Below, Test>;
  std::vector<bool> forward_;  // cycle[e] < cycle[next(e)]
  Status active_;
};

}  // namespace pd
