// The naive decomposition (declarations and the method in naive.h), the method of `naive` (its paper,
// bounds and guarantees: algorithms/naive.cpp), which `naive-chains` and Chazelle-Dobkin's STEP 5 run
// with their own boundary searches.
//
// Deviations and reconstructions:
// - The ray follows the extension of the notch's incoming edge (prev(v), v), not the bisector D of the
//   thesis: the extension is exact in the input's doubles, the bisector is not even rational. It lies
//   on the range's boundary, so the notch is left with a 180-degree angle on one side.
// - Figure 2.5-b, the repair when the ray's first contact is a vertex x of G, is reconstructed from
//   the OCR'd text: "Let t be the intersection of line(b v) with xy if it exists or y otherwise ...
//   consider the largest triangle v x c (with c on xt) which contains no point of the decomposition
//   ... if c is not t, the segment v c must pass through a notch of P". Here the ray is turned by an
//   infinitesimal angle counter-clockwise, into the range, which decides which edge xy it meets (the
//   one it crosses next to x) and also makes it pass by vertices it would touch without crossing G.
//   The segment then ends strictly between x (or, after passed vertices, the extension's crossing point
//   h) and c, where t bounds the turn by the range's other side (the extension of edge (v, next(v))
//   beyond v) and c by the unresolved notches inside triangle (v, x, t): the open triangle with the
//   smallest such angle holds no vertex of G, so nothing crosses the segment, and its nearest-angle
//   blocker is always a notch still reflex in its face, which is why testing the unresolved notches,
//   O(r) per repair, is enough.
// - Where in (h, c) the turned segment ends is our choice (the thesis needs only some point there): the
//   extension's direction u = v - prev(v) turned by atan(2^-k) counter-clockwise, i.e. direction
//   2^k u + rot90(u), for the least k >= 0 that stays short of c. So every segment lies on a line
//   through its notch whose direction is given by two input points and k, and every Steiner point is
//   the meeting point of two such lines (or of one and a polygon edge): its bit length is bounded by the
//   input's and the k's, whatever chain of earlier segments it was found through. An earlier version
//   ended at the midpoint of h and c; on a comb (r = n/2) each repair then ends on the left edge halfway
//   between the extension and the previous repair's end, a chain of r/2 halvings: the Steiner points
//   reached n/4 bits, the interval filters failed on the points nearing the gap bottoms' line, and the
//   time grew as n^2.44 while the operation counts grew as n r. k is about log2 of 1 / the angle
//   between the extension and v c, a property of the geometry at the notch, not of the number of
//   segments before (comb: k <= 13 up to n = 10000, the teeth's height over the comb's width); the
//   comb's Steiner points now have under 30 bits at n = 5000 (up to 1270 before).
// - Theorem 2's walk takes, at each vertex, the neighbour just before the one it came from in
//   counter-clockwise order; with three neighbours two of them can make non-reflex angles, so "the
//   unique neighbour making a non-reflex angle" of the OCR'd text is read as "the first one".
#include "engines/naive/naive.h"

#include "core/filtered.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace pd {
namespace naive {
namespace {

// An input vertex (double) or a constructed point.
class Ref {
 public:
  Ref(const Point& p) : input_(&p) {}
  Ref(const FilteredPoint& q) : made_(&q) {}
  const Point* input() const { return input_; }
  Box box() const { return input_ ? Box{Interval(input_->x()), Interval(input_->y())} : made_->box; }
  QPoint exact() const { return input_ ? to_exact(*input_) : made_->exact; }

