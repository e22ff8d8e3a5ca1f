// Ray shooting by convex arcs; see ray_shooting.h.
#include "engines/search/ray_shooting.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pd {
namespace {

int sign_of(const Rational& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// sign(p1 + sign2 * p2) for p1 = e1 * f1, p2 = e2 * f2, each factor a difference of two doubles:
// decided in doubles when the value clears a forward error bound (each difference, product and the
// sum round once, relative error 2^-53 each: at most 5 * 2^-53 * (|p1| + |p2|), here 8 * 2^-52),
// else by rationals. Tiny or huge magnitudes (underflow, overflow) always go to rationals.
int sign_of_products(double ea, double eb, double fa, double fb, double ga, double gb, double ha, double hb, int sign2) {
  // A difference of two doubles has the sign of the exact one: a product with a zero factor is exactly
  // zero, and the sum has the other product's sign (axis-parallel rays and edges, lattice inputs).
  const auto sign = [](double from, double to) { return (to > from) - (to < from); };
  if (ea == eb || fa == fb) return sign2 * sign(ga, gb) * sign(ha, hb);
  if (ga == gb || ha == hb) return sign(ea, eb) * sign(fa, fb);
  const double p1 = (eb - ea) * (fb - fa), p2 = (gb - ga) * (hb - ha);
  const double v = p1 + sign2 * p2, magnitude = std::fabs(p1) + std::fabs(p2);
  const double bound = 8 * std::numeric_limits<double>::epsilon() * magnitude;
  if (magnitude > 1e-280 && magnitude < 1e280) {
    if (v > bound) return 1;
    if (v < -bound) return -1;
  }
  const Rational exact = (Rational(eb) - Rational(ea)) * (Rational(fb) - Rational(fa)) +
                         sign2 * ((Rational(gb) - Rational(ga)) * (Rational(hb) - Rational(ha)));
  return sign_of(exact);
}

}  // namespace

int cross_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign_of_products(a.x(), b.x(), c.y(), d.y(), a.y(), b.y(), c.x(), d.x(), -1);
}

int dot_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign_of_products(a.x(), b.x(), c.x(), d.x(), a.y(), b.y(), c.y(), d.y(), 1);
}

Rational hit_parameter(const Polygon& p, const QPoint& z, const ExactKernel::Vector_2& u, const RayShooter::Hit& hit) {
  const QPoint w = to_exact(p[hit.vertex]);
  if (hit.at_vertex) return ((w - z) * u) / (u * u);
  const ExactKernel::Vector_2 e = to_exact(p[p.next(hit.vertex)]) - w;
  return CGAL::determinant(w - z, e) / CGAL::determinant(u, e);
}

// The ray from o in direction flag * (b - a); `side` is +1 left of it.
struct RayShooter::Ray {
  const Point& o;
  const Point& a;
  const Point& b;
  int flag;
  int side(const Point& v) const { return flag * cross_sign(a, b, o, v); }
  int edge_turn(const Point& e0, const Point& e1) const { return flag * cross_sign(a, b, e0, e1); }
  int ahead(const Point& v) const { return flag * dot_sign(o, v, a, b); }
};

struct RayShooter::Contact {
  std::size_t vertex;  // the vertex met, or the first vertex of the edge crossed
  bool at_vertex;
};

namespace {

// A contact's position along the ray, up to a positive factor ((x - o) . direction), in number type
// T (intervals to filter, rationals to decide): the contact is vertex u, or a point inside the edge u v.
// Every step is stored as a T, never left as a lazy expression over temporaries.
template <class T>
T position(const RayShooter::Ray& ray, const Point& u, const Point& v, bool at_vertex) {
  const T ox(ray.o.x()), oy(ray.o.y());
  const T dx = T(ray.flag) * (T(ray.b.x()) - T(ray.a.x())), dy = T(ray.flag) * (T(ray.b.y()) - T(ray.a.y()));
  T x(u.x()), y(u.y());
  if (!at_vertex) {
    const T ex = T(v.x()) - x, ey = T(v.y()) - y;
    const T sa = dx * (y - oy) - dy * (x - ox), sb = dx * (T(v.y()) - oy) - dy * (T(v.x()) - ox);
    const T lambda = sa / (sa - sb);
    x = x + lambda * ex;
    y = y + lambda * ey;
  }
  const T along = (x - ox) * dx + (y - oy) * dy;
  return along;
}

}  // namespace

RayShooter::RayShooter(const Polygon& p) : p_(p) { cut_into_arcs(); }

// Starting at a reflex vertex (arcs never run through one), an arc grows while the next edge turns
// left or goes straight and the total turn from the arc's first edge stays below 180 degrees.
void RayShooter::cut_into_arcs() {
  const std::size_t n = p_.size();
  std::size_t start = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (p_.is_reflex(v)) {
      start = v;
      break;
    }
  std::size_t arc_first = start;
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t v = start + k;  // the edge v -> v+1 (mod n) is next, unless v closes the loop
    const bool closes = k == n;
    const bool continues = !closes && !p_.is_reflex(v % n) &&
                           (cross_sign(at(arc_first), at(arc_first + 1), at(v), at(v + 1)) > 0 ||
                            (cross_sign(at(arc_first), at(arc_first + 1), at(v), at(v + 1)) == 0 &&
                             dot_sign(at(arc_first), at(arc_first + 1), at(v), at(v + 1)) > 0));
    if (continues) continue;
    arc_start_.push_back(arc_first % n);
    arc_edges_.push_back(v - arc_first);
    Box box{at(arc_first).x(), at(arc_first).x(), at(arc_first).y(), at(arc_first).y()};
    for (std::size_t u = arc_first + 1; u <= v; ++u) {
      box.x0 = std::min(box.x0, at(u).x()), box.x1 = std::max(box.x1, at(u).x());
      box.y0 = std::min(box.y0, at(u).y()), box.y1 = std::max(box.y1, at(u).y());
    }
    box_.push_back(box);
    arc_first = v;
  }
}

