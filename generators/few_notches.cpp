// Family `few-notches`: a large convex polygon with r shallow notches, each a single reflex vertex.
//
// Shape: the convex lattice polygon of n - r vertices (as the `convex` family makes it), scaled by 4;
// r of its edges, chosen at random, get one vertex pushed just inside the edge's middle.
// Feasible: 4 <= n <= 2,000,000, 0 <= r <= min(n/2, n-4) (one notch per edge of a base of at least
// 4 vertices). Default r = min(16, n/2, n-4).
// Complexity: O(n log n) (the base polygon).
// Why simple: the base edge pq has a primitive direction u, and the notch vertex is
// m = p + 2u + e with e the lattice vector of cross(u, e) = 1 nearest to u's normal. m is at distance
// 1/|u| inside the edge, at a fraction 3/8..5/8 along it; the base's other vertices are at lattice
// distance >= 1 from the edge line, i.e. >= 4/|u| after scaling, so each notch triangle (p, m, q) lies
// inside the base, near its own edge. cross(m - p, q - m) = -4 makes m reflex. Every turn of a base
// with >= 4 vertices is at most 90 degrees (dot >= 0 between consecutive edges), and with the notch
// offsets that small every base vertex stays strictly convex even between two notches.
// Coordinates: 4 times the convex family's, below 8.7e8 at n = 2e6.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

constexpr std::int64_t kScale = 4;

std::size_t max_notches(std::size_t n) { return std::min(n / 2, n - 4); }

std::optional<std::string> few_notches_r_infeasible(std::size_t n, std::size_t r) {
  if (r > max_notches(n)) return "r must be at most min(n/2, n-4) = " + std::to_string(max_notches(n));
  return std::nullopt;
}

// Floor of num / den for den > 0.
__int128 floor_div(__int128 num, __int128 den) { return num >= 0 ? num / den : -((-num + den - 1) / den); }

// (x, y) with a x + b y = gcd(a, b), for a, b >= 0.
std::pair<std::int64_t, std::int64_t> bezout(std::int64_t a, std::int64_t b) {
  if (b == 0) return {1, 0};
  const auto [x, y] = bezout(b, a % b);
  return {y, x - (a / b) * y};
}

// The lattice vector e with cross(u, e) = 1 whose projection on u is smallest (|dot| <= |u|^2 / 2).
Vec unit_offset(Vec u) {
  const auto [x, y] = bezout(u.x < 0 ? -u.x : u.x, u.y < 0 ? -u.y : u.y);
  // u.x * ey - u.y * ex = 1 with ey = sign(u.x) x and ex = -sign(u.y) y.
  Vec e{u.y < 0 ? y : -y, u.x < 0 ? -x : x};
  const __int128 norm = dot(u, u);
  const auto k = static_cast<std::int64_t>(floor_div(2 * dot(e, u) + norm, 2 * norm));
  return e - k * u;
}

std::vector<Point> make_few_notches(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  const std::vector<Vec> base = gen::convex_lattice_polygon(n - r, rng);
  const std::vector<char> notched = gen::random_flags(base.size(), r, rng);
  std::vector<Vec> vertices;
  vertices.reserve(n);
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Vec p = kScale * base[i];
    vertices.push_back(p);
    if (notched[i]) {
      const Vec u = base[(i + 1) % base.size()] - base[i];
      vertices.push_back(p + (kScale / 2) * u + unit_offset(u));
    }
  }
  return gen::centred_points(vertices);
}

}  // namespace

REGISTER_FAMILY({.name = "few-notches",
                 .shape = "a large convex lattice polygon with r shallow single-vertex notches in random edges",
                 .min_n = 4,
                 .max_n = gen::kMaxVertices,
                 .r_range = "0 <= r <= min(n/2, n-4)",
                 .controls_r = true,
                 .r_infeasible = few_notches_r_infeasible,
                 .default_reflex = [](std::size_t n) {
                   return n < 4 ? std::size_t{0} : std::min<std::size_t>(16, max_notches(n));
                 },
                 .make = make_few_notches});

}  // namespace pd
