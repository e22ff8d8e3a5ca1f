// Holes joined to the outer ring by bridges, for algorithms that work on one boundary cycle (ear
// clipping): D. Eberly, "Triangulation by Ear Clipping" (Geometric Tools, 2008), Sec. 4-5.
//
// The holes are taken by decreasing largest x. From a hole's rightmost vertex M a ray runs in +x to the
// nearest point I of the cycle built so far; if I is a vertex, that is M's partner; otherwise the
// partner is the endpoint P of I's edge with the larger x, unless a vertex of the cycle lies in the
// closed triangle M, I, P, in which case it is the one making the smallest angle with the ray (the
// nearest of those on one line). The segment from M to its partner is inside the polygon and meets the
// boundary only at its ends (Eberly's argument; holes not yet joined lie at x <= M's, outside the
// triangle), and it becomes two boundary edges of the cycle, walked once each way: the cycle runs
// partner, M, round the hole (clockwise), M again, the partner again. All tests are exact: orient()
// signs on the input doubles, and the rays' crossings compared by their x as exact rationals.
//
// O(n h) for n vertices and h holes (each bridge scans the cycle once). Without holes the cycle is the
// polygon's boundary.
#pragma once

#include "core/decomposition.h"

#include <cstdint>
#include <vector>

namespace pd {

// One cycle through every ring: node k is a visit of vertex `vertex[k]`. Nodes 0..n-1 are the
// vertices themselves; each bridge adds two nodes, second visits of its two ends.
struct BridgedCycle {
  static constexpr std::uint32_t kNoNode = ~std::uint32_t(0);

  std::vector<VertexId> vertex;
  std::vector<std::uint32_t> next, prev;
  std::vector<Cut> bridges;  // each a diagonal of any triangulation of the cycle
  // The visits of one vertex, chained from its own node v through the copies in the order they were
  // made; empty without holes.
  std::vector<std::uint32_t> later_visit;

  // The visit of the same vertex after `node`, or kNoNode.
  std::uint32_t visit_after(std::uint32_t node) const {
    return node < later_visit.size() ? later_visit[node] : kNoNode;
  }
};

// Counts the edges and vertices the bridge searches test as "bridge_tests".
BridgedCycle bridge_holes(const Polygon& p, Counters& counters);

}  // namespace pd
