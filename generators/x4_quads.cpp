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
// Known optima: 3m + 1 = r + 1 - r/4 convex pieces with Steiner points (one X4-pattern a group, and no
// X-pattern joins fewer than four notches), r + 1 with diagonals only; the ranges, both bounds and why
// the polygon is simple: docs/families.md, "Why x4-quads has the optimum it claims".
// Complexity: O(n log n) (the arcs' vectors).
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
