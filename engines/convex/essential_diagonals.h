// Hertel and Mehlhorn's removal of inessential diagonals, shared by `hertel-mehlhorn` (and its
// variants), `hertel-mehlhorn-greedy` and `greene-sweep`: given a convex decomposition of a polygon by
// diagonals (a triangulation, say), each diagonal in turn is removed unless that would make a reflex
// angle at one of its ends (Keil-Snoeyink (001), Sec. 2). Removing a diagonal only widens angles, so a
// diagonal kept stays essential, and at the end every diagonal is essential: a reflex vertex is
// essential for at most two of them, so at most 2r are left, at most 2r + 1 - h pieces for h holes, at
// most 4 OPT (OPT >= ceil(r/2) + 1 without holes). With holes the pieces stay simple: a face with
// convex angles only is convex, so no removal can leave one wrapped round a hole.
//
// O(n + k) for k diagonals: every vertex's edges in counter-clockwise order as a doubly linked list,
// so that the angle a removal would make at a vertex is read from the diagonal's two neighbours and a
// removal is O(1). Without holes the lists are built without geometric sorting: around a vertex the
// diagonals come in the order of their other ends along the boundary (Keil-Snoeyink, Observation 1),
// so two counting sorts by integer keys order all of them. With holes that order fails (a diagonal may
// end on another ring), and each vertex's diagonals are sorted by angle: O(n + k log k).
#pragma once

#include "core/decomposition.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace pd {
namespace essential {

// The polygon's edges and the diagonals around each vertex, as removable doubly linked lists.
class Rotations {
 public:
  // Half-edges 2k and 2k + 1 are diagonal k from a to b and back; 2m + 2u and 2m + 2u + 1 are the
  // polygon edge (u, next(u)) and back.
  Rotations(const Polygon& p, const std::vector<Cut>& diagonals)
      : n_(p.size()), origin_(2 * (diagonals.size() + n_)), target_(origin_.size()), cw_(origin_.size()),
        ccw_(origin_.size()) {
    for (std::size_t k = 0; k < diagonals.size(); ++k) set_edge(2 * k, diagonals[k].a, diagonals[k].b);
    const std::size_t m = diagonals.size();
    for (std::size_t u = 0; u < n_; ++u) set_edge(2 * (m + u), static_cast<VertexId>(u), static_cast<VertexId>(p.next(u)));
    if (p.hole_count() == 0) link_in_boundary_order();
    else link_by_angle(p, m);
  }

  VertexId origin(std::size_t h) const { return origin_[h]; }
  VertexId target(std::size_t h) const { return target_[h]; }
  // The other ends of the edges just clockwise and just counter-clockwise of half-edge h at its origin.
  VertexId before(std::size_t h) const { return target_[cw_[h]]; }
  VertexId after(std::size_t h) const { return target_[ccw_[h]]; }

  void remove_edge(std::size_t h) {
    unlink(h);
    unlink(h ^ 1);
  }

 private:
  void set_edge(std::size_t h, VertexId a, VertexId b) {
    origin_[h] = a, target_[h] = b;
    origin_[h ^ 1] = b, target_[h ^ 1] = a;
  }

  // Around u, counter-clockwise from the edge to u+1 to the edge to u-1, the other ends come in
  // boundary order u+1, u+2, ..., u-1: sort the half-edges by (origin, offset of the target from the
  // origin along the boundary), two stable counting sorts, and link each origin's run.
  void link_in_boundary_order() {
    auto offset = [&](std::size_t h) { return (target_[h] + n_ - origin_[h]) % n_; };
    std::vector<std::uint32_t> all(origin_.size());
    for (std::size_t h = 0; h < all.size(); ++h) all[h] = static_cast<std::uint32_t>(h);
    all = counting_sort(all, offset);
    all = counting_sort(all, [&](std::size_t h) { return origin_[h]; });
    for (std::size_t k = 0; k + 1 < all.size(); ++k)
      if (origin_[all[k]] == origin_[all[k + 1]]) ccw_[all[k]] = all[k + 1], cw_[all[k + 1]] = all[k];
  }

