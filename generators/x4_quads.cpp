// Family `x4-quads`: a strip of groups of four thin slits, each group resolved by one X4-pattern (a
// tree with two Steiner points joining its four notches: Chazelle's thesis (000), Definition 2.2 in
// Sec. 2.2.3, Lemma 9), so that the optimum with Steiner points is known and needs X4-patterns:
// r + 1 - r/4 (Theorem 7), where diagonals need r + 1.
//
// Shape (template coordinates; the family scales them by an integer and centres them, which changes
// none of the arguments below): a 60-high strip, 80m long, of m groups; group j is the template
// polygon four_slits() of tests/test_steiner_optimum.cpp moved to x0 = 80j, a slit on each side near
// each end of the group, leaning towards the group's middle:
//   bottom-left  BL: mouth (x0 + 19, 0), reflex tip (x0 + 24, 12), mouth (x0 + 21, 0);
//   bottom-right BR: mouth (x0 + 59, 0), reflex tip (x0 + 56, 12), mouth (x0 + 61, 0);
//   top-right    TR: mouth (x0 + 61, 60), reflex tip (x0 + 56, 48), mouth (x0 + 59, 60);
//   top-left     TL: mouth (x0 + 21, 60), reflex tip (x0 + 24, 48), mouth (x0 + 19, 60).
// The group is symmetric under x -> 2 x0 + 80 - x and under y -> 60 - y. n = 12m + 4, r = 4m.
// Extra vertices bulge the sides between slits (and the strip's ends) outward as convex lattice arcs,
// the template being scaled up until the arcs fit (gen::padded_outline, as for `x2-pairs`); the seed
// places the extra vertices.
// Feasible: 16 <= n <= 1,000,000, r = 4m with m >= 1, n >= 3r + 4.
// Default r: 4 max(1, (n-4)/12), the most groups that fit.
//
// Ranges. The range R(v) of a tip (Sec. 2.2) lies in its cone, bounded by the extensions of its two
// slit edges: for BL the points (x0 + 24 + dx, 12 + dy) with dy/4 <= dx <= 5dy/12 (so dy >= 0), an
// 8.6-degree wedge along the slit's axis; the other three cones are its mirror images.
// (i) No tip lies in another tip's cone: BL's cone meets the line y = 12 only at its apex and y = 48
//     only at x0 + [33, 39], and every tip lies on one of those lines at x = 24 or 56 (mod 80); by the
//     symmetries the same holds for every tip.
// (ii) No point lies in the ranges of three tips. An arc bulges by less than 1/6 of its chord (its
//     slopes against the chord stay below 1/3), the longest horizontal chord is 38 and the strip's
//     ends bulge sideways only, so P lies in -6.4 < y < 66.4; there BL's cone spans
//     x0 + [24, 46.7] and by symmetry every range of group j lies in x0 + [24, 56]: ranges of different
//     groups are disjoint. Within a group, BL's cone lies left of the line x = x0 + 24 + 5(y - 12)/12
//     and TR's right of x = x0 + 56 - 5(48 - y)/12, 17 apart at every height, so they are disjoint;
//     likewise TL's and BR's. Any three notches of a group include BL and TR or TL and BR.
// Known optimum with Steiner points: 3m + 1 = r + 1 - r/4 convex pieces.
//   Upper bound: in each group the tree BL-S, TL-S, S-S', S'-BR, S'-TR with S = (x0 + 30, 30) and
//   S' = (x0 + 50, 30), inside the template and so in P, is an X4-pattern: S - BL = (6, 18) lies strictly inside BL's cone (dx/dy = 1/3,
//   between 1/4 and 5/12), likewise for the other tips, and the angles around S and S' are 108.4,
//   143.1 and 108.4 degrees. The m trees cut P into a bottom and a top piece per group and m + 1
//   pieces between and beyond the groups, 3m + 1 in all; each is convex because every vertex turns
//   left in it (the tips' angles are split inside their cones, the Steiner points' angles are below
//   180 degrees, and every other vertex is a convex vertex of P).
//   Lower bound: OPT = r + 1 - p, p the most compatible X-patterns (Theorem 7). A tree with l leaves
//   and s vertices of degree 3 has l = s + 2. An X-pattern with at most 3 notches (vertices of degree 1
//   or 2) is therefore a path, whose end's neighbour is a notch inside the end's range, excluded by
//   (i), or a star of three leaves around one point of their three ranges, excluded by (ii). So every
//   X-pattern joins at least 4 notches; compatible patterns share none (their edges would meet there),
//   so p <= r/4 = m and OPT >= 3m + 1. The count does not need patterns to stay within a group: (ii)
//   confines three-leaf stars to one, larger patterns might span two, and the count allows for it.
// Known optimum with diagonals only: r + 1 = 4m + 1 pieces. Upper bound: the four diagonals BL-BR,
//   BR-TR, TR-TL, TL-BL of each group (its inner rectangle) leave the rectangle, a bottom and a top
//   piece per group and m + 1 pieces between and beyond the groups, each convex (the tips' angles in
//   them are 90, 104 and 157.4 degrees). Lower bound: a tip with one diagonal needs it inside its cone,
//   so by (i) its other end is no notch: such tips have diagonals of their own, one each; every other
//   tip needs two diagonal ends, on further diagonals of two ends each; hence at least r diagonals,
//   r + 1 pieces.
// Complexity: O(n log n) (the arcs' vectors).
// Why simple: the template is simple (each slit is 2 wide at its mouth, 12 deep, inside its side's
// fifth of the strip, and the slits are at least 32 apart). An arc uses local vectors (a, b), a >= 1,
// |b| < a/3, summing along its side, so it stays outside the template within 18.5 degrees of its side;
// every vertex it starts or ends at (a corner, 90 degrees, a mouth where the slit begins, 67.4, or one
// where it ends, 104) turns by more than 37 degrees in the template, so it stays convex and the arcs of
// neighbouring sides stay apart.
// Coordinates: below 1.2e8 at n = 1e6 (largest for the smallest r, 1.15e8 at r = 4, the extra vertices
// then on few sides).
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

