// greene-sweep: Greene's approximate convex decomposition from a y-monotone partition, as the Rosen
// slides (003) list it: "Approximate convex partition using sweep-line - Greene (1983): O(n lg n),
// starts with y-monotone partition". The slides give only that outline, and Greene's own rules for a
// monotone piece are not among our sources.
//
// Time O(n log n) (the partition's sweep; the rest is O(n), or O(n log n) with holes), space O(n). Pre:
// a polygon, with h >= 0 holes (the partition takes them, monotone.h); collinear vertices allowed.
// Output: diagonals only, no Steiner points, at most 2r + 1 - h pieces, at most 4 OPT without holes
// (the bound Greene's approximation is known for).
//
// Reconstruction: (1) the y-monotone partition by plane sweep (y_monotone_diagonals, monotone.h);
// (2) each monotone piece swept top to bottom by the linear stack procedure of the slides (Garey,
// Johnson, Preparata, Tarjan), whose stack is the piece's chain of inward cusps; (3) the diagonals of
// each piece, then those of the partition, removed unless essential (Hertel-Mehlhorn's test,
// engines/convex/essential_diagonals.h), which merges each piece's triangles into convex pieces and then convex
// pieces across the partition. Every diagonal left is essential, which gives the bound. Step (2)-(3)
// stands in for Greene's per-piece rules; the result differs from `hertel-mehlhorn` only in the order
// in which diagonals are considered (pieces first, partition last).
#include "core/registry.h"
#include "engines/convex/essential_diagonals.h"
#include "engines/triangulation/monotone.h"

namespace pd {
namespace {

Decomposition greene_sweep(const Polygon& p, Counters& counters) {
  Counters sweep_counters;
  const std::vector<Cut> partition = y_monotone_diagonals(p, sweep_counters);
  const std::vector<Cut> triangulated = triangulate_monotone_pieces(p, partition, sweep_counters).cuts;
  // triangulate_monotone_pieces returns the partition's diagonals first, then the pieces' own.
  std::vector<Cut> order(triangulated.begin() + static_cast<std::ptrdiff_t>(partition.size()), triangulated.end());
  order.insert(order.end(), partition.begin(), partition.end());
  std::int64_t tests = 0;
  Decomposition d;
  d.cuts = essential::keep_essential(p, order, tests);
  for (const auto& [name, value] : sweep_counters) counters["sweep_" + name] = value;
  counters["partition_diagonals"] = static_cast<std::int64_t>(partition.size());
  counters["diagonals"] = static_cast<std::int64_t>(order.size());
  counters["diagonals_removed"] = static_cast<std::int64_t>(order.size() - d.cuts.size());
  counters["essential_tests"] = tests;
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "greene-sweep", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT",
                    .source = "Greene 1983 as outlined in Rosen slides (003): y-monotone partition, then each piece; per-piece step reconstructed",
                    .accepts = {.holes = true}, .run = greene_sweep});

}  // namespace pd
