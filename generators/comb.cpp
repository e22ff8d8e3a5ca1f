// Family `comb`: a spine with teeth; the reflex vertices are the bottoms of the gaps between teeth.
//
// Shape: a horizontal spine with g + 1 upward teeth of steep sides (run 1, rise T). A square gap has
// two reflex corners, a V gap one: r/2 square gaps and, for odd r, one V gap at a random place.
// Teeth are pointed (one vertex) or flat-topped (two); once every tooth is flat, further vertices
// become convex lattice arcs on the tooth tops. With n = 4t the comb is the classic one: t flat teeth,
// r = 2t-2.
// Feasible: 3 <= n <= 2,000,000, 0 <= r <= 2(n-3)/3 (pointed teeth and square gaps use the fewest
// vertices: 3 + ceil(r/2) + r). Default r = 2 floor(n/4) - 2 for n >= 4 (the classic comb), else 0.
// Complexity: O(n) for the comb, O(n log n) for the arcs' vectors.
// Why simple: the boundary above the bottom edge is an x-monotone chain (every step has dx >= 1)
// that stays at height >= 1 except at its two ends, which are the bottom corners. Along it the slopes
// fall at tooth tops (side T, arc slopes below T, side -T) and rise at gap bottoms, so tops are
// convex and gap corners reflex; no two consecutive steps have equal slope.
// Coordinates: the arcs are split evenly over the teeth; the largest, one tooth at r = 0, is below
// 6.2e8 at n = 2e6.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

std::size_t max_reflex(std::size_t n) { return n < 3 ? 0 : 2 * (n - 3) / 3; }

std::optional<std::string> comb_r_infeasible(std::size_t n, std::size_t r) {
  if (r > max_reflex(n)) return "r must be at most 2(n-3)/3 = " + std::to_string(max_reflex(n));
  return std::nullopt;
}

struct Plan {
  std::size_t gaps;              // between teeth
  std::size_t v_gap;             // index of the one-vertex gap, or `gaps` for none
  std::vector<char> flat;        // per tooth
  std::vector<std::size_t> arc;  // per tooth: arc vertices on the top
};

Plan plan_comb(std::size_t n, std::size_t r, Rng& rng) {
  Plan plan;
  plan.gaps = (r + 1) / 2;
  plan.v_gap = r % 2 == 1 ? rng.below(plan.gaps) : plan.gaps;
  const std::size_t teeth = plan.gaps + 1;
  const std::size_t extra = n - (3 + plan.gaps + r);
  const std::size_t flat = std::min(teeth, extra);
  const std::size_t arcs = extra - flat;
  plan.flat = gen::random_flags(teeth, flat, rng);
  plan.arc = gen::balanced_split(arcs, teeth, rng);
  return plan;
}

std::vector<Point> make_comb(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  const Plan plan = plan_comb(n, r, rng);
  const std::size_t max_arc = *std::max_element(plan.arc.begin(), plan.arc.end());
  const std::vector<Vec> reps = gen::shortest_primitive_vectors(
      max_arc / 2, [](std::int64_t a, std::int64_t b) { return a >= 1 && b >= 1; }, rng);
  // Tooth sides must be steeper than every arc step (slopes up to max b, and 1 in the middle).
  std::int64_t steepest_arc = 1;
  for (Vec v : reps) steepest_arc = std::max(steepest_arc, v.y);
  const std::int64_t spine = rng.between(1, 3);
  const std::int64_t tooth = std::max(rng.between(6, 12), steepest_arc + 1);
  const std::int64_t top = spine + tooth;

  // The boundary above the bottom edge, left to right, from the bottom-left corner.
  std::vector<Vec> profile{{0, 0}};
  for (std::size_t t = 0; t <= plan.gaps; ++t) {
    Vec at{profile.back().x + 1, top};
    profile.push_back(at);
    if (plan.flat[t]) {
      const std::int64_t width = gen::convex_arc_min_length(plan.arc[t], reps, 1) + rng.between(0, 2);
      // Turned upside down the arc bulges up and its slopes fall: convex from the inside.
      for (Vec step : gen::convex_arc(plan.arc[t], width, reps, 1)) {
        at = at + Vec{step.x, -step.y};
        profile.push_back(at);
      }
    }
    if (t == plan.gaps) {
      profile.push_back({at.x + 1, 0});
    } else {
      profile.push_back({at.x + 1, spine});
      if (t != plan.v_gap) profile.push_back({at.x + 1 + rng.between(1, 3), spine});
    }
  }
  // Counter-clockwise: along the bottom edge, then back over the teeth.
  std::vector<Vec> vertices{profile.front(), profile.back()};
  vertices.insert(vertices.end(), profile.rbegin() + 1, profile.rend() - 1);
  return gen::centred_points(vertices);
}

}  // namespace

REGISTER_FAMILY({.name = "comb",
                 .shape = "a spine with steep teeth; r counts the corners at the bottoms of the gaps",
                 .min_n = 3,
                 .max_n = gen::kMaxVertices,
                 .r_range = "0 <= r <= 2(n-3)/3",
                 .controls_r = true,
                 .r_infeasible = comb_r_infeasible,
                 .default_reflex = [](std::size_t n) { return n < 4 ? std::size_t{0} : 2 * (n / 4) - 2; },
                 .make = make_comb});

}  // namespace pd
