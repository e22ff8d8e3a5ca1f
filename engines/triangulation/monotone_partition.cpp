// The y-monotone partition by plane sweep, the method of `y-monotone` (its paper, bounds and
// guarantees: algorithms/y_monotone.cpp), and the first step of `monotone`, `greene-sweep` and
// `hertel-mehlhorn`.
//
// The sweep runs from top to bottom in the order `above` (y, then x; see monotone.h), which settles
// horizontal edges and equal heights the way de Berg et al. do. A collinear vertex has one neighbour
// above and one below in that order, so it is a regular vertex. The status is a balanced search tree
// (std::set) of the edges with the interior on their right, ordered left to right along the sweep
// line; edges are compared with orient() at the height of the lower of their two upper endpoints, and
// a vertex is located with orient() against the edges: no intersection point is ever computed.
//
// The hot loop is locating vertices in the status (split, merge and right-chain vertices, and the
// insertions). A vertex first tries the edge found at its upper neighbour (or inserted there, or what
// replaced that edge since), and an insertion the place last located: two orientations confirm a
// guess (the vertex lies right of the edge and left of its successor), where a search takes log n of
// them; on a comb every tooth's lookups are answered so. The events are ordered by a merge sort:
// introsort falls back to heapsort on comb-like polygons' order.
#include "engines/triangulation/monotone.h"

#include <algorithm>
#include <cstdint>
#include <memory_resource>
#include <set>
#include <vector>

namespace pd {
namespace {

enum class VertexType : std::uint8_t { Start, End, Split, Merge, LeftChain, RightChain };

// A vertex as the sweep meets it.
struct Probe {
  const Point* point;
};

// Orders status edges left to right along the sweep line. Edge e runs down from vertex e to vertex
// e+1 (the interior on its right, east of it), so orient(e, e+1, q) > 0 says q is right of e.
struct LeftToRight {
  using is_transparent = void;
  const Polygon* p;
  std::int64_t* comparisons;

  int side(std::uint32_t e, const Point& q) const {
    ++*comparisons;
    return orient((*p)[e], (*p)[p->next(e)], q);
  }
  // Both edges cross the sweep line at the lower of their upper endpoints; test that one against the
  // other edge. It is never on the other edge: the polygon is simple.
  bool operator()(std::uint32_t e, std::uint32_t f) const {
    if (above((*p)[e], (*p)[f])) return side(e, (*p)[f]) > 0;
    return side(f, (*p)[e]) < 0;
  }
  bool operator()(std::uint32_t e, Probe q) const { return side(e, *q.point) > 0; }
  bool operator()(Probe q, std::uint32_t e) const { return side(e, *q.point) < 0; }
};

class MonotoneSweep {
 public:
  explicit MonotoneSweep(const Polygon& p)
      : p_(p),
        n_(p.size()),
        type_(n_),
        helper_(n_),
        left_of_(n_, kNone),
        replaced_by_(n_, kNone),
        active_(n_, 0),
        handle_(n_),
        status_(LeftToRight{&p, &comparisons_}, &pool_) {}

  std::vector<Cut> run(Counters& counters) {
    for (std::uint32_t v = 0; v < n_; ++v) type_[v] = classify(v);
    for (std::uint32_t v : events()) handle(v);
    counters["tree_operations"] = tree_operations_;
    counters["tree_comparisons"] = comparisons_;
    return std::move(diagonals_);
  }

 private:
  using Status = std::pmr::set<std::uint32_t, LeftToRight>;
  static constexpr std::uint32_t kNone = UINT32_MAX;
  static constexpr int kChase = 4;  // replacements a guess follows before the search takes over

  // Start/end: both neighbours below/above and a convex angle; split/merge: the same with a reflex
  // angle. Otherwise the boundary descends (left chain, interior to the right) or ascends.
  VertexType classify(std::uint32_t v) const {
    const Point &a = p_[p_.prev(v)], &b = p_[v], &c = p_[p_.next(v)];
    const bool prev_above = above(a, b), next_above = above(c, b);
    if (prev_above && next_above) return orient(a, b, c) > 0 ? VertexType::End : VertexType::Merge;
    if (!prev_above && !next_above) return orient(a, b, c) > 0 ? VertexType::Start : VertexType::Split;
    return prev_above ? VertexType::LeftChain : VertexType::RightChain;
  }

  // Vertex indices from top to bottom; sorting the coordinates themselves keeps the sort in cache.
  std::vector<std::uint32_t> events() const {
    struct Key {
      double y, x;
      std::uint32_t v;
    };
    std::vector<Key> keys(n_);
    for (std::uint32_t v = 0; v < n_; ++v) keys[v] = {p_[v].y(), p_[v].x(), v};
    std::stable_sort(keys.begin(), keys.end(),
                     [](const Key& a, const Key& b) { return a.y > b.y || (a.y == b.y && a.x < b.x); });
    std::vector<std::uint32_t> order(n_);
    for (std::uint32_t k = 0; k < n_; ++k) order[k] = keys[k].v;
    return order;
  }

