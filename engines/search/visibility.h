// Visibility from polygon vertices, shared by the minimum convex decomposition programs (greene-dp,
// keil, keil-snoeyink, keil-snoeyink-reduced, min-ink).
//
// A diagonal of p is a segment between two vertices whose relative interior lies strictly inside p; it
// never passes through a vertex. The programs need, for a vertex v, every u such that vu is an edge or
// a diagonal, in counter-clockwise order around v, which by Keil & Snoeyink's Observation 1 (001,
// Sec. 2) is the order of (u - v) mod n.
//
// Method: p is triangulated once (monotone partition and monotone triangulation, O(n log n)); the
// visible vertices of v are then found by walking the triangulation outwards from the triangles at v,
// carrying the open cone of directions from v that still reach the current triangle. The dual of a
// triangulation of a simple polygon is a tree, so a walk from v enters each triangle at most once: O(n)
// per vertex, O(n r) for the r reflex vertices, in place of Joe and Simpson's linear-time visibility
// polygon. The cone is bounded by rays through vertices, so every test is the exact `orient` on input
// points: no point is constructed. A vertex on a cone boundary ray is not visible (the segment would
// pass through the vertex that bounds the cone).
#pragma once

#include "core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pd {

class VisibilityGraph {
 public:
  // Triangulates p: O(n log n). Pre: simple, counter-clockwise; collinear vertices allowed.
  explicit VisibilityGraph(const Polygon& p);

  // Appends to `out` every u != v such that vu is an edge or a diagonal of p, in counter-clockwise order
  // around v (increasing (u - v) mod n). O(n). Adds the number of triangles entered to `triangles`.
  // With `seen`, also appends, for each two consecutive vertices appended to `out`, the polygon edge
  // (by its first vertex e, the edge from e to e + 1) that v sees strictly between them: between two
  // consecutive visible vertices the visible boundary is part of one edge, where the walk's cone ends.
  void visible_from(std::size_t v, std::vector<std::uint32_t>& out, std::int64_t& triangles,
                    std::vector<std::uint32_t>* seen = nullptr) const;

 private:
  std::size_t offset(std::size_t from, std::size_t to) const { return (to + n_ - from) % n_; }
  void sort_rows();
  void link_twins();

  const Polygon& p_;
  std::size_t n_;
  // Each vertex's triangulation neighbours (edges and diagonals) in counter-clockwise order: row v is
  // target_[start_[v] .. start_[v+1]). twin_[h] is the slot of the reverse half-edge.
  std::vector<std::uint32_t> start_, target_, twin_;
};

}  // namespace pd
