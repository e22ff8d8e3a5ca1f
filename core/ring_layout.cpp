// The layout sweep of core/ring_layout.h, the sweep of core/sweep.h over the edges of every ring.
// Edges of one ring are not tested when each ring is known to be simple; otherwise (the one sweep of
// rings_and_layout_pass) all but a ring's adjacent edges are, which meet at their common vertex only.
// The nesting of the rings is read at each ring's leftmost vertex from the active edge just below it:
// the polygon's interior lies to the left of every edge, so the region just above that edge is inside
// a part exactly when the edge runs rightwards.
#include "core/ring_layout.h"
#include "core/sweep.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace pd {
namespace {

struct Edge {
  Point lo, hi;  // lo < hi lexicographically
  std::uint32_t part, ring, from;
  bool rightwards;  // from -> next(from) runs from lo to hi
};

// Two edges that meet, found while ordering or testing neighbours.
struct Meet {
  std::uint32_t a, b;
};

// Bottom-to-top order of active edges, decided where the later of the two starts. Active edges that
// do not meet are ordered consistently; a pair that the order cannot separate meets.
struct Below {
  const std::vector<Edge>* edges;
  bool operator()(std::uint32_t a, std::uint32_t b) const {
    if (a == b) return false;
    const Edge &e = (*edges)[a], &f = (*edges)[b];
    const int side = side_in_sweep(e.lo, e.hi, f.lo, f.hi);
    if (side == 0) throw Meet{a, b};
    return side > 0;
  }
};

std::size_t vertex_count(const std::vector<const Polygon*>& parts) {
  std::size_t n = 0;
  for (const Polygon* p : parts) n += p->size();
  return n;
}

class LayoutSweep {
 public:
  LayoutSweep(const std::vector<const Polygon*>& parts, bool rings_too)
      : parts_(parts), rings_too_(rings_too), active_(vertex_count(parts), Below{&edges_}, Test{this}) {
    for (std::uint32_t q = 0; q < parts.size(); ++q) {
      offset_.push_back(static_cast<std::uint32_t>(edges_.size()));
      const Polygon& p = *parts[q];
      for (std::uint32_t i = 0; i < p.size(); ++i) {
        const Point &a = p[i], &b = p[p.next(i)];
        edges_.push_back({std::min(a, b), std::max(a, b), q, static_cast<std::uint32_t>(p.ring_of(i)), i, a < b});
      }
      for (std::size_t k = 0; k < p.ring_count(); ++k) {
        std::size_t lowest = p.ring_begin(k);
        for (std::size_t i = lowest; i < p.ring_end(k); ++i) lowest = p[i] < p[lowest] ? i : lowest;
        leftmost_.push_back(offset_[q] + static_cast<std::uint32_t>(lowest));
      }
    }
    std::sort(leftmost_.begin(), leftmost_.end());
    outer_started_.assign(parts.size(), false);
  }

