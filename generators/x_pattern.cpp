// Family `x-pattern`: thin slits in triples whose axes meet in one point (Chazelle's X-patterns),
// the case where Steiner points beat diagonals.
//
// Shape: a slit is a thin triangular notch: two mouth vertices on a side, at +-e (e the side's
// primitive direction) around a point M, and a reflex tip halfway from M to the triple's common point
// G, so the slit's axis M -> tip passes exactly through G.
//   r = 3: the triangle (0, 0), (1536, 0), (768, 1344) with a slit at each side's midpoint aimed at the
//   centroid G = (768, 448) (the slits follow the medians). n = 12.
//   r = 3m, m >= 2: a 64-high strip with m triples along it, centres G_j = (64 + 96j, 32). Triple j
//   has one slit straight across from one long side and two at 45 degrees from the other, mouths 32
//   either side; the side with the single slit alternates. n = 9m + 4.
// Extra vertices bulge the sides between slits (and the strip's ends) outward as convex lattice arcs,
// the template being scaled up until the arcs fit; the seed places the extra vertices.
// Feasible: 12 <= n <= 1,000,000, r = 3m with m >= 1, and n >= 9m + 4 for m >= 2.
// Default r: 3 max(1, (n-4)/9), the most triples that fit.
// Known optimum for r = 3, n = 12: 3 convex pieces with Steiner points (cut each tip to G; every piece
// angle is below 180 degrees, and ceil(r/2) + 1 = 3 is a lower bound), 4 with diagonals only: a single
// diagonal resolves a tip only inside the tip's cone, whose only vertex is the opposite corner, and
// those three diagonals (the medians) cross at G; so at most one tip is resolved by one diagonal, the
// others need two each, at least 3 diagonals, and the 3 diagonals between the tips give 4 convex
// pieces. With m triples, cutting every tip to its G gives 2m + 1 convex pieces.
// Complexity: O(n log n) (the arcs' vectors).
// Why simple: the template is simple (slits are thin, inside their side's half-plane, and apart).
// An arc uses local vectors (a, b), a >= 1, |b| < a/3, summing along its side, so it stays outside the
// template within 18.5 degrees of its side; every convex vertex it starts or ends at turns by more
// than 40 degrees in the template, so it stays convex and the arcs of neighbouring sides stay apart.
// Coordinates: the extra vertices are shared out in proportion to the edges' lengths; the worst case,
// r = 3 at n = 1e6, stays below 3.8e8.
#include "generators/family.h"
#include "generators/lattice.h"

namespace pd {
namespace {

using gen::Vec;

constexpr std::size_t kMaxXVertices = 1'000'000;

std::size_t min_vertices(std::size_t triples) { return triples == 1 ? 12 : 9 * triples + 4; }

std::optional<std::string> x_pattern_r_infeasible(std::size_t n, std::size_t r) {
  if (r == 0 || r % 3 != 0) return "r must be a positive multiple of 3";
  if (n < min_vertices(r / 3)) return "r = 3m needs n >= 9m+4 for m >= 2";
  return std::nullopt;
}

// A slit in the side running along primitive direction e, around M, aimed at G.
void add_slit(gen::Outline& outline, Vec m, Vec e, Vec g) {
  outline.slit(m - e, {(m.x + g.x) / 2, (m.y + g.y) / 2}, m + e);
}

gen::Outline triangle() {
  // 16 times the nearly equilateral (0, 0), (96, 0), (48, 84): the midpoints, the centroid and the
  // points halfway between are lattice points, and at this size each slit (mouth half-width |e| <= 8.1,
  // depth >= 222) opens by at most 2.1 degrees either side of its axis.
  const Vec a{0, 0}, b{1536, 0}, c{768, 1344};
  const Vec g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
  gen::Outline outline;
  const Vec corners[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Vec p = corners[i], q = corners[(i + 1) % 3];
    outline.corner(p);
    add_slit(outline, {(p.x + q.x) / 2, (p.y + q.y) / 2}, gen::primitive_direction(q - p), g);
  }
  return outline;
}

gen::Outline strip(std::size_t triples) {
  // Slits reach halfway to G: depth 16 (16 sqrt 2 at 45 degrees) for a mouth half-width of 1, so each
  // opens by under 4 degrees either side of its axis; a triple spans 64, and triples are 96 apart.
  constexpr std::int64_t kHeight = 64, kReach = 32, kSpacing = 96, kMargin = 64;
  const auto centre = [](std::size_t j) {
    return Vec{kMargin + kSpacing * static_cast<std::int64_t>(j), kHeight / 2};
  };
  const std::int64_t width = centre(triples - 1).x + kMargin;
  // Triple j puts its single slit on the top side when j is even, on the bottom when odd.
  gen::Outline outline;
  outline.corner({0, 0});
  for (std::size_t j = 0; j < triples; ++j) {
    const Vec g = centre(j);
    if (j % 2 == 0) {
      add_slit(outline, {g.x - kReach, 0}, {1, 0}, g);
      add_slit(outline, {g.x + kReach, 0}, {1, 0}, g);
    } else {
      add_slit(outline, {g.x, 0}, {1, 0}, g);
    }
  }
  outline.corner({width, 0});
  outline.corner({width, kHeight});
  for (std::size_t j = triples; j-- > 0;) {
    const Vec g = centre(j);
    if (j % 2 == 0) {
      add_slit(outline, {g.x, kHeight}, {-1, 0}, g);
    } else {
      add_slit(outline, {g.x + kReach, kHeight}, {-1, 0}, g);
      add_slit(outline, {g.x - kReach, kHeight}, {-1, 0}, g);
    }
  }
  outline.corner({0, kHeight});
  return outline;
}

std::vector<Point> make_x_pattern(std::size_t n, std::size_t r, std::uint64_t seed) {
  Rng rng(seed);
  return gen::centred_points(gen::padded_outline(r == 3 ? triangle() : strip(r / 3), n, rng));
}

}  // namespace

REGISTER_FAMILY({.name = "x-pattern",
                 .shape = "thin slits in triples aimed at common points: a slit triangle (r = 3) or a strip of triples",
                 .min_n = 12,
                 .max_n = kMaxXVertices,
                 .r_range = "r = 3m with m >= 1, n >= 9m+4 when m >= 2",
                 .controls_r = true,
                 .r_infeasible = x_pattern_r_infeasible,
                 .default_reflex = [](std::size_t n) { return 3 * std::max<std::size_t>(1, n < 4 ? 0 : (n - 4) / 9); },
                 .make = make_x_pattern});

}  // namespace pd
