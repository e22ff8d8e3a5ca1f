// Family `random`: a random x-monotone polygon with exactly r reflex vertices at random places.
//
// Shape: from the leftmost vertex L = (0, 0), a lower chain runs below the x-axis to (X_l, 0) and an
// upper chain above it to (X_u, 0); a horizontal edge joins the two right ends. The seed splits the
// vertices between the chains and picks which of the free vertices are reflex. For r = 0, r >= n-5
// and n < 7 there is only the lower chain, under a horizontal lid from its right end back to L.
// Feasible: 3 <= n <= 2,000,000, 0 <= r <= max(0, n-4). Default r = min(n/4, n-4) (0 for n < 5).
// Complexity: O(n) for the chains, O(k log k) for a table of k < 2n vectors.
// How r is exact: a chain c_1..c_m drops steeply from L to c_1 and climbs steeply from c_m, so c_1 and
// c_m are convex; each of c_2..c_{m-1} is free. Between them, edge j gets a level: the longer of the
// run of convex vertices just before it and the run of reflex vertices just after it. The level
// rises exactly across convex vertices and falls across reflex ones. Levels map to bands of lattice
// vectors (dx >= 1) ordered by slope, so the slope rises exactly at the convex vertices: turns are
// exact and never straight. Levels centre on the median, so the chain drifts little. With two chains
// the widths are made to differ, and the join at the right then has exactly one reflex end (the
// chains' ends at L and the lid's ends are convex). Two chains: r = 1 + reflex free vertices, of
// which there are n-7; one chain: r = reflex free vertices, of which there are n-4.
// Why simple: each chain is x-monotone and lies strictly below (the mirrored upper chain strictly
// above) the x-axis except at its ends, because the first drop exceeds the chain's highest rise.
// Coordinates: the k < max(65536, 2n) table vectors are the shortest with dx >= 1, of length below
// sqrt(1.05 k), so after centring every coordinate is below n sqrt(2.1 n) / 2, 2.05e9 < 2^31 at the
// largest n; r = 0 and r = n-4, whose single chain uses every band once, give 6.2e8.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

std::size_t max_reflex(std::size_t n) { return n < 4 ? 0 : n - 4; }

std::optional<std::string> random_r_infeasible(std::size_t n, std::size_t r) {
  if (r > max_reflex(n)) return "r must be at most max(0, n-4) = " + std::to_string(max_reflex(n));
  return std::nullopt;
}

// Levels of the edges c_1c_2, ..., c_{m-1}c_m from the turns at c_2..c_{m-1} (1 = reflex): a level
// rises across every convex vertex and falls across every reflex one.
std::vector<std::size_t> edge_levels(const std::vector<char>& reflex) {
  const std::size_t edges = reflex.size() + 1;
  std::vector<std::size_t> convex_run(edges, 0), reflex_run(edges, 0), level(edges);
  for (std::size_t j = 1; j < edges; ++j) convex_run[j] = reflex[j - 1] ? 0 : convex_run[j - 1] + 1;
  for (std::size_t j = edges - 1; j-- > 0;) reflex_run[j] = reflex[j] ? reflex_run[j + 1] + 1 : 0;
  for (std::size_t j = 0; j < edges; ++j) level[j] = std::max(convex_run[j], reflex_run[j]);
  return level;
}

// Level l -> a random vector of band l; bands are runs of the slope-sorted shortest primitive vectors
// with dx >= 1, so every vector of a band has a smaller slope than every vector of the next.
class SlopeBands {
 public:
  SlopeBands(const std::vector<std::vector<std::size_t>>& chains, Rng& rng) {
    std::vector<std::size_t> count;
    std::size_t edges = 0;
    for (const auto& levels : chains) {
      for (std::size_t l : levels) {
        if (l >= count.size()) count.resize(l + 1, 0);
        ++count[l];
        ++edges;
      }
    }
    if (edges == 0) return;
    // The median level gets the band of slope about 0, so that the chains' rises and falls balance.
    std::size_t median = 0, seen = 0;
    while (2 * (seen + count[median]) < edges) seen += count[median++];
    const std::size_t reach = std::max(median, count.size() - 1 - median);
    const std::size_t bands = 2 * reach + 1;
    // Several vectors per band for variety, while the table stays small; one when levels are many.
    per_band_ = std::clamp<std::size_t>(65536 / bands, 1, 8);
    offset_ = reach - median;
    table_ = gen::shortest_primitive_vectors(
        bands * per_band_, [](std::int64_t a, std::int64_t) { return a >= 1; }, rng);
    std::sort(table_.begin(), table_.end(), gen::slope_less);
    for (Vec v : table_) steepest_ = std::max(steepest_, v.y < 0 ? -v.y : v.y);
  }
  Vec pick(std::size_t level, Rng& rng) const {
    return table_[(level + offset_) * per_band_ + rng.below(per_band_)];
  }
  // A bound on every band's |slope|: the largest |dy| (dx >= 1).
  std::int64_t steepest() const { return steepest_; }

