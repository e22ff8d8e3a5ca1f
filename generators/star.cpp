// Family `star`: a random star-shaped polygon, after Auer and Held's RPG (T. Auer, M. Held, "Heuristics
// for the Generation of Random Polygons", CCCG 1996, Sec. 2, "Star-shaped polygons"): random points
// about a kernel point, joined in the order of their angles around it.
//
// Shape: n lattice points drawn uniformly from the disc of radius 2^29 about the origin (rejection
// from its square), sorted by the exact angle of their position vectors (gen::angle_less).
// Feasible: 3 <= n <= 2,000,000; r is an outcome (about half the vertices on large n), never chosen.
// Complexity: O(n log n) expected (the sort); a draw is made again, from the same generator, when two
// points share a direction, an angular gap reaches 180 degrees or three consecutive vertices are
// collinear (for large n none of it happens but with probability about n / 2^29).
// Why simple: with distinct directions and every gap below 180 degrees the origin lies strictly inside
// and each edge spans its own angular interval, so the edges meet only at shared vertices: the polygon
// is simple and star-shaped from the origin, counter-clockwise, without collinear vertices.
// Coordinates: below 2^29 in magnitude.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

constexpr std::int64_t kRadius = std::int64_t{1} << 29;

gen::Vec point_in_disc(Rng& rng) {
  while (true) {
    const gen::Vec p{rng.between(-kRadius, kRadius), rng.between(-kRadius, kRadius)};
    if ((p.x != 0 || p.y != 0) && gen::dot(p, p) <= static_cast<__int128>(kRadius) * kRadius) return p;
  }
}

// Whether the points, sorted by angle, make the promised polygon: every turn from one position
// vector to the next strictly left and below 180 degrees, and no three consecutive points collinear.
bool star_shaped(const std::vector<gen::Vec>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const gen::Vec a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
    if (gen::cross(a, b) <= 0 || gen::cross(b - a, c - b) == 0) return false;
  }
  return true;
}

std::vector<Point> make_star(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<gen::Vec> v(n);
  do {
    for (gen::Vec& p : v) p = point_in_disc(rng);
    std::sort(v.begin(), v.end(), gen::angle_less);
  } while (!star_shaped(v));
  return gen::points_of(v);
}

}  // namespace

REGISTER_FAMILY(outcome_family("star",
                               "random points in a disc joined in the order of their angles about its centre (RPG's star)",
                               3, gen::kMaxVertices, make_star));

}  // namespace pd
