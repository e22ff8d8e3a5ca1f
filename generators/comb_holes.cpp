// Family `comb-holes`: an orthogonal comb with h strictly convex lattice holes in its base.
//
// Shape: t teeth of width w and gaps of width w stand on a rectangular base; the holes sit in the
// cells of a g x g grid in the base (g = ceil(sqrt(h)); hole_grid.h), the base as high as the grid
// plus 2 and at least as wide, the teeth as high as the base. The outline has 4t vertices, 2(t - 1) of
// them reflex (the corners of the gaps); when n - r is odd its lower left corner is cut off (one more
// convex vertex). The holes take the other k = n - 4t - b vertices, all reflex: so
// n - r = 2t + b + 2, and t and the cut b follow from n - r.
// Feasible: h >= 1, n - r >= 4 and k = 2r - n + 4 + ((n - r) mod 2) >= 3h (each hole has 3 vertices or
// more), n <= 2,000,000. Default h = 4 and r such that the holes take about half the vertices
// (k >= max(n/2, 3h)).
// Why r is exact: the outline's only reflex vertices are the gaps' corners, and each hole is strictly
// convex, so every one of its vertices has an angle above 180 degrees inside the polygon.
// Why valid: the holes lie in separate cells, at least 1 inside each cell's border; the grid starts at
// (1, 1) inside the base, which is at least 2 wider and higher than the grid, and the cut corner
// (the line x + y = 1) passes below it.
// Complexity: O(n log n) (the holes' vectors). Coordinates: the holes are `convex`'s polygons with at
// most n vertices in all; HoleFamilies.TwoMillionVertices checks that no coordinate reaches 2^31.
#include "generators/family.h"
#include "generators/hole_grid.h"

namespace pd {
namespace {

constexpr std::size_t kDefaultHoles = 4;

// Twice r, plus 4 and the cut b, against n: the holes' vertices k = n - (4t + b) with 2t + b = n - r - 2
// are this minus n. Pre: r <= n - 4, so nothing overflows.
std::size_t hole_vertices_plus_n(std::size_t n, std::size_t r) { return 2 * r + 4 + (n - r) % 2; }

// Pre (HoleFamily::infeasible): n in range, so n - 4 does not wrap; every test is written so that a
// huge r or h cannot wrap either.
std::optional<std::string> rh_infeasible(std::size_t n, std::size_t r, std::size_t h) {
  if (h == 0) return "comb-holes has at least one hole (the comb without holes is `comb`)";
  if (r > n - 4) return "the outline has at least 4 convex vertices: r <= n - 4";
  const std::size_t k_plus_n = hole_vertices_plus_n(n, r);
  if (k_plus_n < n || h > (k_plus_n - n) / 3)
    return "each hole has at least 3 vertices: 2r - n + 4 + (n - r) mod 2 >= 3h";
  return std::nullopt;
}

std::size_t default_reflex(std::size_t n, std::size_t h) {
  if (h > n) return 0;  // infeasible anyway
  const std::size_t k = std::max(n / 2, 3 * h);
  return n + k < 4 ? 0 : (n + k - 4 + 1) / 2;
}

// The comb's outline, counter-clockwise from its lower left corner: t teeth of width w and height
// `height` on a base of width (2t - 1) w and height `base`, the corner cut off when `cut`.
std::vector<gen::Vec> comb_outline(std::int64_t t, std::int64_t w, std::int64_t base, std::int64_t height, bool cut) {
  const std::int64_t width = (2 * t - 1) * w, top = base + height;
  std::vector<gen::Vec> v;
  if (cut) v.insert(v.end(), {{0, 1}, {1, 0}});
  else v.push_back({0, 0});
  v.insert(v.end(), {{width, 0}, {width, top}});
  for (std::int64_t j = t - 1; j >= 0; --j) {
    const std::int64_t left = 2 * j * w;
    if (j < t - 1) v.insert(v.end(), {{left + w, base}, {left + w, top}});
    v.push_back({left, top});
    if (j > 0) v.push_back({left, base});
  }
  return v;
}

Rings make_comb_holes(std::size_t n, std::size_t r, std::size_t h, std::uint64_t seed) {
  Rng rng(seed);
  const std::size_t twice_t_and_cut = n - r - 2;
  const auto t = static_cast<std::int64_t>(twice_t_and_cut / 2);
  const gen::HoleGrid grid(hole_vertices_plus_n(n, r) - n, h, rng);
  const std::int64_t base = grid.side() + 2;
  const std::int64_t w = std::max<std::int64_t>(1, (base + 2 * t - 2) / (2 * t - 1));  // (2t - 1) w >= base
  Rings rings = {gen::points_of(comb_outline(t, w, base, base, twice_t_and_cut % 2 == 1))};
  for (Ring& hole : grid.placed({1, 1}, rng)) rings.push_back(std::move(hole));
  return rings;
}

}  // namespace

REGISTER_HOLE_FAMILY({.name = "comb-holes",
                      .shape = "an orthogonal comb with h strictly convex lattice holes in a grid in its base",
                      .min_n = 7,
                      .max_n = gen::kMaxVertices,
                      .rh_range = "h >= 1, r <= n - 4 and 2r - n + 4 + (n - r) mod 2 >= 3h",
                      .rh_infeasible = rh_infeasible,
                      .default_reflex = default_reflex,
                      .default_holes = kDefaultHoles,
                      .make = make_comb_holes});

}  // namespace pd