 private:
  const Point* input_ = nullptr;
  const FilteredPoint* made_ = nullptr;
};

// Exact orientation of (p, q, r), filtered by interval arithmetic.
int turn(Ref p, Ref q, Ref r) {
  if (p.input() && q.input() && r.input()) return orient(*p.input(), *q.input(), *r.input());
  if (const std::optional<int> sign = interval_orient(p.box(), q.box(), r.box())) return *sign;
  return orient(p.exact(), q.exact(), r.exact());
}

// Exact sign of the dot product (q - p) . (s - r), filtered.
int dot_sign(Ref p, Ref q, Ref r, Ref s) {
  const Box a = p.box(), b = q.box(), c = r.box(), e = s.box();
  std::optional<int> filtered;
  {
    CGAL::Protect_FPU_rounding<true> upwards;
    filtered = certain_sign((b.x - a.x) * (e.x - c.x) + (b.y - a.y) * (e.y - c.y));
  }
  if (filtered) return *filtered;
  const QPoint A = p.exact(), B = q.exact(), C = r.exact(), E = s.exact();
  return CGAL::sign((B.x() - A.x()) * (E.x() - C.x()) + (B.y() - A.y()) * (E.y() - C.y()));
}

// Where line (p0, p1) meets line (q0, q1), which are not parallel.
QPoint meet(const QPoint& p0, const QPoint& p1, const QPoint& q0, const QPoint& q1) {
  const Rational dx = p1.x() - p0.x(), dy = p1.y() - p0.y();
  const Rational ex = q1.x() - q0.x(), ey = q1.y() - q0.y();
  const Rational t = ((q0.x() - p0.x()) * ey - (q0.y() - p0.y()) * ex) / (dx * ey - dy * ex);
  return QPoint(p0.x() + t * dx, p0.y() + t * dy);
}

// A line of G, spanned by two exact points.
struct Line {
  QPoint p, q;
};

QPoint meet(const QPoint& p0, const QPoint& p1, const Line& l) { return meet(p0, p1, l.p, l.q); }

// The direction 2^k u + rot90(u) for the least k >= 0 that puts it strictly between u and w, which
// is strictly counter-clockwise of u by less than a half turn: u turned by atan(2^-k) towards w.
// Its coordinates have k bits more than u's, whatever w's.
std::pair<Rational, Rational> dyadic_turn(const Rational& ux, const Rational& uy, const Rational& wx,
                                          const Rational& wy) {
  // (2^k u + rot90(u)) x w = 2^k (u x w) + rot90(u) x w, with u x w > 0: double until positive.
  Rational scaled_u_cross_w = ux * wy - uy * wx;
  const Rational minus_perp_cross_w = uy * wy + ux * wx;
  Rational scale = 1;
  while (scaled_u_cross_w <= minus_perp_cross_w) scaled_u_cross_w *= 2, scale *= 2;
  return {scale * ux - uy, scale * uy + ux};
}

}  // namespace

// A line of G: a polygon edge or a drawn segment, with the vertices of G inside it in order.
struct LineRef {
  bool segment;
  std::uint32_t index;
};

// The graph G of the thesis as lines: the polygon's edges and the segments, each with the vertices of
// G that lie inside it, sorted from its first end to its second. Shots add a segment and one Steiner
// point inside an existing line.
class Decomposer {
 public:
  Decomposer(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches, Counters& counters)
      : p_(p), n_(p.size()), d_(std::move(d)), counters_(counters), pending_(notches),
        unresolved_(n_, 0) {
    for (VertexId v : notches) unresolved_[v] = 1;
    for (const SteinerPoint& s : d_.steiner) steiner_.emplace_back(s.point);
    place_boundary_steiner_points();
    for (const Cut& c : d_.cuts) segments_.push_back({c.a, c.b, {at(c.a).exact(), at(c.b).exact()}, {}});
    d_.cuts.clear();
  }

  Decomposition run(BoundarySearch& search) {
    for (VertexId v : pending_) shoot(v, search);
    for (const Segment& s : segments_) {
      VertexId from = s.from;
      for (VertexId w : s.inner) d_.add_cut(from, w), from = w;
      d_.add_cut(from, s.to);
    }
    counters_["segments"] = static_cast<std::int64_t>(pending_.size());
    counters_["edge_crossings"] = edge_crossings_;
    counters_["segment_tests"] = segment_tests_;
    counters_["repairs"] = repairs_;
    counters_["repair_tests"] = repair_tests_;
    counters_["steiner_points"] = static_cast<std::int64_t>(d_.steiner.size());
    return std::move(d_);
  }

