// Pattern detection for Chazelle-Dobkin: see chazelle_dobkin_patterns.h for the method, the
// reconstruction of Theorem 14's segments and the deviation from Theorem 11.
#include "algorithms/chazelle_dobkin_patterns.h"

#include "algorithms/visibility.h"

#include <algorithm>
#include <array>

namespace pd::cd {
namespace {

using Vec = ExactKernel::Vector_2;
using Segment = ExactKernel::Segment_2;

Rational cross(const Vec& u, const Vec& v) { return u.x() * v.y() - u.y() * v.x(); }
Rational dot(const Vec& u, const Vec& v) { return u.x() * v.x() + u.y() * v.y(); }

// The open half-plane left of the directed line from `from` through `to`.
struct HalfPlane {
  QPoint from, to;
};

// Where segment se meets h's line, for s and e on opposite sides of it.
QPoint crossing(const HalfPlane& h, const QPoint& s, const QPoint& e) {
  const Vec d = h.to - h.from;
  const Rational fs = cross(d, s - h.from), fe = cross(d, e - h.from);
  const Rational t = fs / (fs - fe);
  return QPoint(s.x() + t * (e.x() - s.x()), s.y() + t * (e.y() - s.y()));
}

// The part of convex polygon `poly` on the closed left side of h (Sutherland-Hodgman, one plane).
std::vector<QPoint> clip(const std::vector<QPoint>& poly, const HalfPlane& h) {
  std::vector<QPoint> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const QPoint& s = poly[i];
    const QPoint& e = poly[(i + 1) % poly.size()];
    const int os = orient(h.from, h.to, s), oe = orient(h.from, h.to, e);
    if (os >= 0) out.push_back(s);
    if (os * oe < 0) out.push_back(crossing(h, s, e));
  }
  return out;
}

Rational twice_area(const std::vector<QPoint>& poly) {
  Rational sum = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const QPoint& s = poly[i];
    const QPoint& e = poly[(i + 1) % poly.size()];
    sum += s.x() * e.y() - s.y() * e.x();
  }
  return sum;
}

// Directions at a notch, ordered by the counter-clockwise angle from `reference` (the notch's forward
// polygon edge), in [0, 360): every direction used here lies in the notch's interior angle, where
// this order is the angular order of the thesis's sweeps.
bool turns_before(const Vec& reference, const Vec& d1, const Vec& d2) {
  auto half = [&](const Vec& d) {
    const Rational c = cross(reference, d);
    return c > 0 || (c == 0 && dot(reference, d) > 0) ? 0 : 1;
  };
  const int h1 = half(d1), h2 = half(d2);
  if (h1 != h2) return h1 < h2;
  return cross(d1, d2) > 0;
}

// 2v - w: the point such that v lies halfway between it and w (the extension of wv beyond v).
QPoint mirrored(const QPoint& v, const QPoint& w) { return QPoint(2 * v.x() - w.x(), 2 * v.y() - w.y()); }

QPoint average(const std::vector<QPoint>& points) {
  Rational sx = 0, sy = 0;
  for (const QPoint& q : points) sx += q.x(), sy += q.y();
  const Rational k = static_cast<int>(points.size());
  return QPoint(sx / k, sy / k);
}

// The Steiner point's angle at the tip of a pair of notch edges: whether the edge from tip to
// `other` splits the angle on the side away from the pocket of a and b into two angles of at most
// 180 degrees, i.e. lies in the closed cone between the extensions of a->tip and b->tip.
bool splits_reflex_side(const QPoint& a, const QPoint& b, const QPoint& tip, const QPoint& other) {
  const Vec u = tip - a, w = tip - b, d = other - tip;
  const Rational uw = cross(u, w);
  if (uw == 0) return orient(a, b, other) >= 0;
  const int s = uw > 0 ? 1 : -1;
  return s * cross(u, d) >= 0 && s * cross(d, w) >= 0;
}

std::vector<QPoint> exact_vertices(const Polygon& p) {
  std::vector<QPoint> exact;
  exact.reserve(p.size());
  for (const Point& v : p.vertices()) exact.push_back(to_exact(v));
  return exact;
}

}  // namespace

