// Pattern detection for Chazelle-Dobkin: engines/chazelle_dobkin/patterns.h says the method, and
// docs/algorithms/chazelle-dobkin-patterns.md the reconstruction of Theorem 14's segments and the
// deviation from Theorem 11.
#include "engines/chazelle_dobkin/patterns.h"

#include "engines/chazelle_dobkin/geodesics.h"
#include "engines/search/visibility.h"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace pd::cd {
namespace {

using Vec = ExactKernel::Vector_2;
using Segment = ExactKernel::Segment_2;

// The region of an X3 test is computed on two kernels: on intervals first (a filter, whose signs throw
// CGAL::Uncertain_conversion_exception where they are not certain) and exactly on rationals. The same
// templates serve both, so that the two take the same branches wherever the filter's signs are certain.
template <class V>
std::decay_t<decltype(std::declval<V>().x())> cross(const V& u, const V& v) { return u.x() * v.y() - u.y() * v.x(); }
template <class V>
std::decay_t<decltype(std::declval<V>().x())> dot(const V& u, const V& v) { return u.x() * v.x() + u.y() * v.y(); }
template <class FT>
int sign_of(const FT& value) { return static_cast<int>(CGAL::make_certain(CGAL::sign(value))); }

// The half-plane left of the directed line from `from` through `to`, with or without that line.
template <class P>
struct HalfPlane {
  P from, to;
  bool closed = false;
};

template <class P>
bool strictly_left(const HalfPlane<P>& h, const P& q) {
  return sign_of(cross(h.to - h.from, q - h.from)) > 0;
}

}  // namespace

// The Steiner points of an X3 test: every condition taken closed gives the convex polygon K (its
// vertices, possibly with repeats; a segment or a single point where K has no interior; none when
// there is no Steiner point), and the open conditions are kept to test points of K's boundary.
template <class P>
struct Region {
  std::vector<P> vertices;
  std::vector<HalfPlane<P>> open;

  bool empty() const { return vertices.empty(); }
  bool admits(const P& q) const {
    return std::all_of(open.begin(), open.end(), [&](const HalfPlane<P>& h) { return strictly_left(h, q); });
  }
};

namespace {

// Where segment se meets h's line, for s and e on opposite sides of it.
template <class P>
P crossing(const HalfPlane<P>& h, const P& s, const P& e) {
  using FT = std::decay_t<decltype(s.x())>;
  const auto d = h.to - h.from;
  const FT fs = cross(d, s - h.from), fe = cross(d, e - h.from);
  const FT t = fs / (fs - fe);
  return P(s.x() + t * (e.x() - s.x()), s.y() + t * (e.y() - s.y()));
}

// The part of convex polygon `poly` on the closed left side of h (Sutherland-Hodgman, one plane).
template <class P>
std::vector<P> clip(const std::vector<P>& poly, const HalfPlane<P>& h) {
  std::vector<P> out;
  const auto d = h.to - h.from;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P& s = poly[i];
    const P& e = poly[(i + 1) % poly.size()];
    const int os = sign_of(cross(d, s - h.from)), oe = sign_of(cross(d, e - h.from));
    if (os >= 0) out.push_back(s);
    if (os * oe < 0) out.push_back(crossing(h, s, e));
  }
  return out;
}

template <class P>
std::decay_t<decltype(std::declval<P>().x())> twice_area(const std::vector<P>& poly) {
  std::decay_t<decltype(std::declval<P>().x())> sum = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P& s = poly[i];
    const P& e = poly[(i + 1) % poly.size()];
    sum += s.x() * e.y() - s.y() * e.x();
  }
  return sum;
}

// Directions at a notch, ordered by the counter-clockwise angle from `reference` (the notch's forward
// polygon edge), in [0, 360): every direction used here lies in the notch's interior angle, where
// this order is the angular order of the thesis's sweeps.
template <class V>
bool turns_before(const V& reference, const V& d1, const V& d2) {
  auto half = [&](const V& d) {
    const int c = sign_of(cross(reference, d));
    return c > 0 || (c == 0 && sign_of(dot(reference, d)) > 0) ? 0 : 1;
  };
  const int h1 = half(d1), h2 = half(d2);
  if (h1 != h2) return h1 < h2;
  return sign_of(cross(d1, d2)) > 0;
}