  Place place_of_input(std::size_t w) const {
    const int o = orient(p_[a_], p_[v_], p_[w]);
    if (o != 0) return o > 0 ? Place::Left : Place::Right;
    return CGAL::collinear_are_strictly_ordered_along_line(p_[a_], p_[v_], p_[w]) ? Place::Ahead : Place::Behind;
  }

  void offer_edge(std::size_t i, bool first_is_right) {
    ++edge_crossings_;
    const VertexId e0 = static_cast<VertexId>(i), e1 = static_cast<VertexId>(p_.next(i));
    offer({false, e0}, first_is_right ? e0 : e1, first_is_right ? e1 : e0);
  }

  // A vertex on the extension ahead of the notch: the nearest one decides whether the ray must turn.
  void offer_ahead(VertexId w) {
    if (!ahead_ || dot_sign(at(w), at(*ahead_), at(a_), at(v_)) > 0) ahead_ = w;
  }

 private:
  struct Segment {
    VertexId from, to;          // from: the notch (or a given cut's first end)
    Line carrier;  // its line, spanned by input vertices or by its notch and a dyadic turn (turned_line)
    std::vector<VertexId> inner;
  };

  // The crossing the perturbed ray meets first, so far.
  struct Hit {
    LineRef line;
    VertexId right, left;  // the line's ends on the right and on the left of the perturbed ray
    FilteredPoint point;   // where the unperturbed extension meets the line
  };

  Ref at(VertexId id) const { return id < n_ ? Ref(p_[id]) : Ref(steiner_[id - n_]); }

  std::pair<VertexId, VertexId> ends(LineRef l) const {
    if (l.segment) return {segments_[l.index].from, segments_[l.index].to};
    return {l.index, static_cast<VertexId>(p_.next(l.index))};
  }
  Line carrier(LineRef l) const {
    if (l.segment) return segments_[l.index].carrier;
    return {at(l.index).exact(), at(static_cast<VertexId>(p_.next(l.index))).exact()};
  }
  std::vector<VertexId>& inner(LineRef l) {
    return l.segment ? segments_[l.index].inner : inner_of_edge_[l.index];
  }

  Place place(VertexId w) const {
    if (w < n_) return place_of_input(w);
    const int o = turn(at(a_), at(v_), at(w));
    if (o != 0) return o > 0 ? Place::Left : Place::Right;
    return dot_sign(at(v_), at(w), at(a_), at(v_)) > 0 ? Place::Ahead : Place::Behind;
  }

  // The Steiner points a given decomposition has on the boundary, in order along their edges.
  void place_boundary_steiner_points() {
    for (std::size_t k = 0; k < d_.steiner.size(); ++k)
      if (d_.steiner[k].boundary_edge != kInterior)
        inner_of_edge_[d_.steiner[k].boundary_edge].push_back(static_cast<VertexId>(n_ + k));
    for (auto& [e, on_edge] : inner_of_edge_) {
      const Ref e0 = p_[e], e1 = p_[p_.next(e)];
      std::sort(on_edge.begin(), on_edge.end(), [&](VertexId s, VertexId t) { return dot_sign(at(s), at(t), e0, e1) > 0; });
    }
  }

  // A line whose ends lie on different sides of the perturbed ray: keep it if it is crossed ahead of
  // the notch and nearer than the best so far. At equal distance the crossings share a vertex of G,
  // and the ray, turned counter-clockwise, meets first the line that leaves that vertex at the widest
  // angle from the ray.
  void offer(LineRef line, VertexId right, VertexId left) {
    if (turn(at(right), at(left), at(v_)) <= 0) return;
    if (best_) {
      const int o = turn(at(right), at(left), best_->point);
      if (o > 0) return;
      if (o == 0) {
        if (turn(best_->point, at(best_->left), at(left)) > 0) best_->line = line, best_->right = right, best_->left = left;
        return;
      }
    }
    best_.emplace(Hit{line, right, left, FilteredPoint(crossing_point(line, right))});
  }

  FilteredPoint crossing_point(LineRef line, VertexId right) const {
    if (turn(at(a_), at(v_), at(right)) == 0) return FilteredPoint(at(right).exact());
    return FilteredPoint(meet(at(a_).exact(), at(v_).exact(), carrier(line)));
  }

