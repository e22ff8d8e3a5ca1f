// Collinear vertices on request (`polydecomp generate --collinear K`): every family promises no three
// consecutive collinear vertices, so a 180-degree vertex, a degeneracy real files are full of, is
// asked for explicitly. The family's polygon of n - K vertices has its coordinates doubled and K of
// its edges, chosen by the seed, split at their midpoints: exact lattice points, so the polygon stays
// simple with the same r (a 180-degree vertex is neither convex nor reflex) and the same bytes on
// every machine. O(n) beyond the family's own cost.
#include "generators/family.h"
#include "generators/rng.h"

#include <cmath>

namespace pd {
namespace {

constexpr double kHalfBound = 1073741824.0;  // 2^30: doubled coordinates stay below 2^31

// Which of the m edges are split: k of them, uniformly, by a partial Fisher-Yates shuffle.
std::vector<bool> edges_to_split(std::size_t m, std::size_t k, std::uint64_t seed) {
  std::vector<std::size_t> order(m);
  for (std::size_t i = 0; i < m; ++i) order[i] = i;
  Rng rng(~seed);  // not the family's own stream (Rng(seed)), which made the polygon
  std::vector<bool> split(m, false);
  for (std::size_t i = 0; i < k; ++i) {
    std::swap(order[i], order[i + rng.below(m - i)]);
    split[order[i]] = true;
  }
  return split;
}

}  // namespace

std::vector<Point> generate_with_collinear(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                                           std::size_t k, std::uint64_t seed) {
  if (k == 0) return generate(family, n, r, seed);
  if (k > n / 2)
    throw GeneratorError("at n=" + std::to_string(n) + " at most n/2 = " + std::to_string(n / 2) +
                         " vertices can be collinear (one on an edge of the polygon of n - k vertices), not " +
                         std::to_string(k));
  std::vector<Point> base;
  try {
    base = generate(family, n - k, r, seed);
  } catch (const GeneratorError& e) {  // the message names n - k: say where that number comes from
    throw GeneratorError("with " + std::to_string(k) + " collinear vertices the polygon under them has n - k = " +
                         std::to_string(n - k) + " vertices: " + e.what());
  }
  for (const Point& p : base)
    if (!(std::abs(p.x()) < kHalfBound && std::abs(p.y()) < kHalfBound))
      throw GeneratorError("family " + family + " at n=" + std::to_string(n - k) + " has coordinates of 2^30 or " +
                           "more, which doubling for collinear vertices would take past 2^31");
  const std::vector<bool> split = edges_to_split(base.size(), k, seed);
  std::vector<Point> polygon;
  polygon.reserve(n);
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Point& a = base[i];
    const Point& b = base[(i + 1) % base.size()];
    polygon.emplace_back(2 * a.x(), 2 * a.y());
    if (split[i]) polygon.emplace_back(a.x() + b.x(), a.y() + b.y());
  }
  return polygon;
}

}  // namespace pd