Patterns::Patterns(const Polygon& p) : p_(p), exact_(exact_vertices(p)), segments_(p, exact_) {
  for (std::size_t v = 0; v < p.size(); ++v)
    if (p.is_reflex(v)) notches_.push_back(static_cast<VertexId>(v));
  const std::size_t r = notches_.size();
  sees_notch_.assign(r * r, 0);
  transition_.assign(r * r, 0);
  transition_reach_.assign(r * r, std::nullopt);
  side_reach_.assign(r * r, std::nullopt);
  tip_known_.assign(r * r, 0);
  tip_.assign(r * r, std::nullopt);
  if (r == 0) return;
  const VisibilityGraph visibility(p);
  visible_.resize(r);
  seen_edge_.resize(r);
  std::int64_t triangles = 0;
  for (std::size_t i = 0; i < r; ++i) {
    visibility.visible_from(notches_[i], visible_[i], triangles, &seen_edge_[i]);
    compute_transitions(i, visible_[i]);
  }
  compute_bare_cones();
}

// For each other notch w: the vertex through which notch `from`'s view passes across w's boundary
// position. `visible` is in counter-clockwise order from the notch, so the boundary points the notch
// sees, in boundary order, sweep counter-clockwise around it: the last vertex x seen up to w and the
// first y seen from w on bound the stretch that holds w (when w itself is not seen). Between x and y
// the notch sees part of one edge: the boundary before that edge lies behind the window on the ray
// through x, the boundary after it behind the window through y. (Usually the edge starts at x or
// ends at y and only one of them is a window; when the notch looks between x and y onto a farther
// edge, both are.)
void Patterns::compute_transitions(std::size_t from, const std::vector<std::uint32_t>& visible) {
  const std::size_t n = p_.size(), r = notches_.size();
  const VertexId v = notches_[from];
  auto offset = [&](std::size_t u) { return (u + n - v) % n; };
  for (std::size_t k = 0; k < r; ++k) {
    if (k == from) continue;
    const VertexId w = notches_[k];
    const auto after_w = std::upper_bound(visible.begin(), visible.end(), offset(w),
                                          [&](std::size_t o, std::uint32_t u) { return o < offset(u); });
    const VertexId x = *(after_w - 1);
    VertexId through = x;
    if (x != w) {
      const VertexId seen = seen_edge_[from][static_cast<std::size_t>(after_w - visible.begin()) - 1];
      if (offset(w) > offset(seen)) through = *after_w;
    }
    transition_[from * r + k] = through;
    const bool adjacent = offset(w) == 1 || offset(w) == n - 1;
    sees_notch_[from * r + k] = x == w && !adjacent;
  }
}

// The bare notches with their joints and branches, O(r).
void Patterns::compute_bare_cones() {
  for (std::size_t k = 0; k < notches_.size(); ++k) {
    const VertexId v = notches_[k];
    const QPoint &pv = at(v), &after = at(next(v)), &before = at(prev(v));
    bare_.push_back({k, after, before});
    bare_joint_.push_back(cone(bare_.back()));
    forward_branch_.push_back({k, after, mirrored(pv, before)});
    backward_branch_.push_back({k, mirrored(pv, after), before});
  }
}

Joint Patterns::cone(const AdaptedNotch& a) const {
  const QPoint& v = notch_point(a.notch);
  if (cross(a.forward - v, a.backward - v) < 0) return {a.notch, mirrored(v, a.backward), mirrored(v, a.forward)};
  return {a.notch, a.forward, a.backward};
}

Joint Patterns::joint(const AdaptedNotch& a) const {
  const AdaptedNotch& bare = bare_[a.notch];
  if (a.forward == bare.forward && a.backward == bare.backward) return bare_joint_[a.notch];
  return cone(a);
}

// The closed cone at an adapted notch: 180-degree angles allowed, the arms themselves not.
bool Patterns::resolves(const AdaptedNotch& n, const QPoint& towards) const {
  const QPoint& v = notch_point(n.notch);
  const Vec d = towards - v, f = n.forward - v, b = n.backward - v;
  const Rational cf = cross(f, d), cb = cross(d, b);
  return (cf > 0 || (cf == 0 && dot(f, d) < 0)) && (cb > 0 || (cb == 0 && dot(d, b) < 0));
}