// 2v - w: the point such that v lies halfway between it and w (the extension of wv beyond v).
QPoint mirrored(const QPoint& v, const QPoint& w) { return QPoint(2 * v.x() - w.x(), 2 * v.y() - w.y()); }

template <class P>
P average(const std::vector<P>& points) {
  std::decay_t<decltype(std::declval<P>().x())> sx = 0, sy = 0;
  for (const P& q : points) sx += q.x(), sy += q.y();
  const int k = static_cast<int>(points.size());
  return P(sx / k, sy / k);
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

// What x3_region needs at one notch of the triple: the notch, the next polygon vertex (the reference
// direction of turns_before), its joint's arms and the vertices its views across the notch ahead and
// the notch behind pass through.
template <class P>
struct NotchSide {
  P v, after, lower, upper, low, high;
  bool closed;  // the joint's cone includes its arms
};

// The open triangle, each joint's cone (with its arms where the joint allows them) and, at each notch,
// the open side of the views across the other two (the kernel of Q), intersected. K contains the
// region and, where K has interior, its interior lies in the region. Where K is a segment or a point
// (a pattern that exists only in degenerate position, e.g. a Steiner point where three cones' arms
// meet), an open condition either holds at every point of K's relative interior or at none (K was
// clipped by its line), so the average of K's vertices decides whether the region is empty.
template <class P>
Region<P> region_of(const std::array<NotchSide<P>, 3>& sides) {
  Region<P> region{{sides[0].v, sides[1].v, sides[2].v}, {}};
  if (sign_of(cross(sides[1].v - sides[0].v, sides[2].v - sides[0].v)) <= 0) return {};  // condition 1
  region.open = {{sides[0].v, sides[1].v}, {sides[1].v, sides[2].v}, {sides[2].v, sides[0].v}};
  std::vector<HalfPlane<P>> planes;
  for (const NotchSide<P>& n : sides) {
    const auto reference = n.after - n.v, lower = n.lower - n.v, upper = n.upper - n.v;
    // Q's edges at this notch: the views across the notches ahead and behind.
    if (!turns_before(reference, n.low - n.v, upper) || !turns_before(reference, lower, n.high - n.v)) return {};
    planes.push_back({n.v, n.lower, n.closed});
    planes.push_back({n.upper, n.v, n.closed});
    // A view along an arm still bounds the region: the arm may be allowed, the view's line is not.
    if (!turns_before(reference, n.low - n.v, lower)) planes.push_back({n.v, n.low});
    if (!turns_before(reference, upper, n.high - n.v)) planes.push_back({n.high, n.v});
  }
  for (const HalfPlane<P>& h : planes) {
    region.vertices = clip(region.vertices, h);
    if (region.empty()) return {};
    if (!h.closed) region.open.push_back(h);
  }
  if (sign_of(twice_area(region.vertices)) <= 0 && !region.admits(average(region.vertices))) return {};
  return region;
}

using IPoint = IntervalKernel::Point_2;

IPoint approximately(const QPoint& q) { return IPoint(CGAL::to_interval(q.x()), CGAL::to_interval(q.y())); }

std::vector<QPoint> exact_vertices(const Polygon& p) {
  std::vector<QPoint> exact;
  exact.reserve(p.size());
  for (const Point& v : p.vertices()) exact.push_back(to_exact(v));
  return exact;
}

}  // namespace