  void shoot(VertexId v, BoundarySearch& search) {
    v_ = v, a_ = static_cast<VertexId>(p_.prev(v)), b_ = static_cast<VertexId>(p_.next(v));
    best_.reset();
    ahead_.reset();
    Shot shot(*this, p_, v);
    search.search(shot);
    offer_segments();
    offer_steiner_points_ahead();
    finish_shot();
    unresolved_[v] = 0;
  }

  void offer_segments() {
    for (std::uint32_t s = 0; s < segments_.size(); ++s) {
      ++segment_tests_;
      const Segment& seg = segments_[s];
      const int from = side_of(place(seg.from)), to = side_of(place(seg.to));
      if (from != to) offer({true, s}, from < 0 ? seg.from : seg.to, from < 0 ? seg.to : seg.from);
    }
  }

  void offer_steiner_points_ahead() {
    for (std::size_t k = 0; k < steiner_.size(); ++k)
      if (place(static_cast<VertexId>(n_ + k)) == Place::Ahead) offer_ahead(static_cast<VertexId>(n_ + k));
  }

  // Where, in the line's sequence of vertices [first end, inner..., second end], the first vertex
  // not before `h` is, and whether it is at h.
  std::pair<std::size_t, bool> locate(LineRef line, const FilteredPoint& h) {
    // Not a structured binding: the lambdas below capture the ends, which C++17 does not allow of one.
    VertexId e0, e1;
    std::tie(e0, e1) = ends(line);
    const std::vector<VertexId>& in = inner(line);
    auto before_h = [&](VertexId w) { return dot_sign(at(w), h, at(e0), at(e1)) > 0; };
    if (!before_h(e0)) return {0, true};
    const std::size_t j = 1 + (std::partition_point(in.begin(), in.end(), before_h) - in.begin());
    const VertexId at_j = j <= in.size() ? in[j - 1] : e1;
    return {j, dot_sign(at(at_j), h, at(e0), at(e1)) == 0};
  }

  void finish_shot() {
    const Hit hit = *best_;
    VertexId e0, e1;  // not a structured binding: captured below
    std::tie(e0, e1) = ends(hit.line);
    const auto [j, at_vertex] = locate(hit.line, hit.point);
    // The sub-edge of the line the perturbed ray crosses: (lo, hi) in the line's vertex sequence.
    const std::size_t lo = at_vertex && hit.left == e1 ? j : j - 1;
    std::vector<VertexId>& in = inner(hit.line);
    auto vertex = [&](std::size_t k) { return k == 0 ? e0 : k <= in.size() ? in[k - 1] : e1; };
    const VertexId left_end = hit.left == e1 ? vertex(lo + 1) : vertex(lo);
    const bool must_turn = at_vertex || (ahead_ && dot_sign(at(*ahead_), hit.point, at(a_), at(v_)) >= 0);
    const Line hit_line = carrier(hit.line);
    const Line line = must_turn ? turned_line(hit.point, left_end, hit_line) : Line{at(a_).exact(), at(v_).exact()};
    const QPoint end = must_turn ? meet(line.p, line.q, hit_line) : hit.point.exact;
    const VertexId s = static_cast<VertexId>(n_ + d_.add_steiner(end, hit.line.segment ? kInterior : hit.line.index));
    steiner_.emplace_back(end);
    in.insert(in.begin() + lo, s);
    segments_.push_back({v_, s, line, {}});
  }