  std::string fault() {
    std::vector<std::uint32_t> order(edges_.size());
    std::iota(order.begin(), order.end(), 0);
    // A merge sort, as for a ring's own check (core/polygon.cpp): introsort falls back to heapsort on
    // the organ-pipe x order of a monotone ring.
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return point(a) < point(b); });
    for (std::size_t k = 1; k < order.size(); ++k)
      if (point(order[k - 1]) == point(order[k]))
        return vertex_name(order[k - 1]) + " coincides with " + vertex_name(order[k]);
    try {
      for (const std::uint32_t v : order) visit(v);
    } catch (const Meet& m) {
      return meeting(m);
    }
    return nesting_fault_;
  }

 private:
  const Point& point(std::uint32_t v) const { return (*parts_[edges_[v].part])[edges_[v].from]; }
  std::uint32_t in_edge(std::uint32_t v) const {
    const Edge& e = edges_[v];
    return offset_[e.part] + static_cast<std::uint32_t>(parts_[e.part]->prev(e.from));
  }

  // Vertex v: the edges ending there leave the order, then the edges starting there join it, tried
  // first where the others left or went in (SweepStatus).
  void visit(std::uint32_t v) {
    const Point& p = point(v);
    const std::uint32_t ends[2] = {in_edge(v), v};
    std::optional<SweepStatus<Below, Test>::Place> place;
    for (const std::uint32_t e : ends)
      if (edges_[e].hi == p) place = active_.remove(e);
    for (const std::uint32_t e : ends)
      if (edges_[e].lo == p) place = active_.insert(e, place);
    if (std::binary_search(leftmost_.begin(), leftmost_.end(), v)) check_nesting(v, ends[0], ends[1]);
  }

  void test(std::uint32_t a, std::uint32_t b) const {
    const Edge &e = edges_[a], &f = edges_[b];
    if (e.part == f.part && e.ring == f.ring && (!rings_too_ || adjacent(e, f))) return;
    if (closed_segments_meet(e.lo, e.hi, f.lo, f.hi)) throw Meet{a, b};
  }
  bool adjacent(const Edge& e, const Edge& f) const {
    const Polygon& p = *parts_[e.part];
    return p.next(e.from) == f.from || p.next(f.from) == e.from;
  }

  // At a ring's leftmost vertex: the edge just below tells which region the ring starts in.
  void check_nesting(std::uint32_t v, std::uint32_t in, std::uint32_t out) {
    const Edge& me = edges_[v];
    const std::uint32_t lower = Below{&edges_}(in, out) ? in : out;
    const std::optional<std::uint32_t> below = active_.below(lower);
    const bool any_below = below.has_value();
    const Edge& e = edges_[below.value_or(lower)];  // meaningful only when any_below
    if (me.ring == 0) {
      outer_started_[me.part] = true;
      if (any_below && e.rightwards)
        note("part " + std::to_string(me.part) + " lies inside part " + std::to_string(e.part));
      return;
    }
    const std::string hole = ring_name(me.part, me.ring);
    if (!outer_started_[me.part] || !any_below) return note(hole + " is not inside " + ring_name(me.part, 0));
    if (e.part == me.part) {
      if (e.rightwards) return;
      note(e.ring == 0 ? hole + " is not inside " + ring_name(me.part, 0) : hole + " lies inside " + ring_name(e.part, e.ring));
    } else {
      note(e.rightwards ? hole + " lies inside part " + std::to_string(e.part)
                        : hole + " lies outside its outer ring or inside another of its holes");
    }
  }

  void note(const std::string& why) {
    if (nesting_fault_.empty()) nesting_fault_ = why;
  }

  std::string ring_name(std::uint32_t part, std::uint32_t ring) const {
    const std::string of = parts_.size() > 1 ? "part " + std::to_string(part) + "'s " : "the ";
    return ring == 0 ? of + "outer ring" : (parts_.size() > 1 ? of : "") + "hole " + std::to_string(ring);
  }
  // A vertex's index in its ring's input (file order).
  std::size_t local(std::uint32_t part, std::size_t i) const {
    const Polygon& p = *parts_[part];
    return p.input_index(i) - p.input_index(p.ring_begin(p.ring_of(i)));
  }
  std::string vertex_name(std::uint32_t v) const {
    const Edge& e = edges_[v];
    return "vertex " + std::to_string(local(e.part, e.from)) + " of " + ring_name(e.part, e.ring);
  }
  std::string edge_name(std::uint32_t g) const {
    const Edge& e = edges_[g];
    const Polygon& p = *parts_[e.part];
    std::size_t a = local(e.part, e.from), b = local(e.part, p.next(e.from));
    if (p.ring_was_reversed(e.ring)) std::swap(a, b);
    return "edge " + std::to_string(a) + "-" + std::to_string(b) + " of " + ring_name(e.part, e.ring);
  }
  std::string meeting(const Meet& m) const {
    const Edge &e = edges_[m.a], &f = edges_[m.b];
    const bool cross = orient(e.lo, e.hi, f.lo) * orient(e.lo, e.hi, f.hi) < 0 &&
                       orient(f.lo, f.hi, e.lo) * orient(f.lo, f.hi, e.hi) < 0;
    const auto [first, second] = std::minmax(m.a, m.b);
    return edge_name(first) + (cross ? " crosses " : " touches ") + edge_name(second);
  }

  const std::vector<const Polygon*>& parts_;
  bool rings_too_;  // test the edges of one ring against one another
  std::vector<Edge> edges_;  // edge offset_[q] + i runs from vertex i of part q to its next
  std::vector<std::uint32_t> offset_;
  std::vector<std::uint32_t> leftmost_;  // each ring's leftmost (lowest-leftmost) vertex, sorted
  struct Test {
    const LayoutSweep* sweep;
    void operator()(std::uint32_t a, std::uint32_t b) const { sweep->test(a, b); }
  };
  SweepStatus<Below, Test> active_;
  std::vector<bool> outer_started_;
  std::string nesting_fault_;
};

}  // namespace

std::string layout_fault(const std::vector<const Polygon*>& parts) { return LayoutSweep(parts, false).fault(); }

bool rings_and_layout_pass(const Polygon& p) { return LayoutSweep({&p}, true).fault().empty(); }

}  // namespace pd