Patterns::Patterns(const Polygon& p, Views views) : p_(p), exact_(exact_vertices(p)), segments_(p, exact_) {
  for (std::size_t v = 0; v < p.size(); ++v)
    if (p.is_reflex(v)) notches_.push_back(static_cast<VertexId>(v));
  const std::size_t r = notches_.size();
  sees_notch_.assign(r * r, 0);
  transition_.assign(r * r, 0);
  tip_known_.assign(r * r, 0);
  tip_.assign(r * r, std::nullopt);
  compute_bare_cones();
  if (views == Views::kTriangulation) views_from_triangulation();
  else if (r > 0) views_from_geodesics();
}

// From each notch, the tree of its geodesics to every other (geodesics.h): a notch it sees is a
// diagonal's end when the geodesic runs straight through P's interior, and its view passes across any
// other notch w along the ray to the first turn of w's geodesic. A hidden w lies in a pocket behind one
// window of the notch's view, a segment on a ray from the notch through the window's reflex vertex;
// every path to w crosses that window, so its geodesic runs straight from the notch along the ray to
// the window and turns first at the window's vertex (or at one beyond it on the ray, when it passes
// straight through that vertex): the direction is the walks'. An adjacent notch, or one whose segment
// touches the boundary, is seen along that segment. O(n + r^2 log n) for the chords, O(r log r) per
// tree: O(n + r^2 log n) in all, as Theorem 11 and Lemma 5 give.
void Patterns::views_from_geodesics() {
  const std::size_t r = notches_.size();
  std::vector<GeodesicTrees::Terminal> terminals;
  for (VertexId v : notches_) terminals.push_back({v, true, at(v)});
  GeodesicTrees trees(p_, terminals);
  for (std::size_t from = 0; from < r; ++from)
    for (std::size_t k = 0; k < r; ++k) {
      if (k == from) continue;
      const GeodesicTrees::Start start = trees.start(from, k);
      if (!start.toward.at_vertex) throw std::logic_error("chazelle-dobkin: a geodesic turns inside an edge");
      const VertexId w = notches_[k];
      const bool adjacent = w == next(notches_[from]) || w == prev(notches_[from]);
      transition_[from * r + k] = static_cast<VertexId>(start.toward.edge);
      sees_notch_[from * r + k] = start.clear && !adjacent;
    }
  view_chords_ = trees.chords();
  view_tangent_steps_ = trees.tangent_steps();
}

void Patterns::views_from_triangulation() {
  const VisibilityGraph visibility(p_);
  std::vector<std::uint32_t> visible, seen;
  std::int64_t triangles = 0;
  for (std::size_t i = 0; i < notches_.size(); ++i) {
    visible.clear();
    seen.clear();
    visibility.visible_from(notches_[i], visible, triangles, &seen);
    compute_transitions(i, visible, seen);
  }
}

// For each other notch w: the vertex through which notch `from`'s view passes across w's boundary
// position. `visible` is in counter-clockwise order from the notch, so the boundary points the notch
// sees, in boundary order, sweep counter-clockwise around it: the last vertex x seen up to w and the
// first y seen from w on bound the stretch that holds w (when w itself is not seen). Between x and y
// the notch sees part of one edge: the boundary before that edge lies behind the window on the ray
// through x, the boundary after it behind the window through y. (Usually the edge starts at x or
// ends at y and only one of them is a window; when the notch looks between x and y onto a farther
// edge, both are.)
void Patterns::compute_transitions(std::size_t from, const std::vector<std::uint32_t>& visible,
                                   const std::vector<std::uint32_t>& seen) {
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
      const VertexId edge = seen[static_cast<std::size_t>(after_w - visible.begin()) - 1];
      if (offset(w) > offset(edge)) through = *after_w;
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
    forward_branch_.push_back({k, after, mirrored(pv, before), /*closed*/ false});
    backward_branch_.push_back({k, mirrored(pv, after), before, /*closed*/ false});
  }
}

