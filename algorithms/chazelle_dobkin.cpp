// chazelle-dobkin: optimal convex decomposition with Steiner points, Algorithm CD with Section 2.4's
// organisation of STEP 3's X4 term (B. Chazelle, Computational Geometry and Convexity, thesis, Yale
// 1980 (000), Sec. 2.4, "An OCD Algorithm Cubic in the Number of Notches": Definition 2.4, Theorem 18,
// Lemma 9, the sorted lists of points A_ik on the segments r_i, the sets E(i, j) and the selection and
// two-way scans of Sec. 2.4.2). The dynamic program (STEPs 1-5), its orientation and its
// reconstructions are in engines/chazelle_dobkin/program.h; pattern detection for the Y-patterns in
// engines/chazelle_dobkin/patterns.h. The loose rays, the table entry and the program that fills and
// reads the rows are in engines/chazelle_dobkin/tables.h, where the tests read the rows too.
//
// Section 2.4's text stops in the middle of its scans (Theorem 18's proof is the lost Figure 2.31); what
// is reconstructed here (tight X4-patterns only, the two pairings E and W in one row per interval, the
// selections and two-way scans, the funnels that test P4), with proofs, the deviations from the thesis
// and the counters are in docs/algorithms/chazelle-dobkin.md. Rays are clipped by ray shooting on convex
// arcs (engines/search/ray_shooting.h); P is never triangulated.
//
// Time: the views O(n + r^2 log n) (engines/chazelle_dobkin/patterns.h), the loose rays O(r^2 log n), the
// scans' vertical chords O(n + r^2 log n) once a scan needs a tree, O(r^2 log r) for the lists,
// O(r log r) for each of at most 3r geodesic trees; STEPs 2 and 4 O(r^3) (engines/chazelle_dobkin/program.h: O(1) per
// test); STEP 3's X4 term O(r^3) lookups and the scans O(r) each (the docs' (6) and (7); a PlaceSet operation is
// O(1) for r < 32768), O(r^3) over the O(r^2) intervals; the checks of the O(r) patterns laid out
// O(r^2 log(n/r)); STEP 5 O(n + r^2 log(n/r)) (engines/chazelle_dobkin/program.h). Worst case O(n + r^3), the
// thesis's: r^2 log n is at most n when r^2 log n <= n, and O(r^3) otherwise, since then
// log n = O(log r). Space O(n + r^2) for the chords and the trees,
// O(r^3) for the rows (a row per interval with a witness) and O(r^2) rationals for the lists and loose
// points. Pre: a simple counter-clockwise polygon with fewer than 32768 notches. Output: an optimal
// convex decomposition (OPT = r + 1 - the most compatible patterns) under the thesis's general-position
// assumption A18' (docs/algorithms/chazelle-dobkin.md), Steiner points exact.
#include "core/registry.h"
#include "engines/chazelle_dobkin/tables.h"

namespace pd {
namespace {

Decomposition chazelle_dobkin(const Polygon& p, Counters& counters) {
  cd::ProgramCubic program(p);
  Decomposition d = program.run(counters);
  program.report(counters);
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "chazelle-dobkin", .kind = Kind::Convex, .steiner = true, .optimal = true,
                    .time_bound = "n+r^3", .pieces_bound = "== OPT",
                    .source = "Chazelle thesis (000) Sec. 2.4, Def. 2.4, Thm 18, Lemma 9",
                    .size_ceiling = 20000, .run = chazelle_dobkin});

}  // namespace pd