// An arc is skipped when its bounding box lies strictly on one side of the ray's line or strictly
// behind the origin (exact tests on the box's corners, which are input coordinates). Contacts are
// ordered along the ray by interval positions, and by rationals when the intervals overlap.
std::optional<RayShooter::Hit> RayShooter::shoot(std::size_t origin, std::size_t through, bool toward) {
  return first_hit({p_[origin], p_[origin], p_[through], toward ? 1 : -1}, origin);
}

std::optional<RayShooter::Hit> RayShooter::shoot_along(std::size_t origin, const Point& a, const Point& b) {
  return first_hit({p_[origin], a, b, 1}, origin);
}

std::optional<RayShooter::Hit> RayShooter::first_hit(const Ray& ray, std::size_t origin) {
  std::vector<Contact> contacts;
  for (std::size_t arc = 0; arc < arc_start_.size(); ++arc)
    if (!box_missed(ray, arc)) contacts_on_arc(ray, arc, contacts);
  CGAL::Interval_nt<> best_at(0);
  auto exact = [&](const Contact& c) {
    return position<Rational>(ray, p_[c.vertex], p_[p_.next(c.vertex)], c.at_vertex);
  };
  std::optional<Contact> best_contact;
  for (const Contact& c : contacts) {
    if (c.at_vertex && c.vertex == origin) continue;
    const CGAL::Interval_nt<> at = position<CGAL::Interval_nt<>>(ray, p_[c.vertex], p_[p_.next(c.vertex)], c.at_vertex);
    if (at.sup() <= 0 || (at.inf() <= 0 && exact(c) <= 0)) continue;
    const bool nearer = !best_contact || at.sup() < best_at.inf() ||
                        (at.inf() <= best_at.sup() && exact(c) < exact(*best_contact));
    if (nearer) best_contact = c, best_at = at;
  }
  if (!best_contact) return std::nullopt;
  return Hit{best_contact->vertex, best_contact->at_vertex};
}

bool RayShooter::box_missed(const Ray& ray, std::size_t arc) const {
  const Box& b = box_[arc];
  const Point corners[4] = {Point(b.x0, b.y0), Point(b.x1, b.y0), Point(b.x1, b.y1), Point(b.x0, b.y1)};
  int left = 0, right = 0, behind = 0;
  for (const Point& c : corners) {
    const int side = ray.side(c);
    left += side > 0, right += side < 0;
    behind += ray.ahead(c) < 0;
  }
  return left == 4 || right == 4 || behind == 4;
}

// The signed distance from the ray's line along an arc rises then falls, or falls then rises, or is
// monotone: the edges' turn against the ray changes sign at most once (the arc turns by less than 180
// degrees). Bisection finds the change; each monotone part then meets the line at most once.
void RayShooter::contacts_on_arc(const Ray& ray, std::size_t arc, std::vector<Contact>& out) {
  const std::size_t s = arc_start_[arc], edges = arc_edges_[arc];
  const int first_turn = ray.edge_turn(at(s), at(s + 1)), last_turn = ray.edge_turn(at(s + edges - 1), at(s + edges));
  probes_ += 2;
  if (first_turn * last_turn >= 0) return contacts_on_monotone_part(ray, s, s + edges, out);
  std::size_t lo = 1, hi = edges - 1;  // the first edge whose turn is not first_turn's lies in [lo, hi]
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    ++probes_;
    if (ray.edge_turn(at(s + mid), at(s + mid + 1)) * first_turn > 0) lo = mid + 1;
    else hi = mid;
  }
  contacts_on_monotone_part(ray, s, s + lo, out);
  contacts_on_monotone_part(ray, s + lo, s + edges, out);
}

// Vertices first..last (indices mod n) with the side of the line monotone along them.
void RayShooter::contacts_on_monotone_part(const Ray& ray, std::size_t first, std::size_t last, std::vector<Contact>& out) {
  const std::size_t n = p_.size();
  const int side_first = ray.side(at(first)), side_last = ray.side(at(last));
  probes_ += 2;
  if (side_first == side_last && side_first != 0) return;
  if (side_first == 0 && side_last == 0) {
    out.push_back({first % n, true});
    out.push_back({last % n, true});
    return;
  }
  const int rising = side_first < side_last ? 1 : -1;
  // The first vertex at or beyond the line, then the first strictly beyond it.
  auto first_reaching = [&](int level) {
    std::size_t lo = first, hi = last + 1;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      ++probes_;
      if (rising * ray.side(at(mid)) >= level) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  };
  const std::size_t on = first_reaching(0);
  if (ray.side(at(on)) != 0) return out.push_back({(on - 1) % n, false});
  const std::size_t past = first_reaching(1);
  out.push_back({on % n, true});
  out.push_back({(past - 1) % n, true});
}

}  // namespace pd