bool Patterns::x2(const AdaptedNotch& a, const AdaptedNotch& b) {
  ++x2_tests_;
  const bool found = diagonal(a.notch, b.notch) && resolves(a, notch_point(b.notch)) && resolves(b, notch_point(a.notch));
  x2_found_ += found;
  return found;
}

// The region of Steiner points of Theorem 14 before condition 3: the open triangle, each joint's cone
// and, at each notch, the views across the other two (the kernel of Q). Returned closed, with its
// vertices; empty when it has no interior.
std::vector<QPoint> Patterns::x3_region(const std::array<const Joint*, 3>& joints) const {
  std::vector<QPoint> region;
  for (const Joint* j : joints) region.push_back(notch_point(j->notch));
  if (orient(region[0], region[1], region[2]) <= 0) return {};  // condition 1
  for (std::size_t k = 0; k < 3; ++k) {
    const Joint& n = *joints[k];
    const std::size_t ahead = joints[(k + 1) % 3]->notch, behind = joints[(k + 2) % 3]->notch;
    const VertexId vid = notches_[n.notch];
    const QPoint& v = at(vid);
    const Vec reference = at(static_cast<VertexId>(p_.next(vid))) - v;
    const Vec lower = n.lower - v, upper = n.upper - v;
    // Q's edges at this notch: the views across the notches ahead and behind.
    const QPoint& low = at(transition(n.notch, ahead));
    const QPoint& high = at(transition(n.notch, behind));
    if (!turns_before(reference, low - v, upper) || !turns_before(reference, lower, high - v)) return {};
    std::vector<HalfPlane> planes{{v, n.lower}, {n.upper, v}};
    if (turns_before(reference, lower, low - v)) planes.push_back({v, low});
    if (turns_before(reference, high - v, upper)) planes.push_back({high, v});
    for (const HalfPlane& h : planes) {
      region = clip(region, h);
      if (region.size() < 3) return {};
    }
  }
  if (twice_area(region) <= 0) return {};
  return region;
}

// The region's two bounding rays at notch n: the lower one turned furthest of the cone's lower arm, the
// view across the notch ahead and the triangle's side towards it; the upper one likewise, turned least.
// The region lies less than 180 degrees counter-clockwise of each lower ray and clockwise of each
// upper one, so one orientation compares two of them (the triangle's side may point out of P's angle
// at the notch, so the angle from the notch's edge would not).
std::array<Patterns::Bound, 2> Patterns::bounds(const Joint& n, std::size_t ahead, std::size_t behind) {
  const QPoint& v = notch_point(n.notch);
  const std::size_t r = notches_.size();
  const QPoint &low_view = at(transition(n.notch, ahead)), &high_view = at(transition(n.notch, behind));
  const std::array<std::pair<const QPoint*, std::optional<QPoint>*>, 3> lows{
      {{&n.lower, &n.lower_reach},
       {&low_view, &transition_reach_[n.notch * r + ahead]},
       {&notch_point(ahead), &side_reach_[n.notch * r + ahead]}}};
  const std::array<std::pair<const QPoint*, std::optional<QPoint>*>, 3> highs{
      {{&n.upper, &n.upper_reach},
       {&high_view, &transition_reach_[n.notch * r + behind]},
       {&notch_point(behind), &side_reach_[n.notch * r + behind]}}};
  auto low = lows[0], high = highs[0];
  for (const auto& b : lows)
    if (orient(v, *low.first, *b.first) > 0) low = b;
  for (const auto& b : highs)
    if (orient(v, *b.first, *high.first) > 0) high = b;
  return {Bound{low.first, &memo_reach(*low.second, n.notch, *low.first)},
          Bound{high.first, &memo_reach(*high.second, n.notch, *high.first)}};
}

// The reach of the ray from notch `from` through `through`, computed on the first call.
const QPoint& Patterns::memo_reach(std::optional<QPoint>& slot, std::size_t from, const QPoint& through) {
  if (!slot) slot = reach(from, through);
  return *slot;
}

