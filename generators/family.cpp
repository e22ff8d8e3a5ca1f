// The family registry and the checked entry point `generate`.
#include "generators/family.h"

#include <algorithm>
#include <cmath>

namespace pd {

namespace {

// Function-local so that registrations from other translation units' static initialisers find it
// constructed.
std::vector<Family>& registry() {
  static std::vector<Family> all;
  return all;
}

std::vector<Family>::iterator position_of(const std::string& name) {
  auto& all = registry();
  return std::lower_bound(all.begin(), all.end(), name,
                          [](const Family& f, const std::string& key) { return f.name < key; });
}

std::string family_names() {
  std::string names;
  for (const Family& f : registry()) names += (names.empty() ? "" : ", ") + f.name;
  return names;
}

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

const std::vector<Family>& families() { return registry(); }

const Family* find_family(const std::string& name) {
  const auto it = position_of(name);
  return it != registry().end() && it->name == name ? &*it : nullptr;
}

bool register_family(Family f) {
  const auto it = position_of(f.name);
  if (it != registry().end() && it->name == f.name) return false;
  registry().insert(it, std::move(f));
  return true;
}

std::vector<Point> generate(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                            std::uint64_t seed) {
  const Family* f = find_family(family);
  if (f == nullptr) throw std::invalid_argument("unknown family " + family + "; families: " + family_names());
  const std::size_t reflex = r ? *r : f->default_reflex(n);
  if (f->infeasible(n, reflex)) {
    throw GeneratorError("family " + f->name + " cannot make n=" + std::to_string(n) +
                         ", r=" + std::to_string(reflex) + ": feasible " + f->range);
  }
  std::vector<Point> polygon = f->make(n, reflex, seed);
  check_output(*f, n, polygon);
  return polygon;
}

}  // namespace pd
