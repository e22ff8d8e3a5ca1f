// hertel-mehlhorn: Hertel and Mehlhorn's approximate convex decomposition (S. Hertel, K. Mehlhorn, Fast
// triangulation of the plane with respect to simple polygons, 1985; as stated in Keil-Snoeyink (001),
// Sec. 2, "start with any triangulation of P, consider each diagonal in turn, and remove a diagonal
// unless doing so forms a reflex angle at one of its endpoints", and in the Rosen slides (003),
// "Hertel-Mehlhorn's algorithm ... O(n) time with the use of appropriate data structures").
//
// Time O(n) after the triangulation, O(n log n) with it (the `monotone` triangulation,
// triangulate_monotone in monotone.h); space O(n). Pre: a polygon, with h >= 0 holes (then each
// vertex's diagonals are sorted by angle: O(n log n) after the triangulation); collinear vertices
// allowed. Output: diagonals only, no Steiner points; every diagonal left is essential, so at most
// 2r + 1 - h pieces, at most 4 OPT without holes. The O(n) removal, with its half-edge lists built by
// counting sorts, is in engines/convex/essential_diagonals.h.
#include "core/registry.h"
#include "engines/convex/essential_diagonals.h"
#include "engines/triangulation/monotone.h"

namespace pd {
namespace {

Decomposition hertel_mehlhorn(const Polygon& p, Counters& counters) {
  Counters triangulation_counters;
  const std::vector<Cut> diagonals = triangulate_monotone(p, triangulation_counters).cuts;
  std::int64_t tests = 0;
  Decomposition d;
  d.cuts = essential::keep_essential(p, diagonals, tests);
  for (const auto& [name, value] : triangulation_counters) counters["triangulation_" + name] = value;
  counters["diagonals"] = static_cast<std::int64_t>(diagonals.size());
  counters["diagonals_removed"] = static_cast<std::int64_t>(diagonals.size() - d.cuts.size());
  counters["essential_tests"] = tests;
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "hertel-mehlhorn", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT",
                    .source = "Hertel-Mehlhorn via Keil-Snoeyink (001) Sec. 2 and slides (003); O(n) after the monotone triangulation",
                    .accepts = {.holes = true}, .run = hertel_mehlhorn});

}  // namespace pd