// Condition 3 of Theorem 14 (C, A and B well defined, i.e. Q lies in P): Q's edge from each notch runs
// along the notch's bounding ray to the corner where it meets the neighbouring notch's ray; the edge lies
// in the closed P exactly when the corner is no farther along the ray than its reach. Q's boundary then
// lies in P, so Q does, and every point of the region's interior (the interior of Q's kernel) sees the
// three notches through Q's interior.
bool Patterns::q_inside(const std::array<const Joint*, 3>& joints) {
  std::array<std::array<Bound, 2>, 3> bound;
  for (std::size_t k = 0; k < 3; ++k)
    bound[k] = bounds(*joints[k], joints[(k + 1) % 3]->notch, joints[(k + 2) % 3]->notch);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t w = (k + 1) % 3;
    const QPoint &a = notch_point(joints[k]->notch), &b = notch_point(joints[w]->notch);
    const Bound &from_a = bound[k][0], &from_b = bound[w][1];
    const Vec da = *from_a.through - a, db = *from_b.through - b, ab = b - a;
    const Rational reach_a = dot(*from_a.reach - a, da), reach_b = dot(*from_b.reach - b, db);
    const Rational den = cross(da, db);
    // Both rays along ab (a positive area region leaves no other parallel case): Q's edge is ab.
    if (den == 0) {
      if (dot(ab, da) > reach_a) return false;
      continue;
    }
    // The corner a + s da = b + t db.
    const Rational s = cross(ab, db) / den, t = cross(ab, da) / den;
    if (s * dot(da, da) > reach_a || t * dot(db, db) > reach_b) return false;
  }
  return true;
}

// Condition 3 decides whether the chosen point of the region is the pattern's Steiner point.
std::optional<QPoint> Patterns::found(const QPoint& s, const std::array<const Joint*, 3>& joints) {
  if (!q_inside(joints)) return std::nullopt;
  ++x3_found_;
  return s;
}

QPoint Patterns::reach(std::size_t notch, const QPoint& through) {
  ++reach_rays_;
  return reach_along(notch, through - notch_point(notch));
}

// Where the ray from notch k in direction d leaves P. Its visible vertices are sorted by angle from its
// forward edge; between two consecutive ones the ray meets the one edge seen there, inside it.
QPoint Patterns::reach_along(std::size_t k, const Vec& d) {
  const VertexId v = notches_[k];
  const QPoint& o = at(v);
  const Vec reference = at(next(v)) - o;
  const std::vector<std::uint32_t>& visible = visible_[k];
  const auto it = std::partition_point(visible.begin(), visible.end(),
                                       [&](std::uint32_t u) { return turns_before(reference, at(u) - o, d); });
  if (it == visible.end()) return o;  // d leaves the notch's angle
  const std::size_t i = static_cast<std::size_t>(it - visible.begin());
  if (cross(at(*it) - o, d) == 0) return past_visible(k, i, d);
  if (const auto hit = on_seen_edge(o, d, seen_edge_[k][i - 1])) return *hit;
  return follow(v, d);
}

// The ray from notch k along d passes through its visible vertex visible_[k][i]. Where it goes on into
// P's interior, the edges at that vertex lie on one side of the ray (both d and the way back to the
// notch point into P's angle there), and beyond the vertex the ray meets the edge the notch sees next
// to it on the other side, unless it meets a vertex there.
QPoint Patterns::past_visible(std::size_t k, std::size_t i, const Vec& d) {
  const std::vector<std::uint32_t>& visible = visible_[k];
  const VertexId x = visible[i];
  if (!into_interior(x, d)) return follow(x, d);
  const QPoint& o = notch_point(k);
  const int behind = orient(o, at(x), at(prev(x)));
  const int side = behind != 0 ? behind : orient(o, at(x), at(next(x)));
  const bool free_clockwise = side > 0 && i > 0, free_counter_clockwise = side < 0 && i + 1 < visible.size();
  if (free_clockwise || free_counter_clockwise)
    if (const auto hit = on_seen_edge(o, d, seen_edge_[k][free_clockwise ? i - 1 : i])) return *hit;
  return follow(x, d);
}

// Where the ray from o along d crosses the edge from `edge` to its successor, if it does inside it.
std::optional<QPoint> Patterns::on_seen_edge(const QPoint& o, const Vec& d, VertexId edge) const {
  const QPoint &e0 = at(edge), &e1 = at(next(edge));
  const Rational c0 = cross(d, e0 - o), c1 = cross(d, e1 - o);
  if (c0 == 0 || c1 == 0 || (c0 > 0) == (c1 > 0)) return std::nullopt;
  const Rational t = c0 / (c0 - c1);
  const QPoint hit(e0.x() + t * (e1.x() - e0.x()), e0.y() + t * (e1.y() - e0.y()));
  if (dot(hit - o, d) <= 0) return std::nullopt;
  return hit;
}

