// Family `convex-holes`: a strictly convex lattice outline with h strictly convex lattice holes.
//
// Shape: the outline is `convex`'s polygon with n - r vertices; the r hole vertices are shared out
// among the h holes as evenly as the seed allows (each at least 3), each hole `convex`'s polygon of its
// size, turned clockwise. The holes sit in the cells of a g x g grid (g = ceil(sqrt(h)); the seed picks
// the cells), each cell wider than every hole by 2, and the outline, scaled by 3 about a lattice point
// inside it, by the least power of two that puts the grid's square round that point strictly inside.
// Feasible: 3 <= n <= 2,000,000; h = 0 and r = 0, or h >= 1 and 3h <= r <= n/2. Default h = 4 and
// r = n/2 (at least 3h).
// Why r is exact: the outline is strictly convex, so none of its vertices is reflex, and each hole is
// strictly convex, so every one of its vertices has an angle above 180 degrees inside the polygon.
// Why valid: the holes lie in separate cells, at least 1 from each cell's border, so no two touch;
// the grid lies strictly inside the outline.
// Complexity: O(n log n) (the convex polygons' vectors).
// Coordinates: with r <= n/2 the outline has at least as many vertices as all holes together, so a
// small scale suffices; HoleFamilies.TwoMillionVertices checks that no coordinate reaches 2^31.
#include "generators/family.h"
#include "generators/hole_grid.h"

namespace pd {
namespace {

constexpr std::size_t kDefaultHoles = 4;

std::optional<std::string> rh_infeasible(std::size_t n, std::size_t r, std::size_t h) {
  if (h == 0) return r == 0 ? std::nullopt : std::optional<std::string>("without holes the polygon is convex: r = 0");
  if (h > r / 3) return "each hole has at least 3 vertices: r >= 3h";  // written so that a huge h cannot wrap
  if (r > n / 2) return "the outline has at least as many vertices as the holes: r <= n/2";
  return std::nullopt;
}

std::size_t default_reflex(std::size_t n, std::size_t h) {
  if (h == 0 || h > n) return 0;  // h > n is infeasible anyway, and 3h must not wrap
  return std::max(3 * h, n / 2);
}

// Whether the square [-a, a]^2 lies strictly inside the convex counter-clockwise polygon.
bool holds_square(const std::vector<gen::Vec>& v, std::int64_t a) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const gen::Vec p = v[i], edge = v[(i + 1) % v.size()] - p;
    for (const gen::Vec corner : {gen::Vec{a, a}, gen::Vec{-a, a}, gen::Vec{-a, -a}, gen::Vec{a, -a}})
      if (gen::cross(edge, corner - p) <= 0) return false;
  }
  return true;
}

Rings make_convex_holes(std::size_t n, std::size_t r, std::size_t h, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<gen::Vec> outline = gen::convex_lattice_polygon(n - r, rng);
  std::rotate(outline.begin(), outline.begin() + static_cast<std::ptrdiff_t>(rng.below(outline.size())), outline.end());
  if (h == 0) {
    const gen::Box ob = gen::box_of(outline);
    gen::translate(outline, {-(ob.x0 + ob.x1) / 2, -(ob.y0 + ob.y1) / 2});
    return {gen::points_of(outline)};
  }
  // The centroid of three vertices a third of the way round each is strictly inside; scaled by 3 it
  // is a lattice point, which becomes the origin.
  const std::size_t m = outline.size();
  const gen::Vec centre3 = outline[0] + outline[m / 3] + outline[2 * m / 3];
  for (gen::Vec& p : outline) p = 3 * p - centre3;
  const gen::HoleGrid grid(r, h, rng);
  const std::int64_t side = grid.side(), half = side / 2 + 1;
  while (!holds_square(outline, half))
    for (gen::Vec& p : outline) p = 2 * p;  // ends: the origin is strictly inside
  Rings rings = {gen::points_of(outline)};
  for (Ring& hole : grid.placed({-side / 2, -side / 2}, rng)) rings.push_back(std::move(hole));
  return rings;
}

}  // namespace

REGISTER_HOLE_FAMILY({.name = "convex-holes",
                      .shape = "a strictly convex lattice outline with h strictly convex lattice holes in a grid",
                      .min_n = 3,
                      .max_n = gen::kMaxVertices,
                      .rh_range = "h = 0 and r = 0, or h >= 1 and 3h <= r <= n/2",
                      .rh_infeasible = rh_infeasible,
                      .default_reflex = default_reflex,
                      .default_holes = kDefaultHoles,
                      .make = make_convex_holes});

}  // namespace pd
