// Family `convex`: a strictly convex lattice polygon, close to a disc.
//
// Shape: the edges are the n shortest primitive lattice vectors closed into a cycle (pairs {v, -v},
// plus the triangle (1, 0), (0, 1), (-1, -1) when n is odd), sorted by angle. The seed breaks ties
// among vectors of equal length and picks the first vertex.
// Feasible: 3 <= n <= 2,000,000, r = 0. Default r = 0.
// Complexity: O(n log n) (enumerating and sorting the vectors).
// Why simple: the edge vectors have pairwise distinct directions and sum to zero, so in angle order
// they turn strictly left at every vertex and wind exactly once: a strictly convex polygon, with no
// collinear vertices.
// Coordinates: the perimeter is about 0.48 n^1.5, and after centring no coordinate exceeds a quarter
// of it: below 3.4e8 at n = 2e6 (2.2e8 measured).
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

std::optional<std::string> convex_r_infeasible(std::size_t , std::size_t r) {
  if (r != 0) return "a convex polygon has r = 0";
  return std::nullopt;
}

std::vector<Point> make_convex(std::size_t n, std::size_t, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<gen::Vec> vertices = gen::convex_lattice_polygon(n, rng);
  std::rotate(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(rng.below(n)), vertices.end());
  return gen::centred_points(vertices);
}

}  // namespace

REGISTER_FAMILY({.name = "convex",
                 .shape = "a strictly convex lattice polygon whose edges are the n shortest primitive vectors",
                 .min_n = 3,
                 .max_n = gen::kMaxVertices,
                 .r_range = "r = 0",
                 .controls_r = false,
                 .r_infeasible = convex_r_infeasible,
                 .default_reflex = [](std::size_t) { return std::size_t{0}; },
                 .make = make_convex});

}  // namespace pd
