// Family `spiral`: a square spiral strip; its inner side is the chain of reflex vertices.
//
// Shape: a strip of width w winding outward counter-clockwise with r right-angle turns. Its outer
// side turns left r times (convex), its inner side turns right r times (reflex), and two caps close
// it (4 convex vertices). Extra vertices, n - 2r - 4 of them, bulge the outermost edge outward as a
// convex lattice arc. The seed picks the width and the gaps between windings.
// Feasible: 6 <= n <= 2,000,000, 1 <= r <= n/2-2. Default r = n/2-2 (no arc).
// Complexity: O(n) for the strip, O(n log n) for the arc's vectors.
// Why simple: with directions d_k = E, N, W, S, ... the k-th corner of the inner side is
// e_{k-1} d_{k-1} + e_k d_k, where the wall positions grow as e_k = e_{k-4} + w + g_k with gaps
// g_k >= 1: each winding's inner side lies at distance g_k >= 1 beyond the previous winding's outer
// side, and the start cap is clear of the first winding. The last edge of the outer side lies on the
// outermost wall, so the arc, which bulges beyond it, meets nothing. The arc leaves and rejoins that
// edge's line turning left, so its ends stay convex.
// Coordinates: the strip spans about 2n; the arc, largest for r = 1, is below 6.2e8 at n = 2e6.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

std::size_t max_turns(std::size_t n) { return n / 2 - 2; }

std::optional<std::string> spiral_r_infeasible(std::size_t n, std::size_t r) {
  if (r < 1) return "r must be at least 1";
  if (r > max_turns(n)) return "r must be at most n/2-2 = " + std::to_string(max_turns(n));
  return std::nullopt;
}

// Direction k of the spiral: east, north, west, south, repeating (a left turn each step).
Vec direction(std::int64_t k) {
  static const Vec kDirections[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return kDirections[((k % 4) + 4) % 4];
}

// The spiral's walls: wall(k) is the position, along direction k, of the line that the inner side's
// segment k+1 runs on. Index k + 4 holds wall k, for k >= -4.
class Walls {
 public:
  Walls(std::size_t turns, std::int64_t width, Rng& rng) : e_(turns + 5) {
    // The walls "before" the spiral: segments 0..2 just need positive length, and the south wall
    // must clear the start cap, which reaches down to y = -width.
    e_[0] = e_[1] = e_[2] = -width;
    e_[3] = 0;
    for (std::size_t k = 4; k < e_.size(); ++k) e_[k] = e_[k - 4] + width + rng.between(1, 3);
  }
  std::int64_t operator()(std::int64_t k) const { return e_[static_cast<std::size_t>(k + 4)]; }

 private:
  std::vector<std::int64_t> e_;
};

std::vector<Point> make_spiral(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  const auto turns = static_cast<std::int64_t>(r);
  const std::int64_t width = rng.between(1, 3);
  const Walls wall(r, width, rng);

  // The outermost outer edge runs along direction `turns` from the last outer corner to the end cap;
  // extra vertices make it a convex arc, which needs a minimum length.
  const std::size_t arc_vertices = n - 2 * r - 4;
  const std::vector<Vec> reps = gen::shortest_primitive_vectors(
      arc_vertices / 2, [](std::int64_t a, std::int64_t b) { return a >= 1 && b >= 1; }, rng);
  const std::int64_t start = -(wall(turns - 2) + width);  // the last outer corner, along d_turns
  const std::int64_t end = std::max(wall(turns), start + gen::convex_arc_min_length(arc_vertices, reps, 1));

  const Vec along = direction(turns), outward = direction(turns - 1);
  std::vector<Vec> vertices;
  vertices.reserve(n);
  // Outer side, from the start cap outward.
  vertices.push_back(width * direction(-1));
  for (std::int64_t k = 0; k < turns; ++k) {
    vertices.push_back((wall(k - 1) + width) * direction(k - 1) + (wall(k) + width) * direction(k));
  }
  // The arc bulges to the right of `along`, i.e. outward: local (a, b) is a along + b (-outward).
  Vec at = vertices.back();
  const std::vector<Vec> arc = gen::convex_arc(arc_vertices, end - start, reps, 1);
  for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
    at = at + arc[i].x * along - arc[i].y * outward;
    vertices.push_back(at);
  }
  const Vec inner_end = wall(turns - 1) * outward + end * along;
  vertices.push_back(inner_end + width * outward);
  // Inner side, back to the centre.
  vertices.push_back(inner_end);
  for (std::int64_t k = turns - 1; k >= 0; --k) {
    vertices.push_back(wall(k - 1) * direction(k - 1) + wall(k) * direction(k));
  }
  vertices.push_back({0, 0});
  return gen::centred_points(vertices);
}

}  // namespace

REGISTER_FAMILY({.name = "spiral",
                 .shape = "a square spiral strip with r right-angle turns; its inner side is all the reflex vertices",
                 .min_n = 6,
                 .max_n = gen::kMaxVertices,
                 .r_range = "1 <= r <= n/2-2",
                 .controls_r = true,
                 .r_infeasible = spiral_r_infeasible,
                 .default_reflex = [](std::size_t n) { return n < 6 ? std::size_t{1} : max_turns(n); },
                 .make = make_spiral});

}  // namespace pd