Joint Patterns::cone(const AdaptedNotch& a) const {
  const QPoint& v = notch_point(a.notch);
  if (cross(a.forward - v, a.backward - v) < 0)
    return {a.notch, mirrored(v, a.backward), mirrored(v, a.forward), /*closed*/ true};
  return {a.notch, a.forward, a.backward, /*closed*/ false};
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

Joint::Joint(std::size_t notch, QPoint lower, QPoint upper, bool closed)
    : notch(notch), lower(std::move(lower)), upper(std::move(upper)), closed(closed),
      lower_approx(approximately(this->lower)), upper_approx(approximately(this->upper)) {}

// The region of Steiner points of Theorem 14 before condition 3 (region_of), found empty on intervals
// where their signs settle it (the filter: when every sign it takes is certain, its branches are the
// exact computation's), else computed on rationals.
Region<QPoint> Patterns::x3_region(const std::array<const Joint*, 3>& joints) const {
  auto sides = [&](auto vertex, auto lower, auto upper) {
    std::array<NotchSide<decltype(vertex(VertexId{0}))>, 3> out;
    for (std::size_t k = 0; k < 3; ++k) {
      const Joint& n = *joints[k];
      const std::size_t ahead = joints[(k + 1) % 3]->notch, behind = joints[(k + 2) % 3]->notch;
      const VertexId v = notches_[n.notch];
      out[k] = {vertex(v), vertex(next(v)), lower(n), upper(n), vertex(transition(n.notch, ahead)),
                vertex(transition(n.notch, behind)), n.closed};
    }
    return out;
  };
  {
    CGAL::Protect_FPU_rounding<true> upwards;
    try {
      const auto approximate = sides([&](VertexId u) { return IPoint(p_[u].x(), p_[u].y()); },
                                     [](const Joint& n) { return n.lower_approx; }, [](const Joint& n) { return n.upper_approx; });
      if (region_of(approximate).empty()) return {};
    } catch (const CGAL::Uncertain_conversion_exception&) {
    }
  }
  return region_of(sides([&](VertexId u) { return at(u); }, [](const Joint& n) { return n.lower; },
                         [](const Joint& n) { return n.upper; }));
}

// The region's point is the Steiner point: condition 3 of Theorem 14 follows from the views that
// bound the region (see the header comment).
std::optional<QPoint> Patterns::found(const QPoint& s) {
  ++x3_found_;
  return s;
}

std::optional<QPoint> Patterns::x3(const Joint& a, const Joint& b, const Joint& c) {
  ++x3_tests_;
  const std::array<const Joint*, 3> joints{&a, &b, &c};
  const Region<QPoint> region = x3_region(joints);
  if (region.empty()) return std::nullopt;
  return found(average(region.vertices));
}

std::optional<QPoint> Patterns::x3_extreme(const Joint& a, const Joint& b, const Joint& c, bool counter_clockwise) {
  ++x3_tests_;
  const std::array<const Joint*, 3> joints{&a, &b, &c};
  const Region<QPoint> region = x3_region(joints);
  if (region.empty()) return std::nullopt;
  // K's vertices other than a itself (a is one when it lies inside the other joints' cones; it is
  // never a Steiner point, and every direction from it ties).
  const QPoint& v = notch_point(a.notch);
  const int further = counter_clockwise ? 1 : -1;
  const QPoint* best = nullptr;
  for (const QPoint& q : region.vertices)
    if (q != v && (!best || orient(v, *best, q) == further)) best = &q;
  // A vertex on the extreme ray that meets the open conditions is itself a Steiner point.
  for (const QPoint& q : region.vertices)
    if (orient(v, *best, q) == 0 && region.admits(q)) return found(q);
  const QPoint mid = average(region.vertices);
  const QPoint s(best->x() + (mid.x() - best->x()) / 64, best->y() + (mid.y() - best->y()) / 64);
  return found(s);
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
  counters["x3_found"] += x3_found_;
  counters["x4_tests"] += x4_tests_;
  counters["x4_found"] += x4_found_;
  counters["tips"] += tips_;
  counters["tips_found"] += tips_found_;
  counters["segment_search_steps"] += segments_.steps();
  counters["view_chords"] += view_chords_;
  counters["view_tangent_steps"] += view_tangent_steps_;
}

}  // namespace pd::cd
