#include "core/registry.h"

#include "core/json.h"

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

std::string algorithms_json() {
  std::string out = "[";
  for (const Algorithm& a : algorithms()) {
    const std::string max_vertices = a.accepts.max_vertices ? std::to_string(a.accepts.max_vertices) : "null";
    out += std::string(out.size() > 1 ? ",\n " : "") + "{\"name\": " + json_quote(a.name) +
           ", \"kind\": " + json_quote(kind_name(a.kind)) + ", \"steiner\": " + json_bool(a.steiner) +
           ", \"optimal\": " + json_bool(a.optimal) + ", \"time_bound\": " + json_quote(a.time_bound) +
           ", \"pieces_bound\": " + json_quote(a.pieces_bound) + ", \"source\": " + json_quote(a.source) +
           ", \"peer\": " + (is_peer(a) ? json_quote(a.peer) : "null") + ", \"holes\": " + json_bool(a.accepts.holes) +
           ", \"accepts\": {\"holes\": " + json_bool(a.accepts.holes) +
           ", \"convex_only\": " + json_bool(a.accepts.convex_only) + ", \"max_vertices\": " + max_vertices +
           "}, \"size_ceiling\": " + std::to_string(a.size_ceiling) + "}";
  }
  return out + "]\n";
}

}  // namespace pd