  // Figure 2.5-b: the line of a segment turned counter-clockwise from the extension, which meets the
  // hit line at h, towards the sub-edge's end q left of the ray. t bounds the turn by the range, c by
  // the unresolved notch inside triangle (v, h, t) with the smallest angle from the extension; the
  // segment turns by the largest angle atan(2^-k), k >= 0, short of c (dyadic_turn).
  Line turned_line(const FilteredPoint& h, VertexId q, const Line& hit_line) {
    ++repairs_;
    const QPoint v = at(v_).exact(), a = at(a_).exact();
    const FilteredPoint t(turn(at(b_), at(v_), at(q)) <= 0 ? at(q).exact() : meet(at(b_).exact(), v, hit_line));
    std::optional<VertexId> blocker;
    for (VertexId w : pending_) {
      if (!unresolved_[w] || w == v_) continue;
      ++repair_tests_;
      if (turn(at(v_), h, at(w)) > 0 && turn(h, t, at(w)) > 0 && turn(t, at(v_), at(w)) > 0 &&
          (!blocker || turn(at(v_), at(w), at(*blocker)) > 0))
        blocker = w;
    }
    const QPoint c = blocker ? meet(v, at(*blocker).exact(), hit_line) : t.exact;
    const auto [dx, dy] = dyadic_turn(v.x() - a.x(), v.y() - a.y(), c.x() - v.x(), c.y() - v.y());
    return {v, QPoint(v.x() + dx, v.y() + dy)};
  }

  const Polygon& p_;
  const std::size_t n_;
  Decomposition d_;
  Counters& counters_;
  std::vector<FilteredPoint> steiner_;
  std::unordered_map<std::uint32_t, std::vector<VertexId>> inner_of_edge_;  // only edges that have some
  std::vector<Segment> segments_;
  std::vector<VertexId> pending_;
  std::vector<char> unresolved_;
  VertexId v_ = 0, a_ = 0, b_ = 0;  // the notch being resolved and its neighbours
  std::optional<Hit> best_;
  std::optional<VertexId> ahead_;
  std::int64_t edge_crossings_ = 0, segment_tests_ = 0, repairs_ = 0, repair_tests_ = 0;
};

Place Shot::place(std::size_t w) const { return g_.place_of_input(w); }
void Shot::offer_edge(std::size_t i, bool first_is_right) { g_.offer_edge(i, first_is_right); }
void Shot::offer_ahead(std::size_t w) { g_.offer_ahead(static_cast<VertexId>(w)); }

Decomposition resolve(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                      BoundarySearch& search, Counters& counters) {
  return Decomposer(p, std::move(d), notches, counters).run(search);
}

std::vector<VertexId> notches_of(const Polygon& p) {
  std::vector<VertexId> notches;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_reflex(i)) notches.push_back(static_cast<VertexId>(i));
  return notches;
}

namespace {

// The naive search: every polygon edge, the notch's ring walked from the notch's successor round to
// its predecessor, every other ring (a hole, or the outer ring for a notch of a hole) all round; each
// edge tested once (a ring walked all round places its first vertex twice, as its first edge's start
// and its last edge's end, and offers it once).
class EveryEdge : public BoundarySearch {
 public:
  explicit EveryEdge(const Polygon& p) : p_(p) {}

  void search(Shot& shot) override {
    const std::size_t own = p_.ring_of(shot.notch());
    walk(shot, p_.next(shot.notch()), p_.ring_end(own) - p_.ring_begin(own) - 2);
    for (std::size_t k = 0; k < p_.ring_count(); ++k)
      if (k != own) walk(shot, p_.ring_begin(k), p_.ring_end(k) - p_.ring_begin(k));
  }

  std::int64_t edge_tests() const { return edge_tests_; }

 private:
  // The `edges` edges of a ring from vertex w on.
  void walk(Shot& shot, std::size_t w, std::size_t edges) {
    Place at_w = shot.place(w);
    for (std::size_t k = 0; k < edges; ++k) {
      const std::size_t u = p_.next(w);
      const Place at_u = shot.place(u);
      ++edge_tests_;
      if (at_u == Place::Ahead) shot.offer_ahead(u);
      if (side_of(at_w) != side_of(at_u)) shot.offer_edge(w, side_of(at_w) < 0);
      w = u, at_w = at_u;
    }
  }

  const Polygon& p_;
  std::int64_t edge_tests_ = 0;
};

}  // namespace
}  // namespace naive

Decomposition naive_complete(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                             Counters& counters) {
  naive::EveryEdge search(p);
  Decomposition out = naive::resolve(p, std::move(d), notches, search, counters);
  counters["edge_tests"] = search.edge_tests();
  return out;
}

Decomposition naive_decomposition(const Polygon& p, Counters& counters) {
  return naive_complete(p, Decomposition{}, naive::notches_of(p), counters);
}

