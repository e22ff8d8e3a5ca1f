#include "engines/triangulation/hole_bridges.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <optional>

namespace pd {
namespace {

class Bridger {
 public:
  Bridger(const Polygon& p, BridgedCycle& c) : p_(p), c_(c) {}

  // Joins hole `ring` to the cycle through node 0.
  void join(std::size_t ring) {
    const std::uint32_t m = rightmost(ring);
    const std::uint32_t partner = partner_of(m);
    const std::uint32_t m2 = add_node(m), p2 = add_node(c_.vertex[partner]);
    const std::uint32_t after = c_.next[partner], last = static_cast<std::uint32_t>(p_.prev(m));
    link(partner, m);
    link(last, m2);
    link(m2, p2);
    link(p2, after);
    c_.bridges.push_back({c_.vertex[partner], m});
  }

  std::int64_t tests() const { return tests_; }

 private:
  const Point& at(std::uint32_t node) const { return p_[c_.vertex[node]]; }

  std::uint32_t rightmost(std::size_t ring) const {
    std::size_t best = p_.ring_begin(ring);
    for (std::size_t i = best; i < p_.ring_end(ring); ++i)
      if (p_[i].x() > p_[best].x() || (p_[i].x() == p_[best].x() && p_[i].y() > p_[best].y())) best = i;
    return static_cast<std::uint32_t>(best);
  }

  // The nearest point of the cycle on the ray from M in +x: a node at it, or an edge (u, next u) with
  // it inside. Exact: the crossings' x values are compared as rationals.
  struct Hit {
    CGAL::Exact_rational x;
    std::uint32_t node;
    bool at_vertex;
  };

  std::uint32_t partner_of(std::uint32_t m) {
    const Point& M = p_[m];
    std::optional<Hit> best;
    // Two edges crossed at one point are the two walks of one bridge: either gives the same triangle
    // and the same partner, so the first is kept.
    auto consider = [&](const CGAL::Exact_rational& x, std::uint32_t node, bool at_vertex) {
      if (!best || x < best->x) best = Hit{x, node, at_vertex};
    };
    std::uint32_t u = 0;
    do {
      ++tests_;
      const Point &a = at(u), &b = at(c_.next[u]);
      if (a.y() == M.y() && a.x() > M.x()) {
        consider(a.x(), u, true);
      } else if ((a.y() < M.y()) != (b.y() < M.y()) && a.y() != M.y() && b.y() != M.y()) {
        const CGAL::Exact_rational x =
            CGAL::Exact_rational(a.x()) + (CGAL::Exact_rational(M.y()) - a.y()) * (CGAL::Exact_rational(b.x()) - a.x()) /
                                              (CGAL::Exact_rational(b.y()) - a.y());
        if (x > M.x()) consider(x, u, false);
      }
      u = c_.next[u];
    } while (u != 0);
    if (best->at_vertex) return node_seeing(c_.vertex[best->node], M);
    return blocking_or_end(m, best->node);
  }

  // The edge (e, next e) is hit inside at I: its end P with the larger x, or the vertex in the closed
  // triangle M, I, P nearest the ray in angle (then in distance).
  std::uint32_t blocking_or_end(std::uint32_t m, std::uint32_t e) {
    const Point& M = p_[m];
    const std::uint32_t to = c_.next[e];
    const bool end_is_to = at(to).x() >= at(e).x();
    const VertexId end = c_.vertex[end_is_to ? to : e];
    const Point &U = at(e), &V = at(to), &P = p_[end];
    const int side = P.y() > M.y() ? 1 : -1;  // P above the ray: the triangle is M, I, P counter-clockwise
    const int edge_sign = end_is_to ? 1 : -1;  // line I -> P runs as U -> V, or against it
    std::optional<VertexId> chosen;
    std::uint32_t u = 0;
    do {
      ++tests_;
      const VertexId v = c_.vertex[u];
      const Point& R = p_[v];
      const bool on_p_side = side > 0 ? R.y() >= M.y() : R.y() <= M.y();
      const bool inside = v != end && on_p_side && orient(U, V, R) * edge_sign * side >= 0 && orient(P, M, R) * side >= 0;
      if (inside && (!chosen || nearer_the_ray(M, R, p_[*chosen], side))) chosen = v;
      u = c_.next[u];
    } while (u != 0);
    return node_seeing(chosen.value_or(end), M);
  }

  // Whether R makes a smaller angle with the ray from M than Q does, or the same and is nearer.
  static bool nearer_the_ray(const Point& M, const Point& R, const Point& Q, int side) {
    const int turn = orient(M, R, Q) * side;
    if (turn != 0) return turn > 0;
    return R.x() < Q.x() || (R.x() == Q.x() && (side > 0 ? R.y() < Q.y() : R.y() > Q.y()));
  }

  // The visit of vertex v whose interior angle holds the direction to q (v is visited more than once
  // when it ends an earlier bridge).
  std::uint32_t node_seeing(VertexId v, const Point& q) const {
    std::uint32_t found = v;
    for (std::uint32_t node = v; node != kNone; node = c_.visit_after(node))
      if (in_cone(node, q)) found = node;
    return found;
  }

  bool in_cone(std::uint32_t node, const Point& q) const {
    const Point &a = at(c_.prev[node]), &b = at(node), &c = at(c_.next[node]);
    if (orient(a, b, c) > 0) return orient(a, b, q) > 0 && orient(b, c, q) > 0;
    return orient(a, b, q) > 0 || orient(b, c, q) > 0;
  }

  static constexpr std::uint32_t kNone = BridgedCycle::kNoNode;

  std::uint32_t add_node(VertexId v) {
    const auto node = static_cast<std::uint32_t>(c_.vertex.size());
    c_.vertex.push_back(v);
    c_.next.push_back(kNone);
    c_.prev.push_back(kNone);
    c_.later_visit.resize(c_.vertex.size(), kNone);
    std::uint32_t last = v;
    while (c_.later_visit[last] != kNone) last = c_.later_visit[last];
    c_.later_visit[last] = node;
    return node;
  }

  void link(std::uint32_t a, std::uint32_t b) {
    c_.next[a] = b;
    c_.prev[b] = a;
  }

  const Polygon& p_;
  BridgedCycle& c_;
  std::int64_t tests_ = 0;
};

}  // namespace

BridgedCycle bridge_holes(const Polygon& p, Counters& counters) {
  const std::size_t n = p.size();
  BridgedCycle c;
  c.vertex.resize(n);
  c.next.resize(n);
  c.prev.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.vertex[i] = static_cast<VertexId>(i);
    c.next[i] = static_cast<std::uint32_t>(p.next(i));
    c.prev[i] = static_cast<std::uint32_t>(p.prev(i));
  }
  if (p.hole_count() == 0) return c;
  std::vector<std::size_t> holes(p.hole_count());
  for (std::size_t k = 0; k < holes.size(); ++k) holes[k] = k + 1;
  auto largest_x = [&](std::size_t ring) {
    double x = p[p.ring_begin(ring)].x();
    for (std::size_t i = p.ring_begin(ring); i < p.ring_end(ring); ++i) x = std::max(x, p[i].x());
    return x;
  };
  std::vector<double> key(p.ring_count());
  for (std::size_t ring : holes) key[ring] = largest_x(ring);
  std::stable_sort(holes.begin(), holes.end(), [&](std::size_t a, std::size_t b) { return key[a] > key[b]; });
  Bridger bridger(p, c);
  for (std::size_t ring : holes) bridger.join(ring);
  counters["bridge_tests"] = bridger.tests();
  return c;
}

}  // namespace pd