// Whether direction d at vertex z points strictly into P's interior angle there.
bool Patterns::into_interior(VertexId z, const Vec& d) const {
  const Vec f = at(next(z)) - at(z), b = at(prev(z)) - at(z);
  const bool along_f = cross(f, d) == 0 && dot(f, d) > 0;
  return !along_f && turns_before(f, d, b);
}

// The ray along d that has reached vertex z of P, in degenerate position: it runs on along an edge
// that continues it, stops where it leaves P's angle, and otherwise crosses P's interior to the next
// boundary point, found by a scan of all edges (O(n), counted in reach_scans).
QPoint Patterns::follow(VertexId z, const Vec& d) {
  for (;;) {
    const QPoint& o = at(z);
    const Vec f = at(next(z)) - o, b = at(prev(z)) - o;
    if (cross(f, d) == 0 && dot(f, d) > 0) {
      z = next(z);
    } else if (cross(b, d) == 0 && dot(b, d) > 0) {
      z = prev(z);
    } else if (!into_interior(z, d)) {
      return o;
    } else {
      ++reach_scans_;
      Contact c = first_contact(z, d);
      if (!c.vertex) return c.point;
      z = *c.vertex;
    }
  }
}

// The first point of P's boundary beyond vertex z on the ray along d: a vertex, or a point inside an edge.
Patterns::Contact Patterns::first_contact(VertexId z, const Vec& d) const {
  const QPoint& o = at(z);
  std::optional<Rational> nearest;
  Contact best{o, std::nullopt};
  auto offer = [&](const QPoint& q, std::optional<VertexId> vertex) {
    const Rational t = dot(q - o, d);
    if (t > 0 && (!nearest || t < *nearest)) nearest = t, best = {q, vertex};
  };
  for (VertexId u = 0; u < exact_.size(); ++u) {
    const VertexId w = next(u);
    if (u == z || w == z) continue;
    const Rational cu = cross(d, at(u) - o), cw = cross(d, at(w) - o);
    if (cu == 0) offer(at(u), u);
    if (cw == 0) offer(at(w), w);
    if (cu != 0 && cw != 0 && (cu > 0) != (cw > 0)) {
      const Rational t = cu / (cu - cw);
      offer(QPoint(at(u).x() + t * (at(w).x() - at(u).x()), at(u).y() + t * (at(w).y() - at(u).y())), std::nullopt);
    }
  }
  return best;
}

std::optional<QPoint> Patterns::x3(const Joint& a, const Joint& b, const Joint& c) {
  ++x3_tests_;
  const std::array<const Joint*, 3> joints{&a, &b, &c};
  const std::vector<QPoint> region = x3_region(joints);
  if (region.empty()) return std::nullopt;
  ++x3_candidates_;
  return found(average(region), joints);
}

std::optional<QPoint> Patterns::x3_extreme(const Joint& a, const Joint& b, const Joint& c, bool counter_clockwise) {
  ++x3_tests_;
  const std::array<const Joint*, 3> joints{&a, &b, &c};
  const std::vector<QPoint> region = x3_region(joints);
  if (region.empty()) return std::nullopt;
  ++x3_candidates_;
  const QPoint& v = notch_point(a.notch);
  const QPoint* best = &region[0];
  for (const QPoint& q : region) {
    const int turn = orient(v, *best, q);
    if (counter_clockwise ? turn > 0 : turn < 0) best = &q;
  }
  const QPoint mid = average(region);
  const QPoint s(best->x() + (mid.x() - best->x()) / 64, best->y() + (mid.y() - best->y()) / 64);
  return found(s, joints);
}

