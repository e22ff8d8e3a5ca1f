// Ray shooting from polygon vertices, for keil-snoeyink-reduced, Chazelle-Dobkin's loose rays
// (engines/chazelle_dobkin/tables.h) and the vertical chords that its geodesics walk (geodesics.h).
//
// Keil & Snoeyink (001, Sec. 4) shoot O(r^2) rays in O(log n) each after linear preprocessing
// (geodesic triangulations, Chazelle et al.; or Hershberger-Suri). This is a simpler structure with a
// weaker but still near-linear bound: the boundary is cut, in O(n), into convex arcs, each a run of
// edges between reflex vertices whose direction turns left by less than 180 degrees in all. The turns
// at convex vertices add up to less than (r + 2) 180 degrees, so there are O(r) arcs. A line meets
// such an arc at most twice, and the signed distance from the line is unimodal along it, so the
// contacts are found by bisection: O(log n) per arc, O(r log n) per ray (arcs whose bounding box the
// ray misses are skipped in O(1)). With the paper's O(r^2) rays the shooting costs O(r^3 log n) in
// place of O(r^2 log n): near-linear in n at fixed r.
//
// Exact: sides of the line are `orient` on input points, directions of edges against the ray are
// exact signs of cross products (interval filter, then rationals), and the nearest contact is chosen
// by comparing exact rational positions along the ray. No point is rounded.
#pragma once

#include "core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pd {

class RayShooter {
 public:
  explicit RayShooter(const Polygon& p);  // O(n)

  // The first point of p's boundary that the ray from p[origin] meets beyond p[origin]: vertex
  // `vertex` itself (at_vertex), or a point inside the edge (vertex, vertex + 1).
  struct Hit {
    std::size_t vertex;
    bool at_vertex;
  };

  // The ray from p[origin] towards p[through] (toward = true) or away from it (toward = false).
  // Pre: origin != through. Returns nothing when the ray meets no boundary point beyond the origin
  // (it cannot when it starts into p's interior).
  std::optional<Hit> shoot(std::size_t origin, std::size_t through, bool toward);
  // The ray from p[origin] in direction b - a (a != b); the same answer. Pre: the ray starts into p's
  // interior, or the answer may be nothing.
  std::optional<Hit> shoot_along(std::size_t origin, const Point& a, const Point& b);

  std::size_t arcs() const { return arc_start_.size(); }
  std::int64_t probes() const { return probes_; }

  struct Ray;  // a ray and its exact tests, in ray_shooting.cpp

 private:
  struct Contact;
  std::optional<Hit> first_hit(const Ray& ray, std::size_t origin);
  struct Box {
    double x0, x1, y0, y1;
  };
  void cut_into_arcs();
  bool box_missed(const Ray& ray, std::size_t arc) const;
  void contacts_on_arc(const Ray& ray, std::size_t arc, std::vector<Contact>& out);
  void contacts_on_monotone_part(const Ray& ray, std::size_t first, std::size_t last, std::vector<Contact>& out);
  const Point& at(std::size_t k) const { return p_[k % p_.size()]; }

  const Polygon& p_;
  // Arc k runs from vertex arc_start_[k] along arc_edges_[k] edges (indices taken mod n).
  std::vector<std::size_t> arc_start_, arc_edges_;
  std::vector<Box> box_;  // each arc's bounding box
  std::int64_t probes_ = 0;
};

// Where a ray from z in direction u (exact) meets the boundary at `hit`: the t with z + t u the point
// met, exactly.
Rational hit_parameter(const Polygon& p, const QPoint& z, const ExactKernel::Vector_2& u, const RayShooter::Hit& hit);

// sign((b - a) x (d - c)), exactly.
int cross_sign(const Point& a, const Point& b, const Point& c, const Point& d);
// sign((b - a) . (d - c)), exactly.
int dot_sign(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace pd
