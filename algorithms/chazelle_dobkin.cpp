// chazelle-dobkin: optimal convex decomposition with Steiner points, Algorithm CD with Section 2.4's
// organisation of STEP 3's X4 term (B. Chazelle, Computational Geometry and Convexity, thesis, Yale
// 1980 (000), Sec. 2.4, "An OCD Algorithm Cubic in the Number of Notches": Definition 2.4, Theorem 18,
// Lemma 9, the sorted lists of points A_ik on the segments r_i, the sets E(i, j) and the selection and
// two-way scans of Sec. 2.4.2). The dynamic program (STEPs 1-5), its orientation and its
// reconstructions are in engines/chazelle_dobkin/program.h; pattern detection for the Y-patterns in
// engines/chazelle_dobkin/patterns.h. The loose rays, the table entry and the program that fills and
// reads the rows are in engines/chazelle_dobkin/tables.h, where the tests read the rows too.
//
// What the thesis says (Sec. 2.4.1-2.4.2, as far as the OCR text goes). Every X4-pattern that does not
// reduce to a Y-pattern reduces to a loose one (Theorem 18, Definition 2.4: each notch edge lined up
// with the extension of one of the notch's two edges, 16 configurations), so its Steiner points are
// among the points A_ik = r_i ∩ r_k, which STEP 1 sorts along each r_i. E(i, j) is computed right after
// S(i, j) and holds, per outer notch, "a single piece of data": whether an inner notch completes an
// X4-pattern that saves |S(i, j)| inside, found by selecting candidates on the two lists (the angle
// conditions 3 and 4 of Fig. 2.32, and tightness) and "2-way scans" of them, O(r) per interval. The
// text stops in the middle of the scan; Theorem 18's proof is the lost Figure 2.31.
//
// Reconstructed here, with proofs (S is the table of Algorithm CD; S(a, b) = 0 when a >= b).
// (1) Only tight X4-patterns matter. S is monotone and superadditive, so an X4-pattern on notches
//     i < k < l < j counts at most S(i+1, j-1) + 1, which it reaches iff T(i, j; k) and T(k, j; l), or
//     iff T(i, j; l) and T(i, l; k), where T(a, b; m): S(a+1, m-1) + S(m+1, b-1) = S(a+1, b-1).
// (2) Two pairings (Figure 2.24-a, -b), two tables, both filled when the program reaches the interval
//     (g, h) between the two notches whose rays carry the Steiner points:
//     E(k, j)[i]: a tight l in (k, j) and an X4 whose first Steiner point X joins z_i, z_k and whose
//       second Y joins z_l, z_j;  W(i, l)[j]: a tight k in (i, l) and an X4 whose first Steiner point
//       joins z_k, z_l and whose second joins z_j, z_i. Both are one shape: notches q, g, m, h in
//       counter-clockwise cyclic order, q outside the interval [g, h] and m inside it, X joining z_q
//       and z_g, Y joining z_m and z_h ((q, g, m, h) = (i, k, l, j) for E, (j, i, k, l) for W), so one
//       row per interval (g, h), indexed by q, holds E(g, h) for q < g and W(g, h) for q > h, and one
//       scan fills both. STEP 3 on (i, j) decides the X4 term from O(r) lookups (T(i, j; k) and
//       E(k, j)[i], or T(i, j; l) and W(i, l)[j]); every row it reads belongs to a shorter interval.
// (3) The loose rays. For notch v, ray 2v is the extension beyond z_v of its forward edge (the thesis's
//     r_v: its R_v is our forward edge, its clockwise order our index order), ray 2v + 1 that of its
//     backward edge, each clipped at its first contact with the boundary (a vertex included). An edge
//     along either leaves 180 degrees on one side and less on the other, so it resolves the notch.
//     Every pair of rays of distinct notches gets, once, the parameter along each line where the other
//     crosses it, and each ray's list sorted by it (exact rationals, computed once, sorted, then kept
//     as ranks): the thesis's sorted lists, O(r^2 log r). A pair whose crossing lies strictly inside both clipped
//     rays is a loose point; its two edges lie in int P.
// (4) The conditions of Lemma 9 for X = G ∩ Q on a ray G of g and Y = H ∩ M on a ray H of h, each exact
//     and strict. Angles below 180 at X are three positive turns (argued, not proven here: the order
//     of the neighbours around X is forced, by Lemma 9's remark on the order of the hull's vertices):
//     orient(X, z_q, z_g) > 0 (a property of the loose point),
//     orient(X, z_g, Y) > 0 (Y strictly right of the line of G: unary in m), orient(X, Y, z_q) > 0
//     (P1: Y strictly left of the line of Q). At Y likewise: orient(Y, z_m, z_h) > 0, X strictly right
//     of the line of H (unary in q), and P2: X strictly left of the line of M. Since Y moves along H,
//     P1 is a threshold on Y's rank along H, its direction the sign of u_Q x u_H (a constant when
//     parallel); P2 a threshold on X's rank along G, by the sign of u_M x u_G. Crossings (Lemma 9.1):
//     z_g X and z_h Y lie on opposite sides of the line XY, as do z_q X and z_m Y; z_g X meets z_m Y
//     only when u_M x u_G > 0, and then iff the crossing of the two lines is on both segments, which
//     under P2 is unary in m; z_q X and z_h Y symmetrically unary in q. P4: the segment XY lies in P.
// (5) The scan, per interval and per choice of G and H (4 runs, so with the two rays of q and of m all
//     16 configurations): the queries (outer q, both rays, in order along G) and the inserts (tight
//     inner m, both rays) that pass their unary conditions are merged along G; inserts with
//     u_M x u_G > 0 enter a set kept in order of Y's rank along H in a forward pass, those with
//     u_M x u_G < 0 in a backward pass, those parallel (P2 constant true) in one set, each query being
//     answered before inserts of its own rank (strictness). The set is a bitset of the places along H
//     under summary words (PlaceSet in engines/chazelle_dobkin/tables.h: at most 3 word operations per insert
//     or nearest member for 32767 notches), and the orders along G and H are counting sorts of ranks,
//     so a scan is O(r) besides finding what its queries see. The P2-feasible Y of a query are then
//     exactly the set; P1 makes them a range from one end of it (the walk's steps), and the query's
//     witness is the first Y of that range, in order from that end, that passes P4, XY in P. The Y
//     that X sees are a range of places (6), found with geodesics (7), so the witness is one nearest
//     member of the set. Soundness: every witness satisfies all of (4), which is checked again in
//     full on every pattern laid out (check_x4; a failure throws: it would be a bug). Completeness
//     over loose pairs: by (4), every loose pair with the four conditions lies in its query's range,
//     so the query finds it unless it found an earlier witness.
// (6) What X sees of H (not in the OCR text, whose "2-way scans" stop before saying how; proven here).
//     G and H are the open clipped rays, in int P; X on G, Y on H. For one X the Y it sees form an
//     interval of H (if X sees Y1 and Y2, the triangle X Y1 Y2 has its boundary in int P, so all of it
//     lies there): its places are a range [lo, hi) of by_at, equal ranks (several rays through one
//     point) in or out together. M: the ends move one way.
//     (a) G and H cross at c. For X, Y other than c, XY lies in int P iff the closed triangle X c Y
//         does: Xc and cY lie in G and H, so if XY lies in int P the triangle's boundary does, and so
//         does the triangle, P being simply connected. The triangle only grows as X or Y moves away
//         from c along its ray. By (4) no X or Y is at c, all X of a scan lie on one side of c and all
//         Y on one side, so the Y that X sees are those between c and a threshold, which moves away
//         from c as X moves towards it.
//     (b) G and H apart. Y lies strictly right of the line of G and X strictly right of that of H (4).
//         Let s and t be the parameters along G and H from their notches. If X1 sees Y1 and X2 sees
//         Y2 with s1 < s2 and t1 > t2, the closed path X1 X2 Y2 Y1 turns clockwise, strictly, at each
//         of its four corners (at X1 and X2 since Y1 and Y2 lie right of G's line, at Y2 and Y1 since
//         X2 and X1 lie right of H's), so it is a convex quadrilateral (its four turns, each strictly
//         between 0 and 180 degrees, add up to a multiple of 360, so to 360). Its sides lie in int P,
//         so all of it does: every X between X1 and X2 sees every Y between Y2 and Y1. So the lowest
//         and the highest Y that X sees along H never go down as X moves up along G.
//     R: for rays apart, the X of G that see some point of H+ (the part of H strictly right of G's
//     line, where every Y lies) form an interval of G. Take X1 < X2 < X3 along G, X1 seeing Y1 and X3
//     seeing Y3 in H+. If t1 > t3 the quadrilateral X1 X3 Y3 Y1 of (b) lies in int P and X2 sees the
//     points of Y3 Y1; if t1 = t3, the triangle X1 X3 Y1 does, and X2 sees Y1; if t1 < t3, the
//     segments X1 Y1 and X3 Y3 cross at a point p (X1 Y1 separates X3 from Y3 in the convex hull of
//     the four points, the turns being as in (b)), the triangles X1 X3 p and p Y1 Y3 lie in int P
//     (their boundaries do), and the ray from X2 through p meets Y1 Y3 at a point X2 sees. So along a
//     scan's queries in order along G, lo and hi move one way, but for the queries before and after
//     that interval, which see no Y.
// (7) How X sees H, from geodesics (not in the OCR text; the facts are standard: Lee and Preparata,
//     Networks 14, 1984; Guibas, Hershberger, Leven, Sharir and Tarjan, Algorithmica 2, 1987, where a
//     point's visibility polygon is read off its tree of shortest paths; engines/chazelle_dobkin/geodesics.h).
//     F1: the geodesic (shortest path in P) between two points is unique and turns only at notches;
//     the trees list a geodesic's turns and ends only. F3: for a segment K in P and a point e, the
//     geodesics from K's two ends to e meet at an apex and form a funnel; the geodesic from X on K to
//     e leaves X towards the funnel vertex f_e(X) from which it goes straight to X, and f_e(X) moves
//     monotonically over the funnel as X moves along K (geodesics to one point do not cross). F4: for
//     X off the line of H, X sees exactly the points of the open H strictly inside the angle between
//     the rays from X through f1 = f_{z_h}(X) and f2 = f_{w_H}(X), the rays along which the geodesics
//     from X to H's notch and to its far end leave X; each holds the first point of the boundary its
//     geodesic meets. The angle is below 180 degrees, and empty (X, f1 and f2 on one line) when X sees
//     no point of H. ("Strictly": a segment XY that touches the boundary touches a vertex, which then
//     lies on one of the two rays.)
//     So a scan takes the two funnels of G's ends to H's ends from the trees of geodesics rooted at
//     H's ends (each built the first time a scan needs it, O(r log r) over a decomposition of P by
//     O(r) vertical chords, at most 3r of them), and each
//     query its f1 and f2 by a search in each funnel and its range [lo, hi) by two searches along H.
//     A place is tested by at most two orientations (a query adds one, for the angle), which tell where
//     its Y lies: before the ray through f1 (towards H's notch), after the ray through f2 (towards the
//     far end), or seen. A query's range
//     is computed once, the first time a pass asks for it, and each search gallops from where the
//     last one ended: by F3 and M the answers move one way along the queries a pass asks for, and by
//     R the queries off the run sit at its two ends (a pass that follows one in the other direction,
//     or a query off the run, costs one jump of O(log r)). A scan therefore costs O(queries + inserts
//     + geodesic vertices) orientations, O(r). Which
//     places a query sees rests on F4 alone; the cost on F3, M and R. The test
//     GeodesicsFindTheWitnessesOfWalksAlone holds every row to walks that test each Y in turn with a
//     segment search, and Geodesics.ShortestPathsOfTheBruteForce the trees to a brute force.
// Proven: every witness is an X4-pattern, so the output is always a valid decomposition, with at most
// the optimum's patterns. Taken from the thesis, not proven here (call it A18'): whenever a tight
// X4-pattern in chazelle-dobkin-n5's sense (tips of Q, Theorem 15) exists, some loose one on tight
// notches exists too or STEP 2 already reaches the same count. That is how STEP 3 uses Theorem 18,
// whose proof rests on the lost Figure 2.31. The theorem is stated without a condition on position,
// and the rays here are the thesis's r_i = R(v_i, R_i) in every position: clipped at the first
// boundary point, a vertex included (counter "x4_rays_at_vertex"), past which no edge of an X-pattern
// runs (Theorem 12; Lemma 9, condition 3). So the scan misses no loose X4-pattern that the theorem
// promises; whether the lost proof covers every degenerate case (a reduction that meets a vertex)
// cannot be checked. Under A18' (and n5's own completeness, engines/chazelle_dobkin/patterns.h) S is the same
// table as n5's, by the induction over intervals. The tests compare the counts on every family, every
// rotation of x4-quads (both pairings), jittered x4-quads with crossing rays and with spikes where only
// P4 fails, many small polygons, and 600 lattice polygons where 3,411 loose rays stop at a vertex
// (SameCountOnDegenerateLatticePolygons); no difference was found (nor on some 40,000 further polygons,
// spikes grazing loose rays included, tried while writing this), so no fallback to tips was added.
// Apart from n5, with which this program shares STEPs 2 and 4, the independent checker
// (tests/steiner_optimum_check.h) gives the same count on degenerate lattice polygons with r <= 6
// (SteinerOptimalPrograms.AgreeWithTheCheckerOnDegenerateLatticePolygons, and 5,399 more tried while
// writing this, 4,872 of them with loose rays stopped at vertices), and on 1,438 x4-quads and
// x-pattern polygons snapped and jittered on lattices, where its witness holds an X4-pattern on 535
// and also rays stop at vertices on 41.
// Four notches at a time, A18' in its strong form (an n5 X4 on four notches has a loose one on the same
// notches and pairing) held for every n5 X4 tried but those with an angle of exactly 180 degrees at a
// Steiner point, which n5's X4 test accepts (splits_reflex_side) and Lemma 9 (strict, followed here)
// does not: e.g. random n=28 r=8 seed=45, notches 0, 1 | 4, 7, tips (-67/7, -80/7) and (-23/5, 92/5)
// on one line with z_0. Such patterns never changed a count (STEP 2 reached the same); the test
// EveryTipX4HasALooseX4OnTheSameNotches checks the strong form on samples.
// Deviations.
// - The thesis's text stops before saying how its scans test P4; its "O(N) per interval after O(N^3)
//   preprocessing" (for the X4 term) suggests a table of what each loose point sees of each ray. The
//   funnels of (7) compute those entries as the scans need them and store none; their geodesic
//   trees cost O(n + r^2 log n) in all (the chords, then O(r log r) per tree), as Algorithm CD's
//   preprocessing of the polygon does.
//   The check of the patterns laid out (check_x4) tests P4 as a segment search on the boundary's
//   convex chains (engines/search/boundary_chains.h), O(r log(n/r)) for each of O(r) patterns. Measured at
//   e6bf1f2 (seed 1, `polydecomp run --json`; "x4_p4_tests" / "x4_funnel_steps", seconds; in brackets
//   the walks with segment searches that (7) replaced: their tests, seconds): notch-heavy n = 50, 100,
//   200, 400: 8,136 / 11,359, 0.05 s; 77,542 / 111,774, 0.30 s; 638,076 / 934,447, 1.45 s; 5,216,414 /
//   7,778,005, 9.37 s (3,515, 0.06 s; 35,362, 0.49 s; 306,687, 4.00 s; 2,627,417, 33.0 s): each count
//   grows by 8.2-9.6 when r doubles. Random n = 2000, r = 100 and 200: 13,098 / 30,334, 0.63 s and
//   81,892 / 184,936, 4.21 s (8,084 and 58,858 tests; 4.1-4.7 s at r = 200, where STEP 2's X3 tests
//   take most of the time).
// - Rays are clipped by ray shooting on convex arcs (engines/search/ray_shooting.h), O(r log n) per ray;
//   preprocessing and STEPs 2 and 4 are shared with chazelle-dobkin-n5 (views across the notches from
//   trees of geodesics in place of superranges; see engines/chazelle_dobkin/patterns.h). The scans' geodesic
//   trees walk a decomposition of P by vertical chords of their own (engines/chazelle_dobkin/geodesics.h), built
//   when a scan first needs a tree (on the reference run's comb, convex, few-notches and spiral
//   polygons none does). P is never triangulated.
//
// Time: the views O(n + r^2 log n) (engines/chazelle_dobkin/patterns.h), the loose rays O(r^2 log n), the
// scans' vertical chords O(n + r^2 log n) once a scan needs a tree, O(r^2 log r) for the lists,
// O(r log r) for each of at most 3r geodesic trees; STEPs 2 and 4 O(r^3) (engines/chazelle_dobkin/program.h: O(1) per
// test); STEP 3's X4 term O(r^3) lookups and the scans O(r) each ((6), (7); a PlaceSet operation is
// O(1) for r < 32768), O(r^3) over the O(r^2) intervals; the checks of the O(r) patterns laid out
// O(r^2 log(n/r)); STEP 5 O(n + r^2 log(n/r)) (engines/chazelle_dobkin/program.h). Worst case O(n + r^3), the
// thesis's: r^2 log n is at most n when r^2 log n <= n, and O(r^3) otherwise, since then
// log n = O(log r). Space O(n + r^2) for the chords and the trees,
// O(r^3) for the rows (a row per interval with a witness) and O(r^2) rationals for the lists and loose
// points. Pre: a simple counter-clockwise polygon with fewer than 32768 notches. Output: an optimal
// convex decomposition (OPT = r + 1 - the most compatible patterns) under A18', Steiner points exact.
//
// Counters, besides the program's and the patterns': "x4_loose_points" (pairs of rays meeting inside
// both), "x4_rays_at_vertex" (loose rays clipped at a vertex), "x4_table_entries" (queries past their
// unary conditions), "x4_table_witnesses" (entries with a pattern, also added to "x4_found"),
// "x4_scan_steps" (list positions visited while filling, places tested included), "x4_p4_tests"
// (places tested against what a query's X sees, (7)), "x4_funnel_points" (vertices of the scans'
// funnels), "x4_funnel_steps" (orientations of the queries' searches in the funnels),
// "x4_scans_sharing_an_end" (scans, with queries and inserts, of rays apart that share an end),
// "x4_lookup_steps" (STEP 3's lookups), "x4_chosen" (intervals whose S was reached by an X4-pattern),
// "x4_chosen_from_w" (those from W's pairing), and the trees' "geodesic_chords" (of the decomposition
// they walk), "geodesic_trees", "geodesic_faces" (faces entered by their walks) and
// "geodesic_tangent_steps" (orientations of their funnel searches).
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
