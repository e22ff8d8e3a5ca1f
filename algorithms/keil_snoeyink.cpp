// keil-snoeyink: J. M. Keil and J. Snoeyink, "On the time bound for convex decomposition of simple
// polygons" (001), Sec. 3, Algorithm 1, Theorem 2.
//
// Minimum convex decomposition without Steiner points: the fewest convex pieces cut by diagonals.
// Time O(n r^2) and space O(n r^2) (Theorem 2), after the visibility lists of the reflex vertices
// (O(n log n) triangulation + O(n) per reflex vertex, visibility.h). Pre: a simple counter-clockwise
// polygon; collinear vertices allowed (pieces may have 180-degree vertices). Pieces: == OPT.
//
// Keil's dynamic program (engines/keil_snoeyink/narrowest_pairs.h) with its search structure replaced by stacks: the pairs of
// P_ik are one array in increasing order; T_ik pops from the bottom (TypeA, called for increasing k
// with i, j fixed) and S_ik from the top (TypeB, called for decreasing i with j, k fixed), each
// popping a pair only while the next one still keeps p_j convex. Whatever is popped is wider at p_j
// than a pair that already serves every later call (Observation 1), so each pair is popped at most
// once per stack: the pops are bounded by the pushes, at most two per TypeA/TypeB call, and the calls
// by n r^2. Deviation: the two cases engines/keil_snoeyink/narrowest_pairs.h adds for collinear vertices (chains, and
// 180-degree pieces found by binary search), which general-position input never reaches.
#include "core/registry.h"
#include "engines/keil_snoeyink/stacks.h"

namespace pd {

REGISTER_ALGORITHM({.name = "keil-snoeyink", .kind = Kind::Convex, .optimal = true, .time_bound = "n*r^2",
                    .pieces_bound = "== OPT", .source = "Keil & Snoeyink (001) Sec. 3, Alg. 1, Thm 2",
                    .size_ceiling = 2000, .run = keil_snoeyink});

}  // namespace pd
