#include "core/registry.h"

#include <algorithm>

namespace pd {
namespace {

std::vector<Algorithm>& registry() {
  static std::vector<Algorithm> all;
  return all;
}

}  // namespace

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Triangulation: return "triangulation";
    case Kind::Partition: return "partition";
    case Kind::Convex: return "convex";
    case Kind::Cut: return "cut";
  }
  return "?";
}

const std::vector<Algorithm>& algorithms() { return registry(); }

const Algorithm* find_algorithm(const std::string& name) {
  for (const Algorithm& a : registry())
    if (a.name == name) return &a;
  return nullptr;
}

bool register_algorithm(Algorithm a) {
  auto& all = registry();
  auto at = std::lower_bound(all.begin(), all.end(), a.name,
                             [](const Algorithm& x, const std::string& name) { return x.name < name; });
  all.insert(at, std::move(a));
  return true;
}

}  // namespace pd
