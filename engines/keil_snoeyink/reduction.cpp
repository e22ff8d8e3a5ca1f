// The reduction of Keil & Snoeyink's Theorem 5 and the program that chooses between the reduced polygon
// and the input: the method of `keil-snoeyink-reduced` (its paper, bounds and deviations:
// algorithms/keil_snoeyink_reduced.cpp).
#include "engines/keil_snoeyink/reduction.h"

#include "engines/keil_snoeyink/stacks.h"
#include "engines/search/ray_shooting.h"

#include <optional>
#include <vector>

namespace pd {
namespace {

class Reduction {
 public:
  explicit Reduction(const Polygon& p) : p_(p), n_(p.size()), shooter_(p), keep_(p.size(), 0) {}

  // The kept vertices in order: every reflex vertex, every RE- and DE-diagonal endpoint, and their
  // neighbours.
  std::vector<std::size_t> kept_vertices() {
    std::vector<std::size_t> reflex;
    for (std::size_t v = 0; v < n_; ++v)
      if (p_.is_reflex(v)) reflex.push_back(v), keep_[v] = 1;
    for (std::size_t r : reflex) keep_re_endpoints(r);
    for (std::size_t a = 0; a < reflex.size(); ++a)
      for (std::size_t b = a + 1; b < reflex.size(); ++b) keep_de_endpoints_of_rr(reflex[a], reflex[b]);
    std::vector<char> with_neighbours(keep_);
    for (std::size_t v = 0; v < n_; ++v)
      if (keep_[v]) with_neighbours[p_.prev(v)] = with_neighbours[p_.next(v)] = 1;
    std::vector<std::size_t> kept;
    for (std::size_t v = 0; v < n_; ++v)
      if (with_neighbours[v]) kept.push_back(v);
    return kept;
  }

  // Whether shooting can beat Algorithm 1 on the whole polygon (see the deviations above): the
  // reduced polygon may be smaller (r^2 + 2r < n) and the rays cost less than n r^2.
  bool worth_shooting(std::size_t r) const {
    std::size_t log_n = 1;
    while ((std::size_t{1} << log_n) < n_) ++log_n;
    return r * r + 2 * r < n_ && shooter_.arcs() * log_n < n_;
  }

  std::int64_t rays() const { return rays_; }
  std::int64_t arcs() const { return static_cast<std::int64_t>(shooter_.arcs()); }
  std::int64_t probes() const { return shooter_.probes(); }

 private:
  std::optional<RayShooter::Hit> shoot(std::size_t origin, std::size_t through, bool toward) {
    ++rays_;
    return shooter_.shoot(origin, through, toward);
  }

  // The first vertex the ray meets, or the first vertex of the edge it meets: the endpoint of the
  // RE- or DE-diagonal along it.
  void keep_hit(const std::optional<RayShooter::Hit>& hit) {
    if (hit) keep_[hit->vertex] = 1;
  }

  // Whether the direction from reflex r away from u (u != r) points strictly into p: not in the
  // closed exterior wedge at r.
  bool away_enters(std::size_t r, std::size_t u) const {
    return orient(p_[r], p_[p_.next(r)], p_[u]) < 0 || orient(p_[p_.prev(r)], p_[r], p_[u]) < 0;
  }
  // Whether the segment ru (u != r) leaves r strictly into p.
  bool toward_enters(std::size_t r, std::size_t u) const {
    return orient(p_[r], p_[p_.next(r)], p_[u]) > 0 || orient(p_[p_.prev(r)], p_[r], p_[u]) > 0;
  }
  // Whether ru is a diagonal: it leaves r into p and the first boundary point on it is u.
  bool is_diagonal(std::size_t r, std::size_t u) {
    if (u == p_.next(r) || u == p_.prev(r) || !toward_enters(r, u)) return false;
    const auto hit = shoot(r, u, true);
    return hit && hit->at_vertex && hit->vertex == u;
  }

  // The RE-diagonal at r runs from r to the vertex the extension of edge (r, r+1) through r meets,
  // or to the first vertex of the edge it meets; a DE-diagonal extends it through r.
  void keep_re_endpoints(std::size_t r) {
    const auto hit = shoot(r, p_.next(r), false);
    keep_hit(hit);
    if (!hit || hit->at_vertex) return;  // along the extension itself: its own extension is the edge
    const std::size_t p = hit->vertex;
    if (is_diagonal(r, p) && away_enters(r, p)) keep_hit(shoot(r, p, false));
  }

  void keep_de_endpoints_of_rr(std::size_t r, std::size_t s) {
    if (!is_diagonal(r, s)) return;
    if (away_enters(r, s)) keep_hit(shoot(r, s, false));
    if (away_enters(s, r)) keep_hit(shoot(s, r, false));
  }

  const Polygon& p_;
  std::size_t n_;
  RayShooter shooter_;
  std::vector<char> keep_;
  std::int64_t rays_ = 0;
};

Decomposition solve_reduced(const Polygon& p, Reduction& reduction, Counters& counters) {
  const std::vector<std::size_t> kept = reduction.kept_vertices();
  std::vector<Point> ring;
  ring.reserve(kept.size());
  for (std::size_t v : kept) ring.push_back(p[v]);
  const Polygon reduced = Polygon::make(std::move(ring));
  Decomposition on_reduced = keil_snoeyink(reduced, counters);
  Decomposition d;
  for (const Cut& c : on_reduced.cuts) d.add_cut(kept[reduced.input_index(c.a)], kept[reduced.input_index(c.b)]);
  counters["rays_shot"] = reduction.rays();
  counters["arcs"] = reduction.arcs();
  counters["ray_probes"] = reduction.probes();
  counters["reduced_n"] = static_cast<std::int64_t>(kept.size());
  return d;
}

}  // namespace

Decomposition keil_snoeyink_reduced(const Polygon& p, Counters& counters) {
  if (p.reflex_count() == 0) return {};
  Reduction reduction(p);
  if (reduction.worth_shooting(p.reflex_count())) return solve_reduced(p, reduction, counters);
  Decomposition d = keil_snoeyink(p, counters);
  counters["rays_shot"] = 0;
  counters["arcs"] = reduction.arcs();
  counters["reduced_n"] = static_cast<std::int64_t>(p.size());
  return d;
}

Decomposition solve_on_reduced_polygon(const Polygon& p, Counters& counters) {
  Reduction reduction(p);
  return solve_reduced(p, reduction, counters);
}

}  // namespace pd
