// Geodesics (shortest paths inside a simple polygon) between points of its boundary, for chazelle-dobkin's
// test of "XY lies in P" between two loose rays (docs/algorithms/chazelle-dobkin.md, (7)), and for
// both Chazelle-Dobkin programs' views across the notches (engines/chazelle_dobkin/patterns.h): how each
// geodesic leaves its root (its first turn) and whether a straight one touches the boundary.
//
// Method: the funnel walk of Lee and Preparata ("Euclidean shortest paths in the presence of
// rectilinear barriers", Networks 14, 1984) and of Guibas, Hershberger, Leven, Sharir and Tarjan
// ("Linear-time algorithms for visibility and shortest path problems inside triangulated simple
// polygons", Algorithmica 2, 1987, Sec. 2), over a convex decomposition with O(r) faces in place of a
// triangulation with n - 2, so that a tree costs O(s log r) for the s sites below (O(r log r) for
// chazelle-dobkin's O(r) terminals) instead of O(n).
//
// The decomposition (vertical chords from every notch: at most 2r chords and 2r + 1 convex faces whose
// dual graph is a tree, built in O(n + r^2 log n + s log s)), the funnel walk over it (one array of
// funnel vertices, each window's two ends restored when its subtree is done) and what a path that
// turns only at notches records: docs/algorithms/geodesics.md.
//
// Exact: every decision is an orientation of three points, taken with CGAL's filtered predicate when
// all three are in doubles, else on intervals and, when they do not settle it, on exact rationals (a
// chord's far end, the root or a terminal may be a rational point inside an edge); a tie in a funnel
// search compares positions along a line exactly.
#pragma once

#include "core/filtered.h"
#include "core/geometry.h"
#include "engines/search/boundary_chains.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
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

// A funnel: points F[lo..hi], from the left end of a window (F[lo]) through the apex F[apex] to its right
// end (F[hi]), left and right as seen from the apex (the left end counter-clockwise from the right end);
// the chains from the apex to the ends are the shortest paths to them. For a point c beyond the window or
// on it, the index of the funnel vertex from which the shortest path reaches c in a straight line: the
// last vertex of the path from the apex's root to c before c (of two on one line with c, the nearer).
// Searched from `guess` (first_holding); adds the orientations taken to `steps`.
std::size_t funnel_tangent(const std::vector<const FilteredPoint*>& F, std::size_t lo, std::size_t hi, std::size_t apex,
                           const FilteredPoint& c, std::size_t guess, std::int64_t& steps);

class GeodesicTrees {
 public:
  using Terminal = boundary::SegmentSearch::Contact;  // a vertex (at_vertex) or a point inside an edge

  // Pre: p simple and counter-clockwise, every terminal on its boundary. Builds the decomposition.
  GeodesicTrees(const Polygon& p, const std::vector<Terminal>& terminals);
  GeodesicTrees(const GeodesicTrees&) = delete;
  GeodesicTrees& operator=(const GeodesicTrees&) = delete;

  // Replaces `out` with the geodesic from terminal `from` to terminal `to`: its first point, the vertices
  // where it turns in order, and its last point (only `to`'s point when the two coincide). The tree
  // rooted at `to` is built the first time it is needed, O(s log r); then O(length).
  void path(std::size_t from, std::size_t to, std::vector<const FilteredPoint*>& out);
  // The terminal's point; terminals at one point, and a terminal at a notch and the notch, share one
  // point object.
  const FilteredPoint& point(std::size_t terminal) const { return sites_[site_of_terminal_[terminal]].point; }

  // How the geodesic from terminal `from` to terminal `to` leaves `from`: towards `toward`, the first
  // point where it turns, or `to` when it runs straight (vertex `toward.edge` when at_vertex); `clear`
  // when it runs straight and its open segment lies in P's interior (touches no point of the boundary).
  // Builds the tree rooted at `from` the first time, then O(1).
  struct Start {
    Terminal toward;
    bool clear;
  };
  Start start(std::size_t from, std::size_t to);

  std::int64_t chords() const { return static_cast<std::int64_t>(chords_.size()); }
  std::int64_t trees() const { return trees_; }
  std::int64_t faces_entered() const { return faces_entered_; }
  std::int64_t tangent_steps() const { return tangent_steps_; }

 private:
  static constexpr std::uint32_t kUnset = UINT32_MAX;
  // A point of the boundary that matters, in order along the boundary from vertex 0: a vertex, or a
  // point inside edge (edge, edge + 1).
  struct Site {
    Terminal place;
    FilteredPoint point;  // place.point, for the filtered orientations
  };
  // One side of a face's boundary, counter-clockwise: from site `from` to site `to`, along a chord or
  // (chord < 0) along the boundary of P.
  struct Step {
    std::uint32_t from, to;
    std::int32_t chord;
  };
  // Where chord c lies on the boundary of the face on each of its sides: faces[k], steps[k].
  struct ChordSides {
    std::array<std::uint32_t, 2> faces{}, steps{};
  };
  // A face entered through its step `step` with the funnel F[lo..hi]; entering first sets F[lo] and
  // F[hi] to the chord's ends when `write_lo`, `write_hi`. A restore only sets F[lo] back to site
  // `hi` once the subtree of the window that changed it is done.
  struct Window {
    std::uint32_t face, step, lo, hi, apex;
    bool write_lo, write_hi, restore;
  };

  // Per root (a site) and site: the last turn before the site on its geodesic from the root (a site,
  // or the root), the first turn after the root (or the site itself when none), and whether it runs
  // straight with its open segment inside P's interior.
  struct Tree {
    std::vector<std::uint32_t> turn, first;
    std::vector<char> clear;
  };

  void add_chords(const Polygon& p);
  void sort_sites();
  void build_faces();
  std::vector<Step> inner_face(std::uint32_t i, std::uint32_t j, std::int32_t chord);
  const Tree& tree(std::uint32_t root);
  void build(std::uint32_t root, Tree& tree);
  bool straight_arc(std::uint32_t a, std::uint32_t b) const;
  void mark_seen_directly(std::uint32_t face, Tree& tree) const;
  void enter(const Window& w, Tree& tree);
  void reach(std::uint32_t site, std::uint32_t from, Tree& tree) const;
  void set_funnel_entry(std::size_t at, std::uint32_t site);

  const Polygon& p_;
  // Before sort_sites: one site per notch, chord end and terminal; after it, the distinct ones in order.
  std::vector<Site> sites_;
  std::vector<std::uint32_t> site_of_terminal_;
  std::vector<std::array<std::uint32_t, 2>> chords_;  // site pairs, the smaller first
  std::vector<ChordSides> sides_;
  std::vector<std::vector<Step>> faces_;  // face 0 holds the boundary from the last site to site 0
  std::vector<std::vector<std::uint32_t>> faces_at_site_;
  std::vector<Tree> trees_by_root_;  // by root site
  std::uint32_t root_ = 0;
  // The walk's funnel (sites), its entries as points for funnel_tangent, and its stack.
  std::vector<std::uint32_t> funnel_;
  std::vector<const FilteredPoint*> funnel_points_;
  std::vector<Window> stack_;
  std::int64_t trees_ = 0, faces_entered_ = 0, tangent_steps_ = 0;
};

}  // namespace pd
