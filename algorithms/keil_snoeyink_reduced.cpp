// keil-snoeyink-reduced: Keil & Snoeyink (001), Sec. 4, Theorem 5: the minimum convex decomposition
// without Steiner points through a reduced polygon.
//
// The fewest convex pieces cut by diagonals. Pre: a simple counter-clockwise polygon; collinear
// vertices allowed. Pieces: == OPT. Time O(n + min(n r^2, r^3 log n + r^4)), space O(n + min(n r^2,
// r^4)): near-linear in n at fixed r (the paper: O(n + min(n r^2, r^4)), see the deviations).
//
// Some minimum decomposition is biased (Corollary 4), and in a biased decomposition every diagonal
// ends at a reflex vertex or at the endpoint of an RE-diagonal (the extension through reflex r of the
// edge after r first meets vertex p or the edge after p) or of a DE-diagonal (the same for the
// extension through r of an RR- or RE-diagonal at r) (Lemma 3). Those endpoints are found by shooting
// rays: for every reflex r its edge extension, the extension of its RE-diagonal, and, for every other
// reflex r', the ray towards r' (is rr' an RR-diagonal?) and the extensions of each RR-diagonal through
// both ends: O(r^2) rays. The polygon is then reduced to the kept vertices (r reflex, at most r RE
// and r + r(r - 1) DE ends: min(n, r^2 + 2r)), and Algorithm 1 (keil-snoeyink) runs on it:
// O(min(n, r^2) r^2). Its diagonals are diagonals of the input, which it returns.
//
// Deviations, each stated where it acts:
//  - Ray shooting by convex arcs (ray_shooting.h), O(a log n) per ray for a = O(r) arcs instead of
//    O(log n). When the reduced polygon could not be smaller (r^2 + 2r >= n) or the rays would cost
//    at least as much as Algorithm 1 on the whole polygon (a log n >= n, so r^2 a log n >= n r^2),
//    nothing is shot and Algorithm 1 runs on the input: the theorem's n r^2 branch (reduced_n = n,
//    rays_shot = 0). Time O(n + min(n r^2, r^2 a log n + r^4)).
//  - The reduced polygon also keeps both neighbours of every kept vertex (so at most
//    min(n, 3 (r^2 + 2r)) vertices, the same order). Then every kept vertex keeps its own angle (a
//    reflex vertex stays reflex, a convex one's piece cannot open beyond 180 degrees once the removed
//    part is put back), and every removed run of convex vertices is a convex pocket cut off by one
//    edge of the reduced polygon; a piece of the reduced polygon on that edge, joined with its pocket,
//    is still convex (the angles at the edge's ends stay within the input's, which are convex). So a
//    decomposition of the reduced polygon is one of the input with the same pieces, and a biased
//    minimum decomposition of the input, whose diagonals join kept vertices and never enter a pocket
//    (a segment cannot cross a pocket's edge twice), is one of the reduced polygon: the minima agree.
#include "core/registry.h"
#include "engines/keil_snoeyink/reduction.h"

namespace pd {

REGISTER_ALGORITHM({.name = "keil-snoeyink-reduced", .kind = Kind::Convex, .optimal = true,
                    .time_bound = "n+min(n*r^2,r^4)", .pieces_bound = "== OPT",
                    .source = "Keil & Snoeyink (001) Sec. 4, Thm 5", .run = keil_snoeyink_reduced});

}  // namespace pd
