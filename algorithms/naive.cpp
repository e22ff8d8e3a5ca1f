// naive: Chazelle's naive convex decomposition with Steiner points (B. Chazelle, Computational Geometry
// and Convexity, thesis, Yale 1980 (000), Sec. 2.2.1, Theorems 1 and 2).
//
// Time O(n r): each of the r notches shoots one segment and its ray is tested against all n edges of P
// and the O(r) segments drawn before (the thesis: G has n + 2N edges). Space O(n). Pre: a polygon, with
// h >= 0 holes (a hole's convex corners are notches of the polygon, and every ring is searched);
// collinear vertices allowed. Output: exactly r + 1 - h convex pieces (Theorem 1; the first segment to
// reach each hole joins two boundaries instead of splitting a piece), r segments split where later
// segments end on them, r Steiner points, all exact rationals, none at a vertex of G (every vertex has
// degree 2 or 3).
//
// Deviations from the thesis (the extension in place of the bisector, the repair of Figure 2.5-b, the
// choice of the turned segment's end, Theorem 2's walk) are stated in engines/naive/naive.cpp.
#include "core/registry.h"
#include "engines/naive/naive.h"

namespace pd {

REGISTER_ALGORITHM({.name = "naive", .kind = Kind::Convex, .steiner = true, .time_bound = "n*r",
                    .pieces_bound = "== r+1-h", .source = "Chazelle thesis (000) Sec. 2.2.1, Thms 1-2",
                    .accepts = {.holes = true}, .size_ceiling = 100000, .run = naive_decomposition});

}  // namespace pd