  // Around u, counter-clockwise: the edge to next(u), the diagonals by angle, the edge to prev(u).
  void link_by_angle(const Polygon& p, std::size_t m) {
    std::vector<std::uint32_t> all(origin_.size());
    for (std::size_t h = 0; h < all.size(); ++h) all[h] = static_cast<std::uint32_t>(h);
    all = counting_sort(all, [&](std::size_t h) { return origin_[h]; });
    for (std::size_t from = 0, to = 0; from < all.size(); from = to) {
      for (to = from; to < all.size() && origin_[all[to]] == origin_[all[from]]; ++to) {
      }
      const VertexId u = origin_[all[from]];
      const Point &centre = p[u], &ray = p[p.next(u)];
      auto rank = [&](std::uint32_t h) {  // 0: the edge to next(u), 1: a diagonal, 2: the edge to prev(u)
        if (h >= 2 * m) return h == 2 * (m + u) ? 0 : 2;
        return 1;
      };
      auto half = [&](std::uint32_t h) { return orient(centre, ray, p[target_[h]]) > 0 ? 0 : 1; };
      std::sort(all.begin() + static_cast<std::ptrdiff_t>(from), all.begin() + static_cast<std::ptrdiff_t>(to),
                [&](std::uint32_t a, std::uint32_t b) {
                  if (rank(a) != rank(b)) return rank(a) < rank(b);
                  if (half(a) != half(b)) return half(a) < half(b);
                  return orient(centre, p[target_[a]], p[target_[b]]) > 0;
                });
      for (std::size_t k = from; k + 1 < to; ++k) ccw_[all[k]] = all[k + 1], cw_[all[k + 1]] = all[k];
    }
  }

  template <class Key>
  std::vector<std::uint32_t> counting_sort(const std::vector<std::uint32_t>& items, Key key) const {
    std::vector<std::size_t> start(n_ + 1, 0);
    for (std::uint32_t h : items) ++start[key(h) + 1];
    for (std::size_t k = 0; k < n_; ++k) start[k + 1] += start[k];
    std::vector<std::uint32_t> sorted(items.size());
    for (std::uint32_t h : items) sorted[start[key(h)]++] = h;
    return sorted;
  }

  void unlink(std::size_t h) {
    ccw_[cw_[h]] = ccw_[h];
    cw_[ccw_[h]] = cw_[h];
  }

  std::size_t n_;
  std::vector<VertexId> origin_, target_;
  std::vector<std::uint32_t> cw_, ccw_;
};

// Removing the diagonal at half-edge h joins the angles on both its sides at its origin u; the joined
// angle runs counter-clockwise from the edge before h to the edge after it, and is reflex exactly when
// that turn is clockwise.
inline bool keeps_convex_at_origin(const Polygon& p, const Rotations& rot, std::size_t h) {
  return orient(p[rot.origin(h)], p[rot.before(h)], p[rot.after(h)]) >= 0;
}

// The diagonals of `diagonals` that are essential once the others have been removed in the given
// order. Pre: the diagonals decompose p into convex pieces. Counts the tests in `tests`.
inline std::vector<Cut> keep_essential(const Polygon& p, const std::vector<Cut>& diagonals, std::int64_t& tests) {
  Rotations rot(p, diagonals);
  std::vector<Cut> kept;
  for (std::size_t k = 0; k < diagonals.size(); ++k) {
    ++tests;
    if (keeps_convex_at_origin(p, rot, 2 * k) && keeps_convex_at_origin(p, rot, 2 * k + 1)) rot.remove_edge(2 * k);
    else kept.push_back(diagonals[k]);
  }
  return kept;
}

// keep_essential as an algorithm's result: the diagonals left, with the triangulation's counters
// (prefixed "triangulation_") and the removal's own.
inline Decomposition removal_result(const Polygon& p, const std::vector<Cut>& diagonals, const Counters& triangulation,
                                    Counters& counters) {
  std::int64_t tests = 0;
  Decomposition d;
  d.cuts = keep_essential(p, diagonals, tests);
  for (const auto& [name, value] : triangulation) counters["triangulation_" + name] = value;
  counters["diagonals"] = static_cast<std::int64_t>(diagonals.size());
  counters["diagonals_removed"] = static_cast<std::int64_t>(diagonals.size() - d.cuts.size());
  counters["essential_tests"] = tests;
  return d;
}

// The diagonals of a triangulation, whichever way it came: its cuts, or (a peer's) its triangles'
// edges that are not polygon edges, each once, in the order the triangles list them. Throws
// std::runtime_error for a triangulation with Steiner points, which no diagonal removal takes.
inline std::vector<Cut> triangulation_diagonals(const Polygon& p, const Decomposition& d) {
  if (!d.steiner.empty()) throw std::runtime_error("the triangulation added Steiner points");
  if (!d.pieces) return d.cuts;
  std::vector<Cut> diagonals;
  for (const Piece& piece : *d.pieces)
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const VertexId a = piece[i], b = piece[(i + 1) % piece.size()];
      if (a < b && p.next(a) != b && p.next(b) != a) diagonals.push_back({a, b});
    }
  return diagonals;
}

}  // namespace essential
}  // namespace pd
