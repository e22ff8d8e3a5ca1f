// The family registry and the checked entry point `generate`.
#include "generators/family.h"

#include <algorithm>
#include <cmath>

namespace pd {

namespace {

// A family's output must be what family.h promises; a violation is a bug in the family.
void check_output(const std::string& family, std::size_t n, const Rings& rings) {
  std::size_t vertices = 0;
  for (const Ring& ring : rings) vertices += ring.size();
  if (vertices != n) {
    throw std::logic_error("family " + family + " made " + std::to_string(vertices) + " vertices instead of " +
                           std::to_string(n));
  }
  constexpr double kBound = 2147483648.0;  // 2^31
  for (const Ring& ring : rings)
    for (const Point& p : ring)
      if (!(std::abs(p.x()) < kBound && std::abs(p.y()) < kBound))
        throw std::logic_error("family " + family + " made a coordinate beyond 2^31 at n=" + std::to_string(n));
}

std::string all_family_names() {
  std::string names = NamedRegistry<Family>::names(), holed = NamedRegistry<HoleFamily>::names();
  return holed.empty() ? names : names + ", " + holed;
}

}  // namespace

Family outcome_family(std::string name, std::string shape, std::size_t min_n, std::size_t max_n,
                      std::function<std::vector<Point>(std::size_t n, std::uint64_t seed)> make) {
  return {.name = std::move(name),
          .shape = std::move(shape),
          .min_n = min_n,
          .max_n = max_n,
          .r_range = "r an outcome of the method",
          .controls_r = false,
          .r_is_outcome = true,
          .r_infeasible = [](std::size_t, std::size_t) -> std::optional<std::string> {
            return "r is an outcome of the method, never chosen";
          },
          .default_reflex = [](std::size_t) { return std::size_t{0}; },
          .make = [make = std::move(make)](std::size_t n, std::size_t, std::uint64_t seed) { return make(n, seed); }};
}

std::string Family::range() const {
  return std::to_string(min_n) + " <= n <= " + std::to_string(max_n) + ", " + r_range;
}

namespace {

std::optional<std::string> n_outside(std::size_t n, std::size_t min_n, std::size_t max_n) {
  if (n < min_n) return "n must be at least " + std::to_string(min_n);
  if (n > max_n) return "n must be at most " + std::to_string(max_n);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> Family::n_infeasible(std::size_t n) const { return n_outside(n, min_n, max_n); }

std::optional<std::string> Family::infeasible(std::size_t n, std::size_t r) const {
  if (const auto why = n_infeasible(n)) return why;
  return r_infeasible(n, r);
}

const std::vector<Family>& families() { return NamedRegistry<Family>::all(); }

const Family* find_family(const std::string& name) { return NamedRegistry<Family>::find(name); }

bool register_family(Family f) {
  if (find_hole_family(f.name)) throw std::logic_error("registered twice: " + f.name);
  return NamedRegistry<Family>::add(std::move(f));
}

std::size_t reflex_vertices(const std::vector<Point>& ring) {
  std::size_t reflex = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    reflex += orient(ring[i == 0 ? ring.size() - 1 : i - 1], ring[i], ring[(i + 1) % ring.size()]) < 0;
  return reflex;
}

namespace {

const Family& family_named(const std::string& family) {
  const Family* f = find_family(family);
  if (f == nullptr) {
    if (find_hole_family(family))
      throw std::invalid_argument("family " + family + " makes polygons with holes");
    throw std::invalid_argument("unknown family " + family + "; families: " + all_family_names());
  }
  return *f;
}

// A family whose r is an outcome: n in range, and r, when asked for, the one the method gives.
std::vector<Point> generate_outcome(const Family& f, std::size_t n, std::optional<std::size_t> r, std::uint64_t seed) {
  if (f.n_infeasible(n))
    throw GeneratorError("family " + f.name + " cannot make n=" + std::to_string(n) + ": feasible " + f.range());
  std::vector<Point> polygon = f.make(n, 0, seed);
  check_output(f.name, n, {polygon});
  if (r && *r != reflex_vertices(polygon))
    throw GeneratorError("family " + f.name + " does not choose r: at n=" + std::to_string(n) + " and seed " +
                         std::to_string(seed) + " its method gives r=" + std::to_string(reflex_vertices(polygon)) +
                         ", not " + std::to_string(*r) + " (feasible " + f.range() + ")");
  return polygon;
}

}  // namespace

std::size_t reflex_outcome(const std::string& family, std::size_t n, std::uint64_t seed) {
  return reflex_vertices(generate(family, n, std::nullopt, seed));
}

std::vector<Point> generate(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                            std::uint64_t seed) {
  const Family* f = &family_named(family);
  if (f->r_is_outcome) return generate_outcome(*f, n, r, seed);
  const std::size_t reflex = r ? *r : f->default_reflex(n);
  if (f->infeasible(n, reflex)) {
    throw GeneratorError("family " + f->name + " cannot make n=" + std::to_string(n) +
                         ", r=" + std::to_string(reflex) + ": feasible " + f->range());
  }
  std::vector<Point> polygon = f->make(n, reflex, seed);
  check_output(f->name, n, {polygon});
  return polygon;
}

std::string HoleFamily::range() const {
  return std::to_string(min_n) + " <= n <= " + std::to_string(max_n) + ", " + rh_range;
}

std::optional<std::string> HoleFamily::infeasible(std::size_t n, std::size_t r, std::size_t h) const {
  if (const auto why = n_outside(n, min_n, max_n)) return why;
  return rh_infeasible(n, r, h);
}

const std::vector<HoleFamily>& hole_families() { return NamedRegistry<HoleFamily>::all(); }

const HoleFamily* find_hole_family(const std::string& name) { return NamedRegistry<HoleFamily>::find(name); }

bool register_hole_family(HoleFamily f) {
  if (find_family(f.name)) throw std::logic_error("registered twice: " + f.name);
  return NamedRegistry<HoleFamily>::add(std::move(f));
}

Rings generate_with_holes(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                          std::optional<std::size_t> h, std::uint64_t seed) {
  const HoleFamily* f = find_hole_family(family);
  if (f == nullptr) {
    if (h.value_or(0) == 0 && find_family(family)) return {generate(family, n, r, seed)};
    if (find_family(family)) throw GeneratorError("family " + family + " makes polygons without holes (h = 0)");
    throw std::invalid_argument("unknown family " + family + "; families: " + all_family_names());
  }
  const std::size_t holes = h.value_or(f->default_holes);
  const std::size_t reflex = r ? *r : f->default_reflex(n, holes);
  if (f->infeasible(n, reflex, holes)) {
    throw GeneratorError("family " + f->name + " cannot make n=" + std::to_string(n) + ", r=" + std::to_string(reflex) +
                         ", h=" + std::to_string(holes) + ": feasible " + f->range());
  }
  Rings rings = f->make(n, reflex, holes, seed);
  check_output(f->name, n, rings);
  return rings;
}

Rings generate_polygon(const GenerateRequest& request) {
  const Family* f = find_family(request.family);
  if (request.reflex && f && f->r_is_outcome)
    throw GeneratorError("family " + request.family + " does not choose r: it is an outcome of the method (leave out " +
                         "--reflex; polydecomp check counts it)");
  if (request.collinear && request.holes)
    throw GeneratorError("--collinear and --holes do not go together: collinear vertices are made for families without holes");
  if (request.collinear)
    return {generate_with_collinear(request.family, request.n, request.reflex, *request.collinear, request.seed)};
  return generate_with_holes(request.family, request.n, request.reflex, request.holes, request.seed);
}

}  // namespace pd
