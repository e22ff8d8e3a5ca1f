// Geodesics (shortest paths inside a simple polygon) between points of its boundary, for chazelle-dobkin's
// test of "XY lies in P" between two loose rays (algorithms/chazelle_dobkin_cubic.cpp, (7)).
//
// Method: the funnel walk of Lee and Preparata ("Euclidean shortest paths in the presence of
// rectilinear barriers", Networks 14, 1984) and of Guibas, Hershberger, Leven, Sharir and Tarjan
// ("Linear-time algorithms for visibility and shortest path problems inside triangulated simple
// polygons", Algorithmica 2, 1987, Sec. 2), over the triangulation that VisibilityGraph already has.
// From a root s, every triangle is entered once, through a window (a diagonal); the shortest paths
// from s to the points of the window form a funnel: two concave chains from an apex to the window's
// ends. The third vertex c of the triangle beyond is reached from the funnel vertex whose wedge holds
// it, and the funnel splits there into the funnels of the triangle's two other sides. That vertex is
// searched from both ends of the funnel at once (first_holding_from_ends), so a split into parts of
// sizes a and b costs O(1 + log min(a, b)) orientations and the whole walk O(n), as with the finger
// search trees of Guibas et al. The funnel lives in one array, where a child changes one entry,
// restored when its subtree is done (a depth-first walk with an explicit stack). The tree keeps, for
// every vertex of the triangles it enters and every terminal inside an edge (found by the same search
// in the funnel of the edge's triangle, O(log n) each), the last vertex before it where its geodesic
// turns, or the root: O(n + terminals log n) per root, O(n) space. The walk enters a window
// only when a terminal lies beyond it (counted once for all roots over the dual tree, O(n)): the
// geodesics to the terminals cross only the triangles between, and every vertex of those is reached.
//
// Turns only: a geodesic that passes straight through a vertex (collinear with the points before and
// after it) does not list it, so a path has O(r) points, the notches where it turns and its two ends.
// Its first point after a start X in P lies on the ray along which it leaves X, at or beyond the first
// point of the boundary that it meets.
//
// Exact: every decision is an orientation of three points, taken with CGAL's filtered predicate when
// all three are in doubles, else on intervals and, when they do not settle it, on exact rationals (a
// root or a terminal may be a rational point inside an edge); a tie in a funnel search compares
// positions along a line exactly.
#pragma once

#include "algorithms/boundary_chains.h"
#include "algorithms/visibility.h"
#include "core/filtered.h"
#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pd {

// The first k in (a, b] where `at` holds, given that it fails at a and holds at b: bisection.
template <class At>
std::ptrdiff_t bisect(std::ptrdiff_t a, std::ptrdiff_t b, const At& at) {
  while (b - a > 1) {
    const std::ptrdiff_t mid = a + (b - a) / 2;
    if (at(mid)) b = mid;
    else a = mid;
  }
  return b;
}

// The first k in [lo, hi] where `holds` is true, for a predicate false before some index and true from
// it on (and taken as true at hi): galloping from `guess` towards the answer, then bisecting, so
// O(1 + log(1 + |k - guess|)) calls. Over a sequence of searches whose answers move one way, each from
// the last answer, the calls add up to O(searches + hi - lo).
template <class Holds>
std::size_t first_holding(std::size_t lo, std::size_t hi, std::size_t guess, const Holds& holds) {
  const auto at = [&](std::ptrdiff_t k) { return k >= static_cast<std::ptrdiff_t>(hi) || holds(static_cast<std::size_t>(k)); };
  const std::ptrdiff_t first = static_cast<std::ptrdiff_t>(lo);
  std::ptrdiff_t a, b;  // at(a) false (or a = first - 1), at(b) true
  const std::ptrdiff_t g = static_cast<std::ptrdiff_t>(std::clamp(guess, lo, hi));
  if (at(g)) {
    b = g;
    for (std::ptrdiff_t step = 1;; step *= 2) {
      a = b - step;
      if (a < first) {
        a = first - 1;
        break;
      }
      if (!at(a)) break;
      b = a;
    }
  } else {
    a = g;
    for (std::ptrdiff_t step = 1;; step *= 2) {
      b = a + step;
      if (b >= static_cast<std::ptrdiff_t>(hi) || at(b)) {
        b = std::min(b, static_cast<std::ptrdiff_t>(hi));
        break;
      }
      a = b;
    }
  }
  return static_cast<std::size_t>(bisect(a, b, at));
}

// The same answer, galloping inwards from both ends in turn, then bisecting: O(1 + log(1 + min(k - lo,
// hi - k))) calls. A walk that splits a list of m entries at the answer into two of sizes a + b = m + O(1)
// (and so on in each part) then makes O(m + splits) calls in all, whatever the answers: with the
// potential 2m - log2 m per list, a split's log2 min(a, b) is paid by the potential's drop plus O(1) (the
// finger-search argument of Guibas, Hershberger, Leven, Sharir and Tarjan 1987, Sec. 2).
template <class Holds>
std::size_t first_holding_from_ends(std::size_t lo, std::size_t hi, const Holds& holds) {
  const std::ptrdiff_t first = static_cast<std::ptrdiff_t>(lo) - 1, last = static_cast<std::ptrdiff_t>(hi);
  std::ptrdiff_t a = first, b = last;  // holds fails at a (or a = lo - 1) and holds at b (or b = hi)
  for (std::ptrdiff_t step = 1; b - a > 1; step *= 2) {
    const std::ptrdiff_t from_left = first + step, from_right = last - step;
    if (from_left >= b && from_right <= a) break;  // both gallops have passed the bracket
    if (from_left < b) {
      if (holds(static_cast<std::size_t>(from_left))) {
        b = from_left;
        break;
      }
      a = from_left;
    }
    if (from_right > a && from_right < b) {
      if (!holds(static_cast<std::size_t>(from_right))) {
        a = from_right;
        break;
      }
      b = from_right;
    }
  }
  return static_cast<std::size_t>(bisect(a, b, [&](std::ptrdiff_t k) { return holds(static_cast<std::size_t>(k)); }));
}

