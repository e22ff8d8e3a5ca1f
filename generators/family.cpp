// The family registry and the checked entry point `generate`.
#include "generators/family.h"

#include <algorithm>
#include <cmath>

namespace pd {

namespace {

// A family's output must be what family.h promises; a violation is a bug in the family.
void check_output(const Family& f, std::size_t n, const std::vector<Point>& polygon) {
  if (polygon.size() != n) {
    throw std::logic_error("family " + f.name + " made " + std::to_string(polygon.size()) +
                           " vertices instead of " + std::to_string(n));
  }
  constexpr double kBound = 2147483648.0;  // 2^31
  for (const Point& p : polygon) {
    if (!(std::abs(p.x()) < kBound && std::abs(p.y()) < kBound)) {
      throw std::logic_error("family " + f.name + " made a coordinate beyond 2^31 at n=" + std::to_string(n));
    }
  }
}

}  // namespace

std::string Family::range() const {
  return std::to_string(min_n) + " <= n <= " + std::to_string(max_n) + ", " + r_range;
}

std::optional<std::string> Family::infeasible(std::size_t n, std::size_t r) const {
  if (n < min_n) return "n must be at least " + std::to_string(min_n);
  if (n > max_n) return "n must be at most " + std::to_string(max_n);
  return r_infeasible(n, r);
}

const std::vector<Family>& families() { return NamedRegistry<Family>::all(); }

const Family* find_family(const std::string& name) { return NamedRegistry<Family>::find(name); }

bool register_family(Family f) { return NamedRegistry<Family>::add(std::move(f)); }

std::vector<Point> generate(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                            std::uint64_t seed) {
  const Family* f = find_family(family);
  if (f == nullptr) throw std::invalid_argument("unknown family " + family + "; families: " + NamedRegistry<Family>::names());
  const std::size_t reflex = r ? *r : f->default_reflex(n);
  if (f->infeasible(n, reflex)) {
    throw GeneratorError("family " + f->name + " cannot make n=" + std::to_string(n) +
                         ", r=" + std::to_string(reflex) + ": feasible " + f->range());
  }
  std::vector<Point> polygon = f->make(n, reflex, seed);
  check_output(*f, n, polygon);
  return polygon;
}

}  // namespace pd
