// ear-n2: triangulation by ear clipping with ear-status updates (Rosen, "Polygon Partitioning",
// lecture slides 003, "Ear based idea" with "Update the ear tip status of v1 and v3"); holes joined
// first by Eberly's bridges ("Triangulation by Ear Clipping", 2008, Sec. 4-5;
// engines/triangulation/hole_bridges.h).
//
// Time O(n^2) (with h holes: O(n h) for the bridges, then O((n + 2h)^2)), space O(n). Pre: a polygon,
// with h >= 0 holes; collinear (180-degree) vertices are allowed. Output: n + 3h - 3 diagonals (the h
// bridges among them), n + 2h - 2 non-degenerate triangles, no Steiner points.
//
// Each vertex keeps its ear status. Clipping the ear at b changes only the status of its neighbours a
// and c, so only they are tested again (O(n) each: against the remaining non-convex vertices). Locating
// the next ear walks the remaining cycle from the last clip, O(n). Testing against the remaining
// non-convex vertices only is enough: when a closed ear triangle holds a vertex, the one farthest from
// line ac is not strictly convex. A vertex is an ear tip only when strictly convex, so collinear
// vertices are never clipped into a degenerate triangle; every simple polygon, collinear vertices and
// all, has such an ear (a leaf of the dual tree of any triangulation). With holes the cycle visits each
// bridge end twice: the other visits of a, b and c are not tested as points (they sit on the corners)
// but by their edges, none of which may leave that corner into the triangle or along the new diagonal.
#include "core/registry.h"
#include "engines/triangulation/hole_bridges.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace pd {
namespace {

class EarClipper {
 public:
  EarClipper(const Polygon& p, BridgedCycle cycle)
      : p_(p), c_(std::move(cycle)), nodes_(c_.vertex.size()), ear_(nodes_, 0), removed_(nodes_, 0) {}

  Decomposition run(Counters& counters) {
    Decomposition d;
    d.cuts.reserve(nodes_ - 3 + c_.bridges.size());
    d.cuts = c_.bridges;
    refresh_non_convex();
    for (std::size_t i = 0; i < nodes_; ++i) ear_[i] = is_ear(i);
    std::size_t v = 0;
    for (std::size_t remaining = nodes_; remaining > 3; --remaining) {
      for (std::size_t walked = 0; !ear_[v]; v = c_.next[v], ++walk_steps_)
        if (++walked > remaining) throw std::logic_error("no ear left among " + std::to_string(remaining) + " vertices");
      const std::size_t a = c_.prev[v], c = c_.next[v];
      d.add_cut(c_.vertex[a], c_.vertex[c]);
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
  const Point& at(std::size_t node) const { return p_[c_.vertex[node]]; }
  int turn(std::size_t v) const { return orient(at(c_.prev[v]), at(v), at(c_.next[v])); }

  void refresh_non_convex() {
    non_convex_.clear();
    for (std::size_t i = 0; i < nodes_; ++i)
      if (turn(i) <= 0) non_convex_.push_back(i);
  }

  // Clipping can only make a neighbour more convex, so the non-convex list only shrinks.
  void unlink(std::size_t v) {
    const std::size_t a = c_.prev[v], c = c_.next[v];
    c_.next[a] = static_cast<std::uint32_t>(c);
    c_.prev[c] = static_cast<std::uint32_t>(a);
    removed_[v] = 1;
    non_convex_.erase(std::remove_if(non_convex_.begin(), non_convex_.end(),
                                     [&](std::size_t u) { return removed_[u] || ((u == a || u == c) && turn(u) > 0); }),
                      non_convex_.end());
  }

  bool is_ear(std::size_t b) {
    ++ear_tests_;
    const std::size_t a = c_.prev[b], c = c_.next[b];
    const VertexId va = c_.vertex[a], vb = c_.vertex[b], vc = c_.vertex[c];
    if (va == vc || orient(at(a), at(b), at(c)) <= 0) return false;
    for (std::size_t v : non_convex_) {
      const VertexId w = c_.vertex[v];
      if (w == va || w == vb || w == vc) continue;
      ++point_tests_;
      if (orient(at(a), at(b), at(v)) >= 0 && orient(at(b), at(c), at(v)) >= 0 && orient(at(c), at(a), at(v)) >= 0)
        return false;
    }
    return !other_visit_enters(a, at(b), at(c), &at(c)) && !other_visit_enters(b, at(c), at(a), nullptr) &&
           !other_visit_enters(c, at(a), at(b), &at(a));
  }

  // Whether another visit of corner `node`'s vertex has an edge leaving the corner into the triangle
  // (strictly between the rays to `first` and `second`, counter-clockwise) or along the new diagonal
  // (the ray to `diagonal`). Along a triangle side that is a boundary edge is fine: that is a bridge,
  // walked the other way on its other side.
  bool other_visit_enters(std::size_t node, const Point& first, const Point& second, const Point* diagonal) const {
    const Point& corner = at(node);
    for (std::uint32_t other = c_.vertex[node]; other != BridgedCycle::kNoNode; other = c_.visit_after(other)) {
      if (other == node || removed_[other]) continue;
      for (const std::uint32_t end : {c_.prev[other], c_.next[other]}) {
        const Point& q = at(end);
        if (orient(corner, first, q) > 0 && orient(corner, second, q) < 0) return true;
        if (diagonal && orient(corner, *diagonal, q) == 0 && CGAL::angle(*diagonal, corner, q) == CGAL::ACUTE) return true;
      }
    }
    return false;
  }

  const Polygon& p_;
  BridgedCycle c_;
  std::size_t nodes_;
  std::vector<std::size_t> non_convex_;
  std::vector<char> ear_, removed_;
  std::int64_t ear_tests_ = 0, point_tests_ = 0, walk_steps_ = 0;
};

Decomposition ear_n2(const Polygon& p, Counters& counters) {
  BridgedCycle cycle = bridge_holes(p, counters);
  return EarClipper(p, std::move(cycle)).run(counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "ear-n2", .kind = Kind::Triangulation, .time_bound = "n^2",
                    .pieces_bound = "== n+2*h-2",
                    .source = "Rosen slides (003), ear clipping with ear-status updates; Eberly 2008 bridges for holes",
                    .accepts = {.holes = true}, .size_ceiling = 20000, .run = ear_n2});

}  // namespace pd
