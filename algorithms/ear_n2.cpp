// ear-n2: triangulation by ear clipping with ear-status updates (Rosen, "Polygon Partitioning",
// lecture slides 003, "Ear based idea" with "Update the ear tip status of v1 and v3").
//
// Time O(n^2), space O(n). Pre: a simple counter-clockwise polygon; collinear (180-degree) vertices are
// allowed. Output: n-3 diagonals, n-2 non-degenerate triangles, no Steiner points.
//
// Each vertex keeps its ear status. Clipping the ear at b changes only the status of its neighbours a
// and c, so only they are tested again (O(n) each: against the remaining non-convex vertices). Locating
// the next ear walks the remaining cycle from the last clip, O(n). Testing against the remaining
// non-convex vertices only is enough: when a closed ear triangle holds a vertex, the one farthest from
// line ac is not strictly convex. A vertex is an ear tip only when strictly convex, so collinear
// vertices are never clipped into a degenerate triangle; every simple polygon, collinear vertices and
// all, has such an ear (a leaf of the dual tree of any triangulation).
#include "core/registry.h"

#include <algorithm>
#include <vector>

namespace pd {
namespace {

class EarClipper {
 public:
  explicit EarClipper(const Polygon& p)
      : p_(p), n_(p.size()), prev_(n_), next_(n_), ear_(n_, 0), removed_(n_, 0) {
    for (std::size_t i = 0; i < n_; ++i) prev_[i] = p.prev(i), next_[i] = p.next(i);
  }

  Decomposition run(Counters& counters) {
    Decomposition d;
    d.cuts.reserve(n_ - 3);
    refresh_non_convex();
    for (std::size_t i = 0; i < n_; ++i) ear_[i] = is_ear(i);
    std::size_t v = 0;
    for (std::size_t remaining = n_; remaining > 3; --remaining) {
      while (!ear_[v]) v = next_[v], ++walk_steps_;
      const std::size_t a = prev_[v], c = next_[v];
      d.add_cut(a, c);
      unlink(v);
      ear_[a] = is_ear(a);
      ear_[c] = is_ear(c);
      v = c;
    }
    counters["ear_tests"] = ear_tests_;
    counters["point_tests"] = point_tests_;
    counters["walk_steps"] = walk_steps_;
    return d;
  }

 private:
  int turn(std::size_t v) const { return orient(p_[prev_[v]], p_[v], p_[next_[v]]); }

  void refresh_non_convex() {
    non_convex_.clear();
    for (std::size_t i = 0; i < n_; ++i)
      if (turn(i) <= 0) non_convex_.push_back(i);
  }

  // Clipping can only make a neighbour more convex, so the non-convex list only shrinks.
  void unlink(std::size_t v) {
    const std::size_t a = prev_[v], c = next_[v];
    next_[a] = c;
    prev_[c] = a;
    removed_[v] = 1;
    non_convex_.erase(std::remove_if(non_convex_.begin(), non_convex_.end(),
                                     [&](std::size_t u) { return removed_[u] || ((u == a || u == c) && turn(u) > 0); }),
                      non_convex_.end());
  }

  bool is_ear(std::size_t b) {
    ++ear_tests_;
    const std::size_t a = prev_[b], c = next_[b];
    if (orient(p_[a], p_[b], p_[c]) <= 0) return false;
    for (std::size_t v : non_convex_) {
      if (v == a || v == b || v == c) continue;
      ++point_tests_;
      if (orient(p_[a], p_[b], p_[v]) >= 0 && orient(p_[b], p_[c], p_[v]) >= 0 && orient(p_[c], p_[a], p_[v]) >= 0)
        return false;
    }
    return true;
  }

  const Polygon& p_;
  std::size_t n_;
  std::vector<std::size_t> prev_, next_, non_convex_;
  std::vector<char> ear_, removed_;
  std::int64_t ear_tests_ = 0, point_tests_ = 0, walk_steps_ = 0;
};

Decomposition ear_n2(const Polygon& p, Counters& counters) { return EarClipper(p).run(counters); }

}  // namespace

REGISTER_ALGORITHM({.name = "ear-n2", .kind = Kind::Triangulation, .time_bound = "n^2",
                    .pieces_bound = "== n-2",
                    .source = "Rosen slides (003), ear clipping with ear-status updates",
                    .size_ceiling = 20000, .run = ear_n2});

}  // namespace pd
