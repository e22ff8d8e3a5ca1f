#include "core/registry.h"

namespace pd {

std::optional<std::string> refusal(const Algorithm& a, const Polygon& p) {
  if (!a.accepts.holes && p.hole_count() > 0) {
    const std::size_t h = p.hole_count();
    return a.name + " does not take polygons with holes; this one has " + std::to_string(h) + (h == 1 ? " hole" : " holes");
  }
  if (a.accepts.convex_only && p.reflex_count() > 0) {
    const std::size_t r = p.reflex_count();
    return a.name + " takes only convex polygons; this one has " + std::to_string(r) +
           (r == 1 ? " reflex vertex" : " reflex vertices");
  }
  if (a.accepts.max_vertices != 0 && p.size() > a.accepts.max_vertices) {
    return a.name + " takes at most " + std::to_string(a.accepts.max_vertices) + " vertices; this polygon has " +
           std::to_string(p.size());
  }
  return std::nullopt;
}

}  // namespace pd