// The tip of Q facing the chain from notch a counter-clockwise to notch b (Theorem 15's reductions
// take a Steiner point there): where a's edge turned as far as it may towards that chain meets b's.
// a's edge is bounded by its range, by its view across b and by the line ab; b's likewise.
const std::optional<QPoint>& Patterns::tip(std::size_t a, std::size_t b) {
  const std::size_t r = notches_.size();
  std::optional<QPoint>& out = tip_[a * r + b];
  if (tip_known_[a * r + b]) return out;
  tip_known_[a * r + b] = 1;
  ++tips_;
  const VertexId va = notches_[a], vb = notches_[b];
  const QPoint &pa = at(va), &pb = at(vb);
  const Joint &ja = bare_joint(a), &jb = bare_joint(b);
  const Vec ref_a = at(static_cast<VertexId>(p_.next(va))) - pa;
  const Vec ref_b = at(static_cast<VertexId>(p_.next(vb))) - pb;
  QPoint from_a = ja.lower;
  for (const QPoint& c : {at(transition(a, b)), pb})
    if (turns_before(ref_a, from_a - pa, c - pa)) from_a = c;
  QPoint from_b = jb.upper;
  for (const QPoint& c : {at(transition(b, a)), pa})
    if (turns_before(ref_b, c - pb, from_b - pb)) from_b = c;
  // Each edge must stay in its notch's range (closed).
  if (turns_before(ref_a, ja.upper - pa, from_a - pa) || turns_before(ref_b, from_b - pb, jb.lower - pb)) return out;
  // The rays a -> from_a and b -> from_b: a + s (from_a - a) = b + t (from_b - b), s, t > 0.
  const Vec da = from_a - pa, db = from_b - pb, ab = pb - pa;
  const Rational den = cross(da, db);
  if (den == 0) return out;
  const Rational s = cross(ab, db) / den, t = cross(ab, da) / den;
  if (s <= 0 || t <= 0) return out;
  const QPoint x(pa.x() + s * da.x(), pa.y() + s * da.y());
  if (orient(pa, pb, x) <= 0 || !sees(va, x) || !sees(vb, x)) return out;
  ++tips_found_;
  out = x;
  return out;
}

std::optional<std::pair<QPoint, QPoint>> Patterns::x4(std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
  ++x4_tests_;
  const std::optional<QPoint>& first = tip(a, b);
  if (!first) return std::nullopt;
  const std::optional<QPoint>& second = tip(c, d);
  if (!second || *first == *second) return std::nullopt;
  const QPoint &pa = notch_point(a), &pb = notch_point(b), &pc = notch_point(c), &pd = notch_point(d);
  if (!splits_reflex_side(pa, pb, *first, *second) || !splits_reflex_side(pc, pd, *second, *first)) return std::nullopt;
  // The only crossings are the Steiner points (Lemma 9, condition 1).
  for (const QPoint* u : {&pa, &pb})
    for (const QPoint* w : {&pc, &pd})
      if (CGAL::do_intersect(Segment(*u, *first), Segment(*w, *second))) return std::nullopt;
  if (!inside(*first, *second)) return std::nullopt;
  ++x4_found_;
  return std::make_pair(*first, *second);
}

bool Patterns::sees(VertexId v, const QPoint& s) const {
  const QPoint& o = at(v);
  const std::size_t nv = p_.next(v), pv = p_.prev(v);
  const Vec d = s - o, f = at(static_cast<VertexId>(nv)) - o, b = at(static_cast<VertexId>(pv)) - o;
  if (d == Vec(0, 0)) return false;
  const bool reflex = cross(f, b) < 0;
  const bool inside = reflex ? !(cross(b, d) >= 0 && cross(d, f) >= 0) : cross(f, d) > 0 && cross(d, b) > 0;
  return inside && !segments_.meets_boundary(o, s, v);
}

bool Patterns::inside(const QPoint& s, const QPoint& t) const { return !segments_.meets_boundary(s, t); }

void Patterns::report(Counters& counters) const {
  counters["x2_tests"] += x2_tests_;
  counters["x2_found"] += x2_found_;
  counters["x3_tests"] += x3_tests_;
  counters["x3_candidates"] += x3_candidates_;
  counters["x3_found"] += x3_found_;
  counters["x4_tests"] += x4_tests_;
  counters["x4_found"] += x4_found_;
  counters["tips"] += tips_;
  counters["tips_found"] += tips_found_;
  counters["segment_search_steps"] += segments_.steps();
  counters["reach_rays"] += reach_rays_;
  counters["reach_scans"] += reach_scans_;
}

}  // namespace pd::cd