 private:
  std::vector<Vec> table_;
  std::size_t per_band_ = 1;
  std::size_t offset_ = 0;
  std::int64_t steepest_ = 0;
};

// A chain below the x-axis from L = (0, 0): its vertices c_1..c_m and the x of its right end.
struct Chain {
  std::vector<Vec> interior;
  std::int64_t width;
};

Chain build_chain(const std::vector<std::size_t>& levels, const SlopeBands& bands, Rng& rng) {
  std::vector<Vec> relative{{0, 0}};
  std::int64_t highest = 0;
  for (std::size_t l : levels) {
    relative.push_back(relative.back() + bands.pick(l, rng));
    highest = std::max(highest, relative.back().y);
  }
  // The drop from L clears the chain's highest point and leaves the last climb steeper than 2K, so
  // that it stays steeper than any band even when the chain is widened by one.
  const std::int64_t drop = highest + 2 * bands.steepest() + 1;
  Chain chain;
  for (Vec p : relative) chain.interior.push_back({1 + p.x, p.y - drop});
  chain.width = chain.interior.back().x + 1;
  return chain;
}

std::vector<std::size_t> levels_of(const std::vector<char>& free_turns, std::size_t interior) {
  return interior >= 2 ? edge_levels(free_turns) : std::vector<std::size_t>{};
}

// One chain under a lid: L, c_1..c_m, (X, 0).
std::vector<Vec> lidded(std::size_t n, std::size_t r, Rng& rng) {
  const std::size_t interior = n - 2;
  const std::vector<char> turns = gen::random_flags(interior >= 2 ? interior - 2 : 0, r, rng);
  const std::vector<std::vector<std::size_t>> levels{levels_of(turns, interior)};
  const SlopeBands bands(levels, rng);
  const Chain chain = build_chain(levels[0], bands, rng);
  std::vector<Vec> vertices{{0, 0}};
  vertices.insert(vertices.end(), chain.interior.begin(), chain.interior.end());
  vertices.push_back({chain.width, 0});
  return vertices;
}

// Two chains: L, lower c_1..c_m, (X_l, 0), (X_u, 0), upper chain mirrored and reversed.
std::vector<Vec> two_chains(std::size_t n, std::size_t r, Rng& rng) {
  // Split the n-3 chain vertices by coin flips, each chain keeping at least 2.
  std::size_t lower = 0;
  for (std::size_t i = 0; i < n - 3; ++i) lower += rng.next() >> 63;
  lower = std::clamp<std::size_t>(lower, 2, n - 5);
  const std::size_t upper = n - 3 - lower;
  const std::vector<char> turns = gen::random_flags(n - 7, r - 1, rng);
  const auto split = turns.begin() + static_cast<std::ptrdiff_t>(lower - 2);
  const std::vector<char> lower_turns(turns.begin(), split), upper_turns(split, turns.end());
  const std::vector<std::vector<std::size_t>> levels{levels_of(lower_turns, lower),
                                                     levels_of(upper_turns, upper)};
  const SlopeBands bands(levels, rng);
  Chain below = build_chain(levels[0], bands, rng);
  Chain above = build_chain(levels[1], bands, rng);
  if (below.width == above.width) (rng.below(2) == 0 ? below : above).width += 1;

  std::vector<Vec> vertices{{0, 0}};
  vertices.insert(vertices.end(), below.interior.begin(), below.interior.end());
  vertices.push_back({below.width, 0});
  vertices.push_back({above.width, 0});
  for (auto it = above.interior.rbegin(); it != above.interior.rend(); ++it)
    vertices.push_back({it->x, -it->y});
  return vertices;
}

std::vector<Point> make_random(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  const bool two = n >= 7 && r >= 1 && r <= n - 6;
  return gen::centred_points(two ? two_chains(n, r, rng) : lidded(n, r, rng));
}

}  // namespace

REGISTER_FAMILY({.name = "random",
                 .shape = "a random x-monotone polygon with exactly r reflex vertices at random places",
                 .min_n = 3,
                 .max_n = gen::kMaxVertices,
                 .r_range = "0 <= r <= max(0, n-4)",
                 .controls_r = true,
                 .r_infeasible = random_r_infeasible,
                 .default_reflex = [](std::size_t n) { return std::min(n / 4, max_reflex(n)); },
                 .make = make_random});

}  // namespace pd
