// Family `x2-pairs`: a strip with its notches in facing pairs, each pair resolved by the one segment
// joining its two tips (Chazelle's X2-patterns), so the optimum is known: r/2 + 1 convex pieces.
//
// Shape: a 64-high strip, 32 (m + 1) long, with m pairs, pair j centred at x = 32 (j + 1). A pair is
// two thin triangular notches straight across from each other: on the bottom side mouth (x -+ 1, 0)
// and reflex tip (x, 16), on the top side mouth (x +- 1, 64) and reflex tip (x, 48). n = 6m + 4.
// Extra vertices bulge the sides between notches (and the strip's ends) outward as convex lattice
// arcs, the template being scaled up until the arcs fit (gen::padded_outline, as for `x-pattern`);
// the seed places the extra vertices.
// Feasible: 10 <= n <= 1,000,000, r = 2m with m >= 1, n >= 3r + 4.
// Default r: 2 max(1, (n-4)/6), the most pairs that fit.
// Known optimum (with or without Steiner points): r/2 + 1 = m + 1 convex pieces.
//   Upper bound: the m vertical segments (x, 16)-(x, 48) lie inside the strip and cut it into m + 1
//   pieces. Each piece is convex: at a tip the cut splits the reflex angle into two angles of
//   180 - atan(1/16) degrees (the cut runs along the notch's axis, inside its range), and every other
//   vertex of a piece is a vertex of the strip, convex in the polygon.
//   Lower bound: ceil(r/2) + 1 (Chazelle's thesis, Theorem 8): an optimal decomposition has r + 1 - p
//   pieces for p compatible X-patterns (Theorem 7), and each X-pattern resolves at least two notches,
//   so p <= r/2.
// Complexity: O(n log n) (the arcs' vectors).
// Why simple: the template is simple (each notch is 2 wide, 16 deep, inside its side's half of the
// strip, and the notches are 32 apart). An arc uses local vectors (a, b), a >= 1, |b| < a/3, summing
// along its side, so it stays outside the template within 18.5 degrees of its side; every vertex it
// starts or ends at (a corner, 90 degrees, or a mouth, 86.4 degrees) turns by more than 37 degrees in
// the template, so it stays convex and the arcs of neighbouring sides stay apart.
// Coordinates: below 1.2e8 at n = 1e6 (largest for the smallest r, 1.14e8 at r = 4, the extra vertices
// then on few sides).
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

constexpr std::size_t kMaxPairsVertices = 1'000'000;
constexpr std::int64_t kHeight = 64, kDepth = 16, kSpacing = 32;

std::size_t min_vertices(std::size_t r) { return 3 * r + 4; }

std::optional<std::string> x2_pairs_r_infeasible(std::size_t n, std::size_t r) {
  if (r == 0 || r % 2 != 0) return "r must be a positive even number";
  if (n < min_vertices(r)) return "r = 2m needs n >= 3r+4";
  return std::nullopt;
}

gen::Outline strip(std::size_t pairs) {
  const auto axis = [](std::size_t j) { return kSpacing * static_cast<std::int64_t>(j + 1); };
  const std::int64_t width = axis(pairs);
  gen::Outline outline;
  outline.corner({0, 0});
  for (std::size_t j = 0; j < pairs; ++j) outline.slit({axis(j) - 1, 0}, {axis(j), kDepth}, {axis(j) + 1, 0});
  outline.corner({width, 0});
  outline.corner({width, kHeight});
  for (std::size_t j = pairs; j-- > 0;) {
    outline.slit({axis(j) + 1, kHeight}, {axis(j), kHeight - kDepth}, {axis(j) - 1, kHeight});
  }
  outline.corner({0, kHeight});
  return outline;
}

std::vector<Point> make_x2_pairs(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  return gen::centred_points(gen::padded_outline(strip(r / 2), n, rng));
}

}  // namespace

REGISTER_FAMILY({.name = "x2-pairs",
                 .shape = "a strip with its notches in facing pairs, each pair resolved by the segment joining its tips",
                 .min_n = 10,
                 .max_n = kMaxPairsVertices,
                 .r_range = "r = 2m with m >= 1, n >= 3r+4",
                 .controls_r = true,
                 .r_infeasible = x2_pairs_r_infeasible,
                 .default_reflex = [](std::size_t n) { return 2 * std::max<std::size_t>(1, n < 4 ? 0 : (n - 4) / 6); },
                 .make = make_x2_pairs});

}  // namespace pd