constexpr std::size_t kMaxQuadsVertices = 1'000'000;
constexpr std::int64_t kHeight = 60, kGroupWidth = 80;

std::size_t min_vertices(std::size_t r) { return 3 * r + 4; }

std::optional<std::string> x4_quads_r_infeasible(std::size_t n, std::size_t r) {
  if (r == 0 || r % 4 != 0) return "r must be a positive multiple of 4";
  if (n < min_vertices(r)) return "r = 4m needs n >= 3r+4";
  return std::nullopt;
}

// The group's two bottom slits, left to right (the outline runs counter-clockwise).
void bottom_slits(gen::Outline& outline, std::int64_t x0) {
  outline.slit({x0 + 19, 0}, {x0 + 24, 12}, {x0 + 21, 0});
  outline.slit({x0 + 59, 0}, {x0 + 56, 12}, {x0 + 61, 0});
}

// The group's two top slits, right to left: the bottom ones turned by 180 degrees about the group's
// centre.
void top_slits(gen::Outline& outline, std::int64_t x0) {
  outline.slit({x0 + 61, kHeight}, {x0 + 56, kHeight - 12}, {x0 + 59, kHeight});
  outline.slit({x0 + 21, kHeight}, {x0 + 24, kHeight - 12}, {x0 + 19, kHeight});
}

gen::Outline strip(std::size_t groups) {
  const auto start = [](std::size_t j) { return kGroupWidth * static_cast<std::int64_t>(j); };
  gen::Outline outline;
  outline.corner({0, 0});
  for (std::size_t j = 0; j < groups; ++j) bottom_slits(outline, start(j));
  outline.corner({start(groups), 0});
  outline.corner({start(groups), kHeight});
  for (std::size_t j = groups; j-- > 0;) top_slits(outline, start(j));
  outline.corner({0, kHeight});
  return outline;
}

std::vector<Point> make_x4_quads(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  return gen::centred_points(gen::padded_outline(strip(r / 4), n, rng));
}

}  // namespace

REGISTER_FAMILY({.name = "x4-quads",
                 .shape = "a strip of groups of four slits, each group resolved by one tree with two Steiner points",
                 .min_n = 16,
                 .max_n = kMaxQuadsVertices,
                 .r_range = "r = 4m with m >= 1, n >= 3r+4",
                 .controls_r = true,
                 .r_infeasible = x4_quads_r_infeasible,
                 .default_reflex = [](std::size_t n) { return 4 * std::max<std::size_t>(1, n < 4 ? 0 : (n - 4) / 12); },
                 .make = make_x4_quads});

}  // namespace pd
