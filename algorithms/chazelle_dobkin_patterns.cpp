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

// The open cone of directions that resolve what is left of the angle at an adapted notch, as its two
// bounding directions (lower, upper) in counter-clockwise order: the extensions of the arms beyond the
// notch while the angle left is reflex, the arms themselves once it is not.
struct Cone {
  Vec lower, upper;
};
Cone cone_of(const QPoint& v, const AdaptedNotch& a) {
  const Vec f = a.forward - v, b = a.backward - v;
  if (cross(f, b) < 0) return {-b, -f};
  return {f, b};
}

}  // namespace

Patterns::Patterns(const Polygon& p) : p_(p) {
  exact_.reserve(p.size());
  for (const Point& v : p.vertices()) exact_.push_back(to_exact(v));
  for (std::size_t v = 0; v < p.size(); ++v)
    if (p.is_reflex(v)) notches_.push_back(static_cast<VertexId>(v));
  const std::size_t r = notches_.size();
  sees_notch_.assign(r * r, 0);
  transition_.assign(r * r, 0);
  if (r == 0) return;
  const VisibilityGraph visibility(p);
  std::vector<std::uint32_t> visible;
  std::int64_t triangles = 0;
  for (std::size_t i = 0; i < r; ++i) {
    visible.clear();
    visibility.visible_from(notches_[i], visible, triangles);
    compute_transitions(i, visible);
  }
}

// For each other notch w: the vertex through which notch `from`'s view passes across w's boundary
// position. `visible` is in counter-clockwise order from the notch, so the boundary points the notch
// sees, in boundary order, sweep counter-clockwise around it: the last vertex x seen up to w and the
// first y seen from w on bound the hidden stretch that holds w (when w itself is not seen), and the
// window over it lies on the ray through x when the boundary turns away behind x, else through y.
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
      const VertexId y = *after_w;
      if (orient(p_[v], p_[x], p_[p_.next(x)]) > 0) through = y;
    }
    transition_[from * r + k] = through;
    const bool adjacent = offset(w) == 1 || offset(w) == n - 1;
    sees_notch_[from * r + k] = x == w && !adjacent;
  }
}

AdaptedNotch Patterns::bare(std::size_t notch) const {
  const VertexId v = notches_[notch];
  return {notch, at(static_cast<VertexId>(p_.next(v))), at(static_cast<VertexId>(p_.prev(v)))};
}

bool Patterns::x2(const AdaptedNotch& a, const AdaptedNotch& b) {
  ++x2_tests_;
  const std::size_t r = notches_.size();
  if (!sees_notch_[a.notch * r + b.notch]) return false;
  // The closed cone at an adapted notch: 180-degree angles allowed, the arms themselves not.
  auto resolves = [](const QPoint& v, const AdaptedNotch& n, const QPoint& towards) {
    const Vec d = towards - v, f = n.forward - v, b = n.backward - v;
    const Rational cf = cross(f, d), cb = cross(d, b);
    return (cf > 0 || (cf == 0 && dot(f, d) < 0)) && (cb > 0 || (cb == 0 && dot(d, b) < 0));
  };
  const QPoint& va = at(notches_[a.notch]);
  const QPoint& vb = at(notches_[b.notch]);
  const bool found = resolves(va, a, vb) && resolves(vb, b, va);
  x2_found_ += found;
  return found;
}

std::optional<QPoint> Patterns::x3(const AdaptedNotch& a, const AdaptedNotch& b, const AdaptedNotch& c) {
  ++x3_tests_;
  const std::array<const AdaptedNotch*, 3> tri{&a, &b, &c};
  std::vector<QPoint> region;
  for (const AdaptedNotch* n : tri) region.push_back(at(notches_[n->notch]));
  if (orient(region[0], region[1], region[2]) <= 0) return std::nullopt;  // condition 1
  for (std::size_t k = 0; k < 3; ++k) {
    const AdaptedNotch& n = *tri[k];
    const AdaptedNotch& ahead = *tri[(k + 1) % 3];
    const AdaptedNotch& behind = *tri[(k + 2) % 3];
    const VertexId vid = notches_[n.notch];
    const QPoint& v = at(vid);
    const Vec reference = at(static_cast<VertexId>(p_.next(vid))) - v;
    const Cone cone = cone_of(v, n);
    // Q's edges at this notch: the views across the notches ahead and behind.
    const QPoint& low = at(transition(n.notch, ahead.notch));
    const QPoint& high = at(transition(n.notch, behind.notch));
    if (!turns_before(reference, low - v, cone.upper) || !turns_before(reference, cone.lower, high - v))
      return std::nullopt;
    std::vector<HalfPlane> planes{{v, n.forward}, {n.backward, v}};
    if (turns_before(reference, cone.lower, low - v)) planes.push_back({v, low});
    if (turns_before(reference, high - v, cone.upper)) planes.push_back({high, v});
    for (const HalfPlane& h : planes) {
      region = clip(region, h);
      if (region.size() < 3) return std::nullopt;
    }
  }
  if (twice_area(region) <= 0) return std::nullopt;
  ++x3_candidates_;
  Rational sx = 0, sy = 0;
  for (const QPoint& q : region) sx += q.x(), sy += q.y();
  const QPoint s(sx / static_cast<int>(region.size()), sy / static_cast<int>(region.size()));
  for (const AdaptedNotch* n : tri)
    if (!sees(notches_[n->notch], s)) return std::nullopt;
  ++x3_found_;
  return s;
}

bool Patterns::sees(VertexId v, const QPoint& s) const {
  const QPoint& o = at(v);
  const std::size_t nv = p_.next(v), pv = p_.prev(v);
  const Vec d = s - o, f = at(static_cast<VertexId>(nv)) - o, b = at(static_cast<VertexId>(pv)) - o;
  if (d == Vec(0, 0)) return false;
  const bool reflex = cross(f, b) < 0;
  const bool inside = reflex ? !(cross(b, d) >= 0 && cross(d, f) >= 0) : cross(f, d) > 0 && cross(d, b) > 0;
  if (!inside) return false;
  const Segment seg(o, s);
  for (std::size_t e = 0; e < p_.size(); ++e) {
    const std::size_t e1 = p_.next(e);
    if (e == v || e1 == v) continue;
    if (CGAL::do_intersect(seg, Segment(at(static_cast<VertexId>(e)), at(static_cast<VertexId>(e1))))) return false;
  }
  return true;
}

void Patterns::report(Counters& counters) const {
  counters["x2_tests"] += x2_tests_;
  counters["x2_found"] += x2_found_;
  counters["x3_tests"] += x3_tests_;
  counters["x3_candidates"] += x3_candidates_;
  counters["x3_found"] += x3_found_;
}

}  // namespace pd::cd
