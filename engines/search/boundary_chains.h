// The boundary of a polygon cut into convex chains between its notches (B. Chazelle, Computational
// Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.2.2, Figure 2.6, Theorem 3), shared by
// `naive-chains` (ray shooting, engines/naive/naive_chains.cpp) and Chazelle-Dobkin's pattern tests (segments against
// the boundary, engines/chazelle_dobkin/patterns.h).
//
// A chain has `edges` edges from polygon vertex `start` on, along its ring, such that every prefix
// closes into a convex polygon: its edge directions turn counter-clockwise through less than a full
// turn, so, measured from its first edge, they are sorted by angle, and a line meets it in O(log k)
// binary-search steps for k edges (Chapter 4, where the thesis does this, is not part of the text we
// have; see engines/naive/naive_chains.cpp). The chains are the thesis's (greedy, maximal): m <= 2(1 + r) of them for
// r notches (Theorem 3), found in one O(n) pass.
#pragma once

#include "core/decomposition.h"
#include "core/filtered.h"

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pd::boundary {

// Exact signs of cross(q - p, s - r) and (q - p) . (s - r) on input points. The pass over all n
// vertices evaluates the first at every vertex, so they get the semi-static filter CGAL gives its
// orientation predicate (CGAL's four-point predicates have only its slower interval filter): each is
// the sum of two products of differences of input doubles, each difference rounded once, so CGAL's
// error bound for the orientation determinant holds with the same constant, and with the dot
// product's own magnitudes. Outside the filter's range, or when it cannot decide, the sign is
// computed in rationals.
[[gnu::noinline]] int exact_sign_of(const Point& p, const Point& q, const Point& r, const Point& s, bool cross);

constexpr double kFilterBound = 8.8872057372592798e-16;

// The difference q - p of two input points, rounded (a rounded difference has the exact one's sign).
struct Edge {
  Edge(const Point& p, const Point& q) : x(q.x() - p.x()), y(q.y() - p.y()) {}
  // Which quarter turn [0, 90), [90, 180), [180, 270), [270, 360) the direction is in. Exact.
  int quadrant() const {
    const bool upper = (y > 0) | ((y == 0) & (x > 0));  // [0, 180); written to compile without branches
    return upper ? int(x <= 0) : 2 + int(x >= 0);
  }
  double x, y;
};

// Sign of cross(u, w) for rounded differences u and w when the filter settles it, else kUnsettled.
constexpr int kUnsettled = 2;
inline int filtered_cross_sign(const Edge& u, const Edge& w) {
  const double max_x = std::max(std::abs(u.x), std::abs(w.x)), max_y = std::max(std::abs(u.y), std::abs(w.y));
  const double low = std::min(max_x, max_y), high = std::max(max_x, max_y);
  if (low >= 1e-146 && high < 1e153) {
    const double det = u.x * w.y - u.y * w.x, eps = kFilterBound * low * high;
    if (det > eps) return 1;
    if (det < -eps) return -1;
  }
  // A rounded difference is zero exactly when the difference is: when both products vanish that way
  // (as for two axis-parallel edges, common in real polygons) the sign is 0, which no bound settles.
  if ((u.x == 0 || w.y == 0) && (u.y == 0 || w.x == 0)) return 0;
  return kUnsettled;
}

inline int cross_sign(const Point& p, const Point& q, const Point& r, const Point& s) {
  const int sign = filtered_cross_sign(Edge(p, q), Edge(r, s));
  return sign != kUnsettled ? sign : exact_sign_of(p, q, r, s, true);
}

inline int dot_sign(const Point& p, const Point& q, const Point& r, const Point& s) {
  const Edge u(p, q), w(r, s);
  const double high = std::max(std::max(std::abs(u.x), std::abs(u.y)), std::max(std::abs(w.x), std::abs(w.y)));
  if (high >= 1e-146 && high < 1e153) {
    const double dot = u.x * w.x + u.y * w.y, eps = kFilterBound * high * high;
    if (dot > eps) return 1;
    if (dot < -eps) return -1;
  }
  if ((u.x == 0 || w.x == 0) && (u.y == 0 || w.y == 0)) return 0;
  return exact_sign_of(p, q, r, s, false);
}

// A convex chain: `edges` edges from polygon vertex `start` on, along its ring (the interior on the
// left), such that every prefix closes into a convex polygon; `lead` of its first edges point the same
// way as the first. The ring holds vertices ring_end - ring_size .. ring_end - 1.
struct Chain {
  std::size_t start, edges, lead, ring_end, ring_size;
};

// Polygon vertex j of chain c (j <= c.edges).
inline std::size_t chain_vertex(const Chain& c, std::size_t j) {
  const std::size_t k = c.start + j;
  return k < c.ring_end ? k : k - c.ring_size;
}

// The place of polygon vertex v along chain c's ring, counted from the chain's start: below c.edges
// for the start of one of the chain's edges, and at least c.edges for a vertex off the chain (or of
// another ring).
inline std::size_t offset_in_chain(const Chain& c, std::size_t v) {
  const std::size_t ring_begin = c.ring_end - c.ring_size;
  if (v < ring_begin || v >= c.ring_end) return c.edges;
  return v >= c.start ? v - c.start : v + c.ring_size - c.start;
}

// Angular position of the chain's edge j (from its vertex j to j + 1), measured counter-clockwise from
// its first edge d0: 0 for [0, 180), 1 for [180, 360), and 2 for an edge that has turned a full circle
// back to d0's direction. Edges are sorted by (half, angle within the half).
inline int half_of_edge(const Polygon& p, const Chain& c, std::size_t j) {
  const Point &x0 = p[chain_vertex(c, 0)], &x1 = p[chain_vertex(c, 1)];
  const Point &xj = p[chain_vertex(c, j)], &xj1 = p[chain_vertex(c, j + 1)];
  const int cross = cross_sign(x0, x1, xj, xj1);
  if (cross != 0) return cross > 0 ? 0 : 1;
  if (dot_sign(x0, x1, xj, xj1) <= 0) return 1;
  return j < c.lead ? 0 : 2;
}

// Figure 2.6: the notches of p in index order, and each ring cut between consecutive notches into
// maximal convex chains, from its first notch on; a ring without a notch (the outer ring, when the
// holes have all the notches) is one chain from its first vertex. None when p is convex: no shot
// needs them. O(n).
void split_into_chains(const Polygon& p, std::vector<VertexId>& notches, std::vector<Chain>& chains);

// Segments with exact rational ends against the chains: O(log k) per chain of k edges, O(r log(n/r))
// for all of them. Each chain is cut where its direction passes the segment's and the opposite one, into
// at most three runs along which the signed distance to the segment's line is monotone; a binary search
// in each finds the only edges that can reach the line, which are then tested exactly. The signs are
// settled in interval arithmetic where it can, else in rationals: every answer is exact. The chains'
// bounding boxes form a balanced hierarchy over the chains in boundary order (consecutive chains lie
// close together), each node's box holding its children's; a search descends only into the nodes
// whose box meets the segment's box and straddles its line, so it visits O(log r) nodes per chain
// near the segment instead of passing every chain's box. A node is passed over only when the
// interval arithmetic settles that it misses the segment, so the pruning never changes an answer.
// The worst case stays O(r log(n/r)) per segment, when the segment passes near every chain.
class SegmentSearch {
 public:
  // `exact` holds p's vertices as rationals.
  SegmentSearch(const Polygon& p, const std::vector<QPoint>& exact);

  // Whether the closed segment st meets the closed boundary of p, the two edges at polygon vertex
  // `skip` left out (kNoVertex: none). Pre: s != t.
  static constexpr VertexId kNoVertex = static_cast<VertexId>(-1);
  bool meets_boundary(const QPoint& s, const QPoint& t, VertexId skip = kNoVertex);

  // A point of the boundary and where it lies: at polygon vertex `edge` (at_vertex), or inside the edge
  // from vertex `edge` to the next.
  struct Contact {
    std::size_t edge;
    bool at_vertex;
    QPoint point;

    // Whether contact a comes before b in the order of p's boundary from vertex 0 on (neither does
    // when they are one point).
    static bool before(const Polygon& p, const Contact& a, const Contact& b) {
      if (a.edge != b.edge) return a.edge < b.edge;
      if (a.at_vertex || b.at_vertex) return a.at_vertex && !b.at_vertex;
      const QPoint w = to_exact(p[a.edge]);
      const ExactKernel::Vector_2 e = to_exact(p[p.next(a.edge)]) - w;
      return (a.point - w) * e < (b.point - w) * e;
    }
  };

  std::int64_t steps() const { return steps_; }

 private:
  const QPoint& x(std::size_t j) const { return exact_[chain_vertex(*chain_, j)]; }
  const Point& input(std::size_t j) const { return p_[chain_vertex(*chain_, j)]; }
  int side(std::size_t j);
  int cross_sign_with_u(std::size_t from, std::size_t to, int sense);
  int dot_sign_with_u(std::size_t from, std::size_t to);
  std::size_t first_edge_reaching(std::size_t lo, std::size_t hi, int sense);
  bool range_meets(std::size_t lo, std::size_t hi);
  bool run_meets(std::size_t lo, std::size_t hi);
  bool meets(std::size_t from, std::size_t to);
  bool chain_meets(std::size_t k, VertexId skip);
  bool box_meets(const CGAL::Bbox_2& box) const;
  static CGAL::Bbox_2 box_of(const QPoint& s, const QPoint& t);
  Interval line_side(double x, double y) const;

  const Polygon& p_;
  const std::vector<QPoint>& exact_;
  std::vector<Chain> chains_;
  // The hierarchy, in heap order: node 1 is the root, node i has children 2i and 2i + 1, and leaf
  // `leaves_ + k` is chain k's box (from its input vertices); leaves past the last chain hold the
  // empty box, which meets nothing.
  std::size_t leaves_ = 1;
  std::vector<CGAL::Bbox_2> boxes_;
  const Chain* chain_ = nullptr;
  // The segment of the current search, its direction u = t - s, and intervals around s and u that
  // settle most signs in floating point.
  const QPoint *s_ = nullptr, *t_ = nullptr;
  ExactKernel::Segment_2 st_;
  CGAL::Bbox_2 around_;
  ExactKernel::Vector_2 u_;
  Interval sx_, sy_, ux_, uy_;
  std::int64_t steps_ = 0;
};

}  // namespace pd::boundary