  void handle(std::uint32_t v) {
    const std::uint32_t incoming = static_cast<std::uint32_t>(p_.prev(v));  // edge prev(v) -> v
    switch (type_[v]) {
      case VertexType::Start:
        insert(v);
        break;
      case VertexType::End:
        connect_if_merge(v, incoming);
        erase(incoming);
        break;
      case VertexType::Split: {
        const std::uint32_t e = edge_left_of(v);
        diagonals_.push_back({v, helper_[e]});
        helper_[e] = v;
        insert(v);
        break;
      }
      case VertexType::Merge: {
        connect_if_merge(v, incoming);
        erase(incoming);
        const std::uint32_t e = edge_left_of(v);
        connect_if_merge(v, e);
        helper_[e] = v;
        break;
      }
      case VertexType::LeftChain:
        connect_if_merge(v, incoming);
        replace(incoming, v);
        break;
      case VertexType::RightChain: {
        const std::uint32_t e = edge_left_of(v);
        connect_if_merge(v, e);
        helper_[e] = v;
        break;
      }
    }
  }

  void connect_if_merge(std::uint32_t v, std::uint32_t e) {
    if (type_[helper_[e]] == VertexType::Merge) diagonals_.push_back({v, helper_[e]});
  }

  // A start or split vertex's edge goes in just right of the edge last located, where the sweep often
  // still is (a comb's teeth, left to right); std::set checks a hint and searches when it is wrong.
  void insert(std::uint32_t e) {
    ++tree_operations_;
    handle_[e] = last_located_ != kNone && active_[last_located_]
                     ? status_.insert(std::next(handle_[last_located_]), e)
                     : status_.insert(e).first;
    active_[e] = 1;
    helper_[e] = e;
  }

  void erase(std::uint32_t e) {
    ++tree_operations_;
    status_.erase(handle_[e]);
    active_[e] = 0;
  }

  // On a left-chain vertex the outgoing edge takes the incoming edge's place in the order, so the
  // erased position is the insertion hint (amortised constant time).
  void replace(std::uint32_t old_edge, std::uint32_t new_edge) {
    tree_operations_ += 2;
    const auto next = status_.erase(handle_[old_edge]);
    active_[old_edge] = 0;
    replaced_by_[old_edge] = new_edge;
    handle_[new_edge] = status_.insert(next, new_edge);
    active_[new_edge] = 1;
    helper_[new_edge] = new_edge;
  }

  // The status edge directly left of vertex v. Called only where the interior lies just left of v on
  // the sweep line (split, merge and right-chain vertices), so a left boundary edge is there. Its
  // upper neighbour next(v) is tried first: the edge it inserted (a start vertex), or the one it found,
  // or what replaced that edge since, when its left chain went on.
  std::uint32_t edge_left_of(std::uint32_t v) {
    ++tree_operations_;
    const std::uint32_t up = static_cast<std::uint32_t>(p_.next(v));
    std::uint32_t guess = type_[up] == VertexType::Start ? up : left_of_[up];
    for (int step = 0; guess != kNone && !active_[guess] && step < kChase; ++step) guess = replaced_by_[guess];
    if (guess == kNone || !active_[guess] || !directly_left(guess, p_[v]))
      guess = *std::prev(status_.lower_bound(Probe{&p_[v]}));
    return left_of_[v] = last_located_ = guess;
  }

  // Whether status edge e is the last one left of q: q is right of e and not right of e's successor.
  bool directly_left(std::uint32_t e, const Point& q) {
    const LeftToRight& left_to_right = status_.key_comp();
    if (!left_to_right(e, Probe{&q})) return false;
    const auto successor = std::next(handle_[e]);
    return successor == status_.end() || !left_to_right(*successor, Probe{&q});
  }

  const Polygon& p_;
  std::uint32_t n_;
  std::vector<VertexType> type_;
  std::vector<std::uint32_t> helper_;
  std::vector<std::uint32_t> left_of_;      // the status edge found directly left of a located vertex
  std::vector<std::uint32_t> replaced_by_;  // the edge that took a left-chain edge's place in the status
  std::vector<std::uint8_t> active_;        // whether an edge is in the status
  std::vector<Status::iterator> handle_;
  std::uint32_t last_located_ = kNone;
  std::int64_t comparisons_ = 0, tree_operations_ = 0;
  std::pmr::unsynchronized_pool_resource pool_;  // the status's nodes: an erase hands its node to an insert
  Status status_;
  std::vector<Cut> diagonals_;
};

}  // namespace

std::vector<Cut> y_monotone_diagonals(const Polygon& p, Counters& counters) { return MonotoneSweep(p).run(counters); }

}  // namespace pd
