// Family `notch-heavy`: a triangle whose three sides cave in, so nearly every vertex is reflex.
//
// Shape: the triangle (0, 0), (S, 0), (0, S) with each side replaced by a concave lattice chain (every
// vertex reflex); its three corners are the only convex vertices when r = n-3. For smaller r, "dents"
// are added in the middle of the sides: a down-then-up pair of edges, one convex and one reflex vertex.
// Feasible: 3 <= n <= 2,000,000, (n-2)/2 <= r <= n-3 (integer division; that is r >= n-3-r, since each
// of the n-3-r dents brings a reflex vertex with its convex one).
// Default r = n-3.
// Complexity: O(n log n) (the chains' vectors).
// Why simple: side i is drawn in a frame (u_i, v_i) (u along the side, v inward, positive
// determinant) from local vectors (a, b) with a >= 1 and |b| < a/3 whose b sum to zero, so in local
// coordinates the chain is x-monotone and stays in the double cone |y| < min(x, S-x)/3 over its side.
// The three cones meet only at the corners, and at each corner |b| < a/3 on both sides keeps the
// turn strictly left (the cross product of the two edges exceeds a a'/3 > 0). Inside a side the slopes
// fall at every junction except in a dent's middle, and the dents sit where the slopes change sign, so
// each junction turns as intended.
// Coordinates: the reflex vertices are split evenly over the sides; at n = 2e6, r = n-3 they stay below
// 4.1e8.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

// Reps for the chains: primitive (a, b) with b >= 1 and 3b < a. Dents are drawn from the first few.
constexpr std::size_t kDentChoices = 8;

std::size_t min_reflex(std::size_t n) { return (n - 2) / 2; }

std::optional<std::string> notch_heavy_r_infeasible(std::size_t n, std::size_t r) {
  if (r > n - 3) return "r must be at most n-3 = " + std::to_string(n - 3);
  if (r < min_reflex(n)) return "r must be at least (n-2)/2 = " + std::to_string(min_reflex(n));
  return std::nullopt;
}

struct Side {
  Vec along;               // u: from one corner towards the next
  Vec inward;              // v: positive determinant with u
  std::size_t concave;     // reflex vertices of the concave chain
  std::vector<Vec> dents;  // each contributes a convex and a reflex vertex
};

// The minimum span of a side: its arc's minimum plus its dents.
std::int64_t min_span(const Side& side, const std::vector<Vec>& reps, std::int64_t min_middle) {
  std::int64_t span = gen::convex_arc_min_length(side.concave, reps, min_middle);
  for (Vec d : side.dents) span += 2 * d.x;
  return span;
}

// A side's local steps (a, b): a convex arc turned over (b negated) is concave; its first concave/2
// steps climb, then the slopes change sign, which is where the dents go.
std::vector<Vec> side_steps(const Side& side, std::int64_t span, const std::vector<Vec>& reps,
                            std::int64_t min_middle) {
  std::int64_t arc_length = span;
  for (Vec d : side.dents) arc_length -= 2 * d.x;
  const std::vector<Vec> arc = gen::convex_arc(side.concave, arc_length, reps, min_middle);
  std::vector<Vec> steps;
  for (std::size_t i = 0; i < arc.size(); ++i) {
    if (i == side.concave / 2) {
      for (Vec d : side.dents) {
        steps.push_back({d.x, -d.y});
        steps.push_back(d);
      }
    }
    steps.push_back({arc[i].x, -arc[i].y});
  }
  return steps;
}

std::vector<Point> make_notch_heavy(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  const std::size_t dents = n - 3 - r;
  const std::vector<std::size_t> concave = gen::balanced_split(r - dents, 3, rng);
  const std::vector<std::size_t> dent_split = gen::balanced_split(dents, 3, rng);
  const std::size_t most_pairs =
      std::max(kDentChoices, *std::max_element(concave.begin(), concave.end()) / 2);
  const std::vector<Vec> reps = gen::shortest_primitive_vectors(
      most_pairs, [](std::int64_t a, std::int64_t b) { return b >= 1 && 3 * b < a; }, rng);
  // The arcs' near-flat middles must be shallower than any dent (slope >= 1/a for a dent (a, b)).
  std::int64_t min_middle = 0;
  for (std::size_t i = 0; i < kDentChoices; ++i) min_middle = std::max(min_middle, reps[i].x + 1);

  const Vec frames[3][2] = {{{1, 0}, {0, 1}}, {{-1, 1}, {-1, 0}}, {{0, -1}, {1, 0}}};
  std::vector<Side> sides;
  for (std::size_t s = 0; s < 3; ++s) {
    sides.push_back({frames[s][0], frames[s][1], concave[s], {}});
    for (std::size_t d = 0; d < dent_split[s]; ++d) sides[s].dents.push_back(reps[rng.below(kDentChoices)]);
  }
  // Every side spans the same S: the longest minimum, the others' middles absorbing the rest.
  std::int64_t span = 0;
  for (const Side& side : sides) span = std::max(span, min_span(side, reps, min_middle));

  std::vector<Vec> vertices;
  vertices.reserve(n);
  Vec at{0, 0};
  for (const Side& side : sides) {
    vertices.push_back(at);
    const std::vector<Vec> steps = side_steps(side, span, reps, min_middle);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      at = at + steps[i].x * side.along + steps[i].y * side.inward;
      if (i + 1 < steps.size()) vertices.push_back(at);
    }
  }
  return gen::centred_points(vertices);
}

}  // namespace

REGISTER_FAMILY({.name = "notch-heavy",
                 .shape = "a triangle with caved-in sides: up to n-3 reflex vertices, dents add convex ones",
                 .min_n = 3,
                 .max_n = gen::kMaxVertices,
                 .r_range = "(n-2)/2 <= r <= n-3",
                 .controls_r = true,
                 .r_infeasible = notch_heavy_r_infeasible,
                 .default_reflex = [](std::size_t n) { return n < 3 ? std::size_t{0} : n - 3; },
                 .make = make_notch_heavy});

}  // namespace pd
