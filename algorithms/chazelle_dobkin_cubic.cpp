// chazelle-dobkin: optimal convex decomposition with Steiner points, Algorithm CD with Section 2.4's
// organisation of STEP 3's X4 term (B. Chazelle, Computational Geometry and Convexity, thesis, Yale
// 1980 (000), Sec. 2.4, "An OCD Algorithm Cubic in the Number of Notches": Definition 2.4, Theorem 18,
// Lemma 9, the sorted lists of points A_ik on the segments r_i, the sets E(i, j) and the selection and
// two-way scans of Sec. 2.4.2). The dynamic program (STEPs 1-5), its orientation and its
// reconstructions are in algorithms/chazelle_dobkin.h; pattern detection for the Y-patterns in
// algorithms/chazelle_dobkin_patterns.h. The loose rays, the table entry and the program that fills and
// reads the rows are in algorithms/chazelle_dobkin_tables.h, where the tests read the rows too.
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
//     under summary words (PlaceSet in chazelle_dobkin_tables.h: at most 3 word operations per insert
//     or nearest member for 32767 notches), and the orders along G and H are counting sorts of ranks,
//     so a scan is O(r) besides its walks. The P2-feasible Y of a query are then exactly the set; P1
//     makes them a range from one end of it, and the query's witness is the first Y of that range, in
//     order from that end, that passes P4: the walk. Soundness: every witness satisfies all of (4)
//     (P4 tested, or, where a walk records a Y without testing it, proven by (6)), which chosen()
//     checks again in full before the layout (a failure throws: it would be a bug).
//     Completeness over loose pairs: by (4), every loose pair with the four conditions is reached by
//     the walk of its query before the walk stops, unless the walk stopped at an earlier witness.
// (6) The walks of a pass share what they learn (not in the OCR text, whose "2-way scans" stop before
//     saying how; proven here). G and H are the open clipped rays, in int P; X on G, Y on H; along a
//     pass X moves one way along G. A walk may skip a Y only where (a) or (b) proves that X cannot see
//     it, so it stops at the same Y as a walk testing every Y in turn (the test
//     CarriedOverWalksFindTheWitnessesOfWalksAlone holds every row of both to each other).
//     Two facts first. For one X the Y it sees form an interval of H (if X sees Y1 and Y2, the triangle
//     X Y1 Y2 has its boundary in int P, so all of it lies there), and for one Y the X that see it an
//     interval of G; they cover X or Y at equal ranks (several rays through one point).
//     (a) G and H cross at c. For X, Y other than c, XY lies in int P iff the closed triangle X c Y
//         does: Xc and cY lie in G and H, so if XY lies in int P the triangle's boundary does, and so
//         does the triangle, P being simply connected. The triangle only grows as X or Y moves away
//         from c along its ray. So on each side of c the Y that X sees are those between c and a
//         threshold: beyond c only the first Y of a walk need be tested, and on the walk's own side
//         (c included) the seen Y are the last ones. While X moves towards c, every Y an earlier X saw
//         stays seen: the walk tests the Y before the first such Y of the walk, one by one back
//         towards its start, while the tests pass.
//         While X moves away from c, a Y an earlier X did not see stays unseen: the walk starts after
//         it. (By (4) no X or Y is at c and all Y of a scan lie on one side of c; the code does not
//         need it.)
//     (b) G and H apart. Y lies strictly right of the line of G and X strictly right of that of H (4).
//         Let s and t be the parameters along G and H from their notches. If X1 sees Y1 and X2 sees
//         Y2 with s1 < s2 and t1 > t2, the closed path X1 X2 Y2 Y1 turns clockwise, strictly, at each
//         of its four corners (at X1 and X2 since Y1 and Y2 lie right of G's line, at Y2 and Y1 since
//         X2 and X1 lie right of H's), so it is a convex quadrilateral (its four turns, each strictly
//         between 0 and 180 degrees, add up to a multiple of 360, so to 360). Its sides lie in int P, so all of it does: every X between X1 and X2
//         sees every Y between Y2 and Y1. So the lowest and the highest Y that X sees along H never go
//         down as X moves up along G, and, for a walk whose seen Y move away from its start along the
//         pass: if X does not see Y but X or an earlier X saw a Y' at or after Y, no later X sees Y or
//         a Y before it (the walk starts after the last such Y). For a walk whose seen Y move back
//         towards its start: if X does not see Y but an earlier X saw a Y' at or before Y, neither X
//         nor a later X sees Y or a Y after it (the walk stops). (The same holds for crossing rays;
//         the cases differ in what the walks cost, (a) bounding it.)
// (7) For rays apart, where XY first meets the boundary tells on which side of what X sees Y lies (not
//     in the OCR text; proven here). G and H are chords of P, disjoint but perhaps for a shared end (a
//     ray stopping at the other's notch, or both at one boundary point), and not on one line (a query's
//     X lies strictly right of H's line, (4), so a scan of collinear rays has no query); two such
//     chords do not interleave on the boundary (ArcsBetween). Between them lies the part P' bounded
//     by G, an arc A of the boundary from an end of G to an end a of H, H, and an arc B from H's other
//     end b back to G (a single point where G and H share an end); beyond G lies the part bounded by
//     G and the boundary between G's ends. Take X on G and Y on H (open), XY meeting the boundary first at c,
//     going from X (first_contact). By (4), Y lies strictly right of G's line and X of H's, so XY
//     meets G's line only at X and H's only at Y, and c is no end of G or H.
//     (i) c on A: X sees no point Y' of H between Y and a. Else the chord XY' cuts P' into P_a (XY',
//         H from Y' to a, A, part of G) and P_b (XY', H from Y' to b, Y on it, B, the rest of G). The
//         triangle X Y' Y lies on one side of the line XY', near Y' the side of P_b (XY' reaches Y'
//         from P', and the side Y'Y is H towards b), so near X too, a chord having its part on one side
//         all along: XY leaves X into P_b. Until c it lies in int P' and cannot cross XY' (they share
//         X only), so it stays in P_b, whose boundary does not meet A: a contradiction. Likewise B, b.
//     (ii) c beyond G: XY left X away from P', and so does XY'' for every Y'' on H on Y's side of G's
//         line; such an XY'' cannot cross G, so it meets the boundary beyond G before reaching Y''.
//         Those Y'' are the points of H between Y and its end on Y's side of G's line.
//     (iii) c is on A, on B or beyond G: XY leaving X into P' stays in int P' until c, and P''s
//         boundary holds no point of the boundary beyond H.
//     So every unseen Y has an end e(Y) of H with no seen point between them. What X sees is an
//     interval of H (6), so along a walk the unseen steps before the seen ones have e at the walk's
//     start (a seen step lies between them and the far end) and those after at the far end: the
//     steps run start side*, seen*, far side*. If X sees no point of H no step is seen, whatever
//     the sides. The first seen inserted step, the walk's witness, is therefore the first inserted
//     step not on the start side when that one is seen, and there is none otherwise: the searches
//     find it by galloping and bisecting, O(log r) tests, each failing one followed by a
//     first_contact. Most walks end at once: the first two steps are tested in turn without asking
//     their sides (kPlainSteps), and a step not seen that (6) already places (at or before the
//     furthest step an earlier X saw, or at or after the nearest) needs no first_contact. What the
//     searches record for later X is what (6) allows for the steps they tested.
// Proven: every witness is an X4-pattern, so the output is always a valid decomposition, with at most
// the optimum's patterns. Assumed, not proven (call it A18'): whenever a tight X4-pattern in
// chazelle-dobkin-n5's sense (tips of Q, Theorem 15) exists, some loose one on tight notches exists too
// or STEP 2 already reaches the same count. That is Theorem 18 with its lost proof, which assumes
// general position (no reduction meets a notch): where a loose ray stops at a vertex (counter
// "x4_rays_at_vertex") the loose points beyond it do not exist, and nothing here proves that no
// pattern is lost. Under A18' (and n5's own completeness, chazelle_dobkin_patterns.h) S is the same
// table as n5's, by the induction over intervals. The tests compare the counts on every family, every
// rotation of x4-quads (both pairings), jittered x4-quads with crossing rays and with spikes where only
// P4 fails, and many small polygons; no difference was found (nor on some 40,000 further polygons,
// spikes grazing loose rays included, tried while writing this), so no fallback to tips was added.
// Four notches at a time, A18' in its strong form (an n5 X4 on four notches has a loose one on the same
// notches and pairing) held for every n5 X4 tried but those with an angle of exactly 180 degrees at a
// Steiner point, which n5's closed cones accept and Lemma 9 (strict, followed here) does not: e.g.
// random n=28 r=8 seed=45, notches 0, 1 | 4, 7, tips (-67/7, -80/7) and (-23/5, 92/5) on one line
// with z_0. Such patterns never changed a count (STEP 2 reached the same); the test
// EveryTipX4HasALooseX4OnTheSameNotches checks the strong form on samples.
// Deviations.
// - P4 is tested as a segment search on the boundary's convex chains (algorithms/boundary_chains.h:
//   a hierarchy of their bounding boxes, then binary searches on the chains near XY), O(r log(n/r))
//   per test in the worst case, rather than in O(1): the thesis's text stops before saying how. On
//   random n = 2000 (seed 1) a test costs 57, 45, 43 and 36 steps at r = 25, 50, 100 and 200
//   ("segment_search_steps" per "x4_p4_tests").
// - The walks of (6) reach O(1) amortized tests per query for crossing rays (a pass tests O(r) Y
//   besides at most two per query), the searches of (7) O(log r) per query for rays apart, a failing
//   test followed by a first_contact where (6) does not place its step. The thesis's scans presumably test O(1) per query; how
//   is in the lost text. Measured, seed 1, "x4_p4_tests": walks each alone (Walks::kEachAlone) / the
//   walks of (6) alone, before (7) / with (7), and "x4_p4_sides": notch-heavy n = 50, 100, 200, 400:
//   3,870 / 3,517 / 3,515 (19); 49,877 / 35,867 / 35,362 (586); 557,553 / 316,259 / 306,687 (6,152);
//   7,514,640 / 2,853,715 / 2,627,417 (78,028), for 3,262, 31,442, 270,966 and 2,279,469 witnesses;
//   random n = 2000, r = 100 and 200: 9,050 / 8,160 / 8,084 (290) and 82,454 / 69,449 / 58,858
//   (5,469), for 4,467 and 29,758 witnesses. The first contacts cost about what the tests saved
//   ("segment_search_steps" at notch-heavy n = 400 118,120,108 before (7), 117,362,561 with it;
//   random r = 200 2,442,827 and 2,396,616). User time, median of 5 runs alternating with the
//   build before (7): random r = 200 4.01 s then 4.14 s, notch-heavy n = 200 3.19 s then 3.38 s;
//   in a later, noisier set 4.05 s then 4.21 s and 4.11 s then 3.98 s. (7) bounds the worst case;
//   it does not speed up these.
// - Rays are clipped by ray shooting on convex arcs (algorithms/ray_shooting.h), O(r log n) per ray;
//   preprocessing and STEPs 2 and 4 are shared with chazelle-dobkin-n5 (visibility in place of
//   superranges; see chazelle_dobkin_patterns.h).
//
// Time: O(n log n + n r + r^2 log n) preprocessing, O(r^2 log r) for the lists; STEPs 2 and 4
// O(r^3) (chazelle_dobkin.h: O(1) per test); STEP 3's X4 term
// O(r^3) lookups; the scans O(r^3) list steps (a PlaceSet operation is O(1) for r < 32768) plus the
// P4 tests and first contacts, O(r log(n/r)) each: O(r) per pass and at most two per query for
// crossing rays, O(log r) per query for rays apart (7), so O(r^3 log r) of them over the O(r^3)
// queries (O(r) per interval). Worst case O(n log n + n r + r^4 log r log(n/r)). Space
// O(n + r^3) (a row per interval with a witness) plus O(r^2) rationals for the lists. Pre: a simple counter-clockwise polygon with fewer than 32768 notches. Output: an optimal
// convex decomposition (OPT = r + 1 - the most compatible patterns) under A18', Steiner points exact.
//
// Counters, besides the program's and the patterns': "x4_loose_points" (pairs of rays meeting inside
// both), "x4_rays_at_vertex" (loose rays clipped at a vertex), "x4_table_entries" (queries past their
// unary conditions), "x4_table_witnesses" (entries with a pattern, also added to "x4_found"),
// "x4_scan_steps" (list positions visited while filling, walks included), "x4_p4_tests" (segments XY
// tested), "x4_p4_sides" (first contacts asked for by the searches of rays apart, (7)),
// "x4_scans_sharing_an_end" (scans, with queries and inserts, of rays apart that share an end, (7)),
// "x4_lookup_steps" (STEP 3's lookups), "x4_chosen" (intervals whose S was reached by an X4-pattern)
// and "x4_chosen_from_w" (those from W's pairing).
#include "algorithms/chazelle_dobkin_tables.h"

namespace pd {
namespace {

Decomposition chazelle_dobkin(const Polygon& p, Counters& counters) {
  cd::ProgramCubic program(p);
  Decomposition d = program.run(counters);
  program.report(counters);
  return d;
}

}  // namespace

REGISTER_ALGORITHM(Algorithm{"chazelle-dobkin", Kind::Convex, true, true, "n*log(n)+n*r+r^4*log(r)*log(n/r)", "== OPT",
                             "Chazelle thesis (000) Sec. 2.4, Def. 2.4, Thm 18, Lemma 9", 20000, chazelle_dobkin});

}  // namespace pd