// A funnel: points F[lo..hi], from the left end of a window (F[lo]) through the apex F[apex] to its right
// end (F[hi]), left and right as seen from the apex (the left end counter-clockwise from the right end);
// the chains from the apex to the ends are the shortest paths to them. For a point c beyond the window or
// on it, the index of the funnel vertex from which the shortest path reaches c in a straight line: the
// last vertex of the path from the apex's root to c before c (of two on one line with c, the nearer).
// Searched from `guess` (first_holding), or from both ends at once without one (first_holding_from_ends);
// adds the orientations taken to `steps`.
std::size_t funnel_tangent(const std::vector<const FilteredPoint*>& F, std::size_t lo, std::size_t hi, std::size_t apex,
                           const FilteredPoint& c, std::optional<std::size_t> guess, std::int64_t& steps);

class GeodesicTrees {
 public:
  using Terminal = boundary::SegmentSearch::Contact;  // a vertex (at_vertex) or a point inside an edge

  // Pre: p simple and counter-clockwise, `triangulation` built on it, every terminal on its boundary.
  GeodesicTrees(const Polygon& p, const VisibilityGraph& triangulation, const std::vector<Terminal>& terminals);
  GeodesicTrees(const GeodesicTrees&) = delete;
  GeodesicTrees& operator=(const GeodesicTrees&) = delete;

  // Replaces `out` with the geodesic from terminal `from` to terminal `to`: its first point, the vertices
  // where it turns in order, and its last point (only `to`'s point when the two coincide). The tree
  // rooted at `to` is built the first time it is needed, O(n + terminals * log n); then O(length).
  void path(std::size_t from, std::size_t to, std::vector<const FilteredPoint*>& out);
  // The terminal's point; a terminal at a vertex shares the vertex's point object.
  const FilteredPoint& point(std::size_t terminal) const;

  std::int64_t trees() const { return trees_; }
  std::int64_t triangles() const { return triangles_; }
  std::int64_t tangent_steps() const { return tangent_steps_; }

 private:
  static constexpr std::uint32_t kUnset = UINT32_MAX;
  // Per vertex and per terminal, the last turn before it on its geodesic: a vertex id, or the root's
  // (edge_root_id_ for a root inside an edge).
  struct Tree {
    std::vector<std::uint32_t> vertex_turn, terminal_turn;
  };
  // One window of the walk: the half-edge right end -> left end (as seen from the root) and the funnel
  // F[lo..hi] with its apex; entering it first sets F[write_at] (a new end) to `id`. A window whose slot
  // is kRestore only sets F[write_at] back to `id`, once the subtree of the window that changed it is
  // done.
  struct Window {
    std::uint32_t slot, lo, hi, apex, write_at, id;
  };
  static constexpr std::uint32_t kRestore = UINT32_MAX;

  void mark_windows_towards_terminals();
  std::array<std::uint32_t, 3> triangle_slots(std::uint32_t h) const;
  void build(std::size_t root);
  void start_at_vertex(std::size_t v, Tree& tree);
  void start_inside_edge(std::size_t root, Tree& tree);
  void walk(const Window& first, Tree& tree);
  void reach_edge(std::size_t edge, const Window& w, Tree& tree);
  std::size_t tangent(const Window& w, const FilteredPoint& c);
  std::uint32_t last_turn(std::uint32_t reached_from, const FilteredPoint& c, const Tree& tree) const;
  void set_funnel_entry(std::size_t at, std::uint32_t id);
  const FilteredPoint& point_of(std::uint32_t id) const { return id == edge_root_id_ ? *root_point_ : vertices_[id]; }
  // The funnel array's middle, where each walk starts: a walk adds at most one entry on either side per
  // triangle, at most n - 2 of them.
  std::uint32_t funnel_middle() const { return static_cast<std::uint32_t>(p_.size() + 3); }

  const Polygon& p_;
  const VisibilityGraph& triangulation_;
  std::vector<Terminal> terminals_;
  std::vector<FilteredPoint> vertices_, edge_points_;  // edge_points_: per terminal, used inside edges
  std::vector<std::vector<std::uint32_t>> terminals_on_edge_;  // per edge, its terminals inside it
  // Per half-edge slot, whether a terminal (a vertex, counted in the triangle on its forward edge, or
  // a point inside an edge) lies in the part of the triangulation beyond it, on its right.
  std::vector<char> towards_terminal_;
  std::vector<Tree> trees_by_root_;
  std::vector<char> built_;
  const std::uint32_t edge_root_id_;  // the id of a root inside an edge
  std::uint32_t root_id_ = 0;         // the id of the root being walked
  // The walk's funnel (ids), its entries as points for funnel_tangent, and the root being walked.
  std::vector<std::uint32_t> funnel_;
  std::vector<const FilteredPoint*> funnel_points_;
  std::vector<Window> stack_;
  const FilteredPoint* root_point_ = nullptr;
  std::int64_t trees_ = 0, triangles_ = 0, tangent_steps_ = 0;
};

}  // namespace pd