namespace {

// Counter-clockwise order of the neighbours of a vertex, starting anywhere: by half-plane, then by turn.
struct AroundVertex {
  const std::vector<QPoint>& pts;
  const QPoint& centre;
  int half(const QPoint& q) const {
    return q.y() > centre.y() || (q.y() == centre.y() && q.x() > centre.x()) ? 0 : 1;
  }
  bool operator()(VertexId a, VertexId b) const {
    const int ha = half(pts[a]), hb = half(pts[b]);
    return ha != hb ? ha < hb : orient(centre, pts[a], pts[b]) > 0;
  }
};

// The boundary of P as one cycle of vertex ids per ring, Steiner points inside the edges they name, in
// order.
std::vector<std::vector<VertexId>> boundary_cycles(const Polygon& p, const Decomposition& d,
                                                   const std::vector<QPoint>& pts) {
  const std::size_t n = p.size();
  std::vector<std::vector<VertexId>> on_edge(n);
  for (std::size_t k = 0; k < d.steiner.size(); ++k)
    if (d.steiner[k].boundary_edge != kInterior) on_edge[d.steiner[k].boundary_edge].push_back(static_cast<VertexId>(n + k));
  std::vector<std::vector<VertexId>> cycles(p.ring_count());
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<VertexId>& cycle = cycles[p.ring_of(i)];
    cycle.push_back(static_cast<VertexId>(i));
    std::sort(on_edge[i].begin(), on_edge[i].end(), [&](VertexId s, VertexId t) {
      return CGAL::squared_distance(pts[i], pts[s]) < CGAL::squared_distance(pts[i], pts[t]);
    });
    cycle.insert(cycle.end(), on_edge[i].begin(), on_edge[i].end());
  }
  return cycles;
}

}  // namespace

NaiveGraph naive_graph(const Polygon& p, const Decomposition& d) {
  const std::vector<QPoint> pts = exact_points(p, d);
  NaiveGraph g;
  g.adjacent.resize(pts.size());
  g.degree.assign(pts.size(), 0);
  auto link = [&](VertexId a, VertexId b) {
    for (const auto& [u, w] : {std::pair{a, b}, std::pair{b, a}}) {
      if (g.degree[u] == 3) throw std::invalid_argument("vertex " + std::to_string(u) + " has degree above 3");
      g.adjacent[u][g.degree[u]++] = w;
    }
  };
  for (const std::vector<VertexId>& cycle : boundary_cycles(p, d, pts))
    for (std::size_t i = 0; i < cycle.size(); ++i) link(cycle[i], cycle[(i + 1) % cycle.size()]);
  for (const Cut& c : d.cuts) link(c.a, c.b);
  for (std::size_t v = 0; v < pts.size(); ++v)
    std::sort(g.adjacent[v].begin(), g.adjacent[v].begin() + g.degree[v], AroundVertex{pts, pts[v]});
  return g;
}

std::vector<Piece> naive_pieces(const Polygon& p, const Decomposition& d, const NaiveGraph& g) {
  auto slot_of = [&](VertexId v, VertexId w) {
    std::size_t k = 0;
    while (g.adjacent[v][k] != w) ++k;
    return k;
  };
  // Half-edge v -> adjacent[v][k] is 3 v + k; a piece lies to the left of each of its half-edges.
  std::vector<char> walked(3 * g.adjacent.size(), 0);
  std::vector<Piece> pieces;
  for (const std::vector<VertexId>& cycle : boundary_cycles(p, d, exact_points(p, d)))
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      VertexId from = cycle[i], to = cycle[(i + 1) % cycle.size()];
      std::size_t slot = slot_of(from, to);
      if (walked[3 * from + slot]) continue;
      Piece piece;
      while (!walked[3 * from + slot]) {
        walked[3 * from + slot] = 1;
        piece.push_back(from);
        const std::size_t back = slot_of(to, from);
        const std::size_t next = back == 0 ? g.degree[to] - 1 : back - 1;
        from = to, slot = next, to = g.adjacent[from][slot];
      }
      pieces.push_back(std::move(piece));
    }
  return pieces;
}

}  // namespace pd
