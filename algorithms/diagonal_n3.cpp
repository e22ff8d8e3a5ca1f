// diagonal-n3: diagonal-based triangulation improved to O(n^3) (Rosen, "Polygon Partitioning", lecture
// slides 003, "Brute force triangulation": "can be made O(n^3)").
//
// Time O(n^3), space O(n^2). Pre: a simple counter-clockwise polygon; collinear (180-degree) vertices
// are allowed. Output: n-3 diagonals, n-2 non-degenerate triangles (the greedy triangulation), no
// Steiner points.
//
// `diagonal-n4` repeats the O(n^3) search for a proper diagonal n-3 times, testing the same candidate
// against the polygon's edges in every round although the answer cannot change. Here each of the
// O(n^2) candidates is tested once (Theta(n): every edge and both neighbourhoods, engines/triangulation/diagonal_test.h), the
// diagonals are sorted in the order `diagonal-n4` picks them (shortest first, ties by endpoints,
// O(n^2 log n)), and each is output unless it crosses one already output (O(n) each). A diagonal
// crossing an output one never becomes proper again, so the output is `diagonal-n4`'s, in its order.
#include "core/registry.h"
#include "engines/triangulation/diagonal_test.h"

#include <algorithm>
#include <vector>

namespace pd {
namespace {

using namespace diagonal_test;

Decomposition diagonal_n3(const Polygon& p, Counters& counters) {
  const std::size_t n = p.size();
  std::int64_t diagonal_tests = 0, edge_tests = 0, crossing_tests = 0;
  std::vector<Cut> diagonals;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j + 1 == n) continue;
      ++diagonal_tests;
      if (is_diagonal(p, i, j, edge_tests)) diagonals.push_back({static_cast<VertexId>(i), static_cast<VertexId>(j)});
    }
  std::sort(diagonals.begin(), diagonals.end(), [&](const Cut& s, const Cut& t) { return picked_before(p, s, t); });
  Decomposition d;
  d.cuts.reserve(n - 3);
  for (const Cut& c : diagonals) {
    if (d.cuts.size() + 3 == n) break;
    const bool free = std::none_of(d.cuts.begin(), d.cuts.end(), [&](const Cut& t) {
      ++crossing_tests;
      return cross(p, c, t);
    });
    if (free) d.add_cut(c.a, c.b);
  }
  counters["diagonal_tests"] = diagonal_tests;
  counters["edge_tests"] = edge_tests;
  counters["crossing_tests"] = crossing_tests;
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "diagonal-n3", .kind = Kind::Triangulation, .time_bound = "n^3",
                    .pieces_bound = "== n-2",
                    .source = "Rosen slides (003), diagonal-based triangulation made O(n^3)",
                    .size_ceiling = 1000, .run = diagonal_n3});

}  // namespace pd
