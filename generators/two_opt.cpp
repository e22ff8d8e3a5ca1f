// Family `2-opt`: a random polygon by 2-opt moves, after Auer and Held's RPG (T. Auer, M. Held,
// "Heuristics for the Generation of Random Polygons", CCCG 1996, Sec. 2, "2-opt moves"): a random tour
// of random points, untangled by 2-opt moves until no two edges cross.
//
// Shape: n distinct random lattice points of the square [-2^29, 2^29]^2 in a random order. While two
// edges (a, b) and (c, d) of the tour cross, the tour between b and c is reversed, which replaces them
// by (a, c) and (b, d); each pass scans every pair of edges whose x-ranges overlap, in tour order.
// Every move shortens the tour strictly (a crossing's diagonals are longer than its sides), so it ends,
// in a simple polygon, turned counter-clockwise. A draw where some three points are found collinear
// (an edge touching another one at a point, or three consecutive vertices on a line; rare with
// coordinates this large) is drawn again whole, from the same generator, so the polygon never depends
// on how a degenerate contact would be resolved.
// Feasible: 3 <= n <= 10,000 (the sweeps make each polygon again at the start of every run); r is an
// outcome, never chosen.
// Complexity: O(n^2) per pass; the number of passes and moves is what the tour needs (Auer and Held
// bound the moves by O(n^3)): measured, n = 2,000 in 0.1 s, 10,000 in 5.7 s and 20,000 in 32 s (the
// largest within a minute is about 25,000), on two busy cores.
// Coordinates: below 2^29 in magnitude.
#include "generators/family.h"
#include "generators/lattice.h"

#include <algorithm>
#include <optional>

namespace pd {
namespace {

using gen::Vec;

constexpr std::int64_t kHalfSide = std::int64_t{1} << 29;
constexpr std::size_t kMaxVertices = 10000;

int sign(__int128 v) { return (v > 0) - (v < 0); }

// How segments ab and cd meet: 0 apart, 1 crossing at one point inside both, -1 degenerate (some
// three of the points collinear where the segments meet).
int meeting(Vec a, Vec b, Vec c, Vec d) {
  const int d1 = sign(gen::cross(b - a, c - a)), d2 = sign(gen::cross(b - a, d - a));
  const int d3 = sign(gen::cross(d - c, a - c)), d4 = sign(gen::cross(d - c, b - c));
  if (d1 * d2 < 0 && d3 * d4 < 0) return 1;
  if (d1 * d2 > 0 || d3 * d4 > 0) return 0;
  // Some orientation is 0: the segments may touch or overlap; check the boxes of the collinear parts.
  const auto within = [](Vec p, Vec q, Vec x) {
    return std::min(p.x, q.x) <= x.x && x.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= x.y && x.y <= std::max(p.y, q.y);
  };
  if ((d1 == 0 && within(a, b, c)) || (d2 == 0 && within(a, b, d)) || (d3 == 0 && within(c, d, a)) ||
      (d4 == 0 && within(c, d, b)))
    return -1;
  return 0;
}

// One pass over the pairs of non-adjacent edges, a 2-opt move at each crossing found. Returns the
// number of moves, or nothing when a degenerate contact was met.
std::optional<std::size_t> untangle_pass(std::vector<Vec>& tour) {
  const std::size_t n = tour.size();
  std::size_t moves = 0;
  for (std::size_t i = 0; i + 2 < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the edges (n-1, 0) and (0, 1) share vertex 0
      const Vec a = tour[i], b = tour[i + 1], c = tour[j], d = tour[(j + 1) % n];
      if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x)) continue;
      const int m = meeting(a, b, c, d);
      if (m < 0) return std::nullopt;
      if (m == 0) continue;
      std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i + 1), tour.begin() + static_cast<std::ptrdiff_t>(j + 1));
      ++moves;
    }
  }
  return moves;
}

// The untangled tour, or nothing when the draw met a degenerate contact.
std::optional<std::vector<Vec>> untangled(std::size_t n, Rng& rng) {
  std::vector<Vec> tour = gen::distinct_random_points(n, kHalfSide, rng);
  while (true) {
    const std::optional<std::size_t> moves = untangle_pass(tour);
    if (!moves) return std::nullopt;
    if (*moves == 0) break;
  }
  if (gen::has_collinear_vertices(tour)) return std::nullopt;
  __int128 twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) twice_area += gen::cross(tour[i], tour[(i + 1) % n]);
  if (twice_area < 0) std::reverse(tour.begin(), tour.end());
  return tour;
}

std::vector<Point> make_two_opt(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::optional<std::vector<Vec>> tour;
  while (!(tour = untangled(n, rng))) {
  }
  return gen::points_of(*tour);
}

}  // namespace

REGISTER_FAMILY(outcome_family("2-opt",
                               "a random tour of random points untangled by 2-opt moves (RPG's 2-opt)",
                               3, kMaxVertices, make_two_opt));

}  // namespace pd
