#include "core/registry.h"

#include "core/json.h"

#include <vector>

namespace pd {
namespace {

std::vector<VariantFamily>& variant_families() {
  static std::vector<VariantFamily> registered;
  return registered;
}

void add_variant(const VariantFamily& family, const Algorithm& base) {
  if (!base.variant_of.empty() || !family.takes(base)) return;
  Algorithm variant = family.make(base);
  variant.name = variant_name(family.name, base.name);
  variant.variant_of = base.name;
  NamedRegistry<Algorithm>::add(std::move(variant));
}

}  // namespace

bool register_algorithm(Algorithm a) {
  NamedRegistry<Algorithm>::add(a);
  for (const VariantFamily& family : variant_families()) add_variant(family, a);
  return true;
}

std::optional<std::string> taken_name(const Algorithm& a) {
  if (find_algorithm(a.name)) return a.name;
  for (const VariantFamily& family : variant_families()) {
    const std::string name = variant_name(family.name, a.name);
    if (a.variant_of.empty() && family.takes(a) && find_algorithm(name)) return name;
  }
  return std::nullopt;
}

bool register_variant_family(VariantFamily family) {
  const std::vector<Algorithm> bases = algorithms();  // a copy: adding the variants moves the entries
  for (const Algorithm& base : bases) add_variant(family, base);
  variant_families().push_back(std::move(family));
  return true;
}

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
           "}, \"size_ceiling\": " + std::to_string(a.size_ceiling) +
           ", \"variant_of\": " + (a.variant_of.empty() ? "null" : json_quote(a.variant_of)) + "}";
  }
  return out + "]\n";
}

}  // namespace pd
