// ear-n3: triangulation by ear clipping with the ear status recomputed every round (Rosen, "Polygon
// Partitioning", lecture slides 003, "Ear based idea" and "Triangulation: implementation", the version
// before "Can be made O(n^2)"; Meisters' two-ears theorem).
//
// Time O(n^3), space O(n). Pre: a simple counter-clockwise polygon; collinear (180-degree) vertices are
// allowed. Output: n-3 diagonals, n-2 non-degenerate triangles, no Steiner points.
//
// Each round tests every remaining vertex afresh (m ear tests of m-3 point tests each for m remaining
// vertices), clips the first ear after the last clipped vertex and outputs its diagonal; nothing is
// remembered from one round to the next, which is what ear-n2 improves on. So every round costs
// Theta(m^2) and the total is Theta(n^3) on every polygon.
//
// A vertex b with neighbours a, c is an ear tip when it is strictly convex and no other remaining vertex
// lies in the closed triangle abc: then ac is a diagonal (an edge crossing ac would have to end inside
// the triangle) and the triangle is not degenerate. A collinear vertex is never an ear tip. Every simple
// polygon with more than three vertices, collinear ones included, has such an ear: a leaf of the dual
// tree of any triangulation into non-degenerate triangles.
#include "core/registry.h"

#include <cstdint>
#include <vector>

namespace pd {
namespace {

class FreshEarClipper {
 public:
  explicit FreshEarClipper(const Polygon& p) : p_(p), n_(p.size()), prev_(n_), next_(n_), ear_(n_) {
    for (std::size_t i = 0; i < n_; ++i) prev_[i] = p.prev(i), next_[i] = p.next(i);
  }

  Decomposition run(Counters& counters) {
    Decomposition d;
    d.cuts.reserve(n_ - 3);
    std::size_t start = 0;  // where the scan for the next ear begins
    for (std::size_t remaining = n_; remaining > 3; --remaining) {
      recompute_ear_status(start, remaining);
      std::size_t b = start;
      while (!ear_[b]) b = next_[b];
      d.add_cut(prev_[b], next_[b]);
      start = next_[b];
      unlink(b);
    }
    counters["rounds"] = static_cast<std::int64_t>(n_ - 3);
    counters["ear_tests"] = ear_tests_;
    counters["point_tests"] = point_tests_;
    return d;
  }

 private:
  void recompute_ear_status(std::size_t start, std::size_t remaining) {
    std::size_t v = start;
    for (std::size_t k = 0; k < remaining; ++k, v = next_[v]) ear_[v] = is_ear(v, start, remaining);
  }

  // In full: every other remaining vertex is tested, whatever the angle at b and whatever an earlier
  // vertex showed, so that each ear test costs Theta(m) as the slides count it (a reflex tip would
  // otherwise cost O(1), and a polygon of notches would be cleared in O(n^2)).
  bool is_ear(std::size_t b, std::size_t start, std::size_t remaining) {
    ++ear_tests_;
    const std::size_t a = prev_[b], c = next_[b];
    bool holds_a_vertex = false;
    std::size_t v = start;
    for (std::size_t k = 0; k < remaining; ++k, v = next_[v]) {
      if (v == a || v == b || v == c) continue;
      ++point_tests_;
      holds_a_vertex |= orient(p_[a], p_[b], p_[v]) >= 0 && orient(p_[b], p_[c], p_[v]) >= 0 &&
                        orient(p_[c], p_[a], p_[v]) >= 0;
    }
    return !holds_a_vertex && orient(p_[a], p_[b], p_[c]) > 0;
  }

  void unlink(std::size_t b) {
    next_[prev_[b]] = next_[b];
    prev_[next_[b]] = prev_[b];
  }

  const Polygon& p_;
  std::size_t n_;
  std::vector<std::size_t> prev_, next_;
  std::vector<char> ear_;
  std::int64_t ear_tests_ = 0, point_tests_ = 0;
};

Decomposition ear_n3(const Polygon& p, Counters& counters) { return FreshEarClipper(p).run(counters); }

}  // namespace

REGISTER_ALGORITHM({.name = "ear-n3", .kind = Kind::Triangulation, .time_bound = "n^3",
                    .pieces_bound = "== n-2",
                    .source = "Rosen slides (003), ear clipping, ear status recomputed each round",
                    .size_ceiling = 1000, .run = ear_n3});

}  // namespace pd
