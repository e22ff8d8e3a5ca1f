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
//
// The diagonals are considered in the order the triangulation gives them (for `monotone`: monotone
// piece by piece, in the order of the partition's sweep). The paper leaves the triangulation open, and
// the pieces depend on it: `hertel-mehlhorn[T]` is the same removal over registered triangulation T
// (every one without Steiner points, the peers' included), in T's order of its cuts or of its
// triangles' edges; it takes what T takes, and its time is T's plus O(n) (plus O(n log n) with holes,
// so a T claiming less, `seidel`, gets n log n). Over `monotone` it is `hertel-mehlhorn` itself, not
// registered twice. Over a peer's triangulation it is marked as that peer's, whose result it reports
// as returned: the tests check it strictly over cgal-cdt (tests/test_convex_approx.cpp).
#include "core/registry.h"
#include "engines/convex/essential_diagonals.h"
#include "engines/triangulation/monotone.h"

#include <chrono>

namespace pd {
namespace {

Decomposition hertel_mehlhorn(const Polygon& p, Counters& counters) {
  Counters triangulation;
  const std::vector<Cut> diagonals = triangulate_monotone(p, triangulation).cuts;
  return essential::removal_result(p, diagonals, triangulation, counters);
}

// The variant over `base`: when the base times itself (a plug-in), the variant's time is the base's
// own time plus the removal's.
Decomposition over_triangulation(const Algorithm& base, const Polygon& p, Counters& counters) {
  Counters triangulation;
  const Decomposition t = base.run(p, triangulation);
  const auto start = std::chrono::steady_clock::now();
  Decomposition d = essential::removal_result(p, essential::triangulation_diagonals(p, t), triangulation, counters);
  if (t.own_seconds)
    d.own_seconds = *t.own_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

// The removal sorts each vertex's diagonals by angle when the polygon has holes: O(n log n) after any
// triangulation that claims less.
bool below_n_log_n(const std::string& time_bound) { return time_bound == "n" || time_bound == "n*log*(n)"; }

Algorithm variant(const Algorithm& base) {
  Algorithm a = *find_algorithm("hertel-mehlhorn");
  a.time_bound = base.accepts.holes && below_n_log_n(base.time_bound) ? "n*log(n)" : base.time_bound;
  a.source = "Hertel-Mehlhorn as in hertel-mehlhorn, over the " + base.name + " triangulation";
  a.peer = base.peer;
  a.accepts = base.accepts;
  a.size_ceiling = base.size_ceiling;
  a.times_itself = base.times_itself;
  a.run = [base](const Polygon& p, Counters& counters) { return over_triangulation(base, p, counters); };
  return a;
}

}  // namespace

REGISTER_ALGORITHM({.name = "hertel-mehlhorn", .kind = Kind::Convex, .time_bound = "n*log(n)",
                    .pieces_bound = "<= 4*OPT",
                    .source = "Hertel-Mehlhorn via Keil-Snoeyink (001) Sec. 2 and slides (003); O(n) after the monotone triangulation",
                    .accepts = {.holes = true}, .run = hertel_mehlhorn});

REGISTER_VARIANTS({.name = "hertel-mehlhorn",
                   .takes = [](const Algorithm& base) {
                     return base.kind == Kind::Triangulation && !base.steiner && base.name != "monotone";
                   },
                   .make = variant});

}  // namespace pd
