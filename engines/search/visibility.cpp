// Visibility by walking a triangulation; see visibility.h.
#include "engines/search/visibility.h"

#include "engines/triangulation/monotone.h"

#include <algorithm>

namespace pd {

VisibilityGraph::VisibilityGraph(const Polygon& p) : p_(p), n_(p.size()), start_(p.size() + 1, 0) {
  Counters scratch;
  const Decomposition triangulation = triangulate_monotone(p, scratch);
  for (std::size_t v = 0; v < n_; ++v) start_[v + 1] = 2;
  for (const Cut& c : triangulation.cuts) ++start_[c.a + 1], ++start_[c.b + 1];
  for (std::size_t v = 0; v < n_; ++v) start_[v + 1] += start_[v];
  target_.resize(start_[n_]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t v = 0; v < n_; ++v) {
    target_[fill[v]++] = static_cast<std::uint32_t>(p.next(v));
    target_[fill[v]++] = static_cast<std::uint32_t>(p.prev(v));
  }
  for (const Cut& c : triangulation.cuts) target_[fill[c.a]++] = c.b, target_[fill[c.b]++] = c.a;
  sort_rows();
  link_twins();
}

// Observation 1: around v the neighbours come in the order of their indices counted from v + 1.
void VisibilityGraph::sort_rows() {
  for (std::size_t v = 0; v < n_; ++v)
    std::sort(target_.begin() + start_[v], target_.begin() + start_[v + 1],
              [&](std::uint32_t a, std::uint32_t b) { return offset(v, a) < offset(v, b); });
}

void VisibilityGraph::link_twins() {
  twin_.resize(target_.size());
  for (std::size_t v = 0; v < n_; ++v)
    for (std::uint32_t h = start_[v]; h < start_[v + 1]; ++h) {
      const std::uint32_t u = target_[h];
      const auto first = target_.begin() + start_[u], last = target_.begin() + start_[u + 1];
      const auto it = std::lower_bound(first, last, static_cast<std::uint32_t>(v), [&](std::uint32_t a, std::uint32_t b) {
        return offset(u, a) < offset(u, b);
      });
      twin_[h] = static_cast<std::uint32_t>(it - target_.begin());
    }
}

// Slot h is a half-edge a -> b. The triangle to the left of b -> a has its third vertex just before b in
// a's counter-clockwise row (slot h - 1), unless h opens the row: then a -> b is the polygon edge
// a -> a+1, with the outside beyond it.
//
// The walk is an in-order traversal of the cones (right sub-cone, the apex, left sub-cone), so the
// vertices come out in counter-clockwise order and need no sorting.
void VisibilityGraph::visible_from(std::size_t v, std::vector<std::uint32_t>& out, std::int64_t& triangles,
                                   std::vector<std::uint32_t>* seen) const {
  constexpr std::uint32_t kWindow = UINT32_MAX;
  struct Item {
    std::uint32_t emit;   // a visible vertex to output, or kWindow
    std::uint32_t slot;   // the window: half-edge right end -> left end, seen from v
    std::uint32_t right;  // the cone: open, counter-clockwise from ray v->right to ray v->left
    std::uint32_t left;
  };
  std::vector<Item> stack;
  const Point& pv = p_[v];
  for (std::uint32_t h = start_[v + 1]; h-- > start_[v];) {
    if (h + 1 < start_[v + 1]) stack.push_back({kWindow, twin_[h] - 1, target_[h], target_[h + 1]});
    stack.push_back({target_[h], 0, 0, 0});
  }
  while (!stack.empty()) {
    const Item w = stack.back();
    stack.pop_back();
    if (w.emit != kWindow) {
      out.push_back(w.emit);
      continue;
    }
    const std::uint32_t right_end = target_[twin_[w.slot]];
    if (w.slot == start_[right_end]) {
      if (seen) seen->push_back(right_end);
      continue;
    }
    ++triangles;
    const std::uint32_t c = target_[w.slot - 1];
    const std::uint32_t to_left = twin_[w.slot - 1] - 1;  // half-edge c -> left end
    if (orient(pv, p_[w.right], p_[c]) <= 0) {
      stack.push_back({kWindow, to_left, w.right, w.left});
    } else if (orient(pv, p_[w.left], p_[c]) >= 0) {
      stack.push_back({kWindow, w.slot - 1, w.right, w.left});
    } else {
      stack.push_back({kWindow, to_left, c, w.left});
      stack.push_back({c, 0, 0, 0});
      stack.push_back({kWindow, w.slot - 1, w.right, c});
    }
  }
}

}  // namespace pd
