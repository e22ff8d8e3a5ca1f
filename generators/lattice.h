// Lattice building blocks shared by the polygon families: integer vectors, the shortest primitive
// vectors of a region, exact angle order, seeded shuffles and subsets, strictly convex lattice
// polygons and convex arcs of lattice vectors.
//
// Everything here is integer arithmetic driven by pd::Rng, so the families built on it give the same
// polygon on every machine.
#pragma once

#include "core/geometry.h"
#include "generators/rng.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace pd::gen {

// The largest n any family makes. Each family's coordinate bound was checked at this n for its most
// expensive r; the families' infeasible() refuse larger n.
constexpr std::size_t kMaxVertices = 2'000'000;

// A lattice point or vector.
struct Vec {
  std::int64_t x = 0;
  std::int64_t y = 0;
};

inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
inline Vec operator-(Vec a) { return {-a.x, -a.y}; }
inline Vec operator*(std::int64_t k, Vec a) { return {k * a.x, k * a.y}; }

inline __int128 cross(Vec a, Vec b) {
  return static_cast<__int128>(a.x) * b.y - static_cast<__int128>(a.y) * b.x;
}
inline __int128 dot(Vec a, Vec b) {
  return static_cast<__int128>(a.x) * b.x + static_cast<__int128>(a.y) * b.y;
}

// Whether u comes before v counter-clockwise from direction (1, 0) (which comes first).
bool angle_less(Vec u, Vec v);

// Whether u's slope is below v's; both point right (x > 0).
inline bool slope_less(Vec u, Vec v) { return cross(u, v) > 0; }

// The `count` shortest primitive vectors (a, b) (gcd 1) with a >= 0 and in_region(a, b), ties in length
// broken by `rng`. The region must hold at least `count` primitive vectors.
template <class InRegion>
std::vector<Vec> shortest_primitive_vectors(std::size_t count, InRegion in_region, Rng& rng) {
  struct Candidate {
    std::int64_t norm;
    std::uint64_t tie;
    Vec v;
  };
  if (count == 0) return {};
  // A disc of radius R holds about 1.9 R^2 primitive vectors; start a little below the need for a
  // half-plane and grow by 5/4, so the last, successful pass does most of the work.
  std::int64_t radius = 2;
  while (radius * radius < static_cast<std::int64_t>(count)) ++radius;
  for (;; radius += radius / 4 + 1) {
    std::vector<Candidate> found;
    const std::int64_t r2 = radius * radius;
    for (std::int64_t a = 0; a <= radius; ++a) {
      for (std::int64_t b = -radius; b <= radius; ++b) {
        const std::int64_t norm = a * a + b * b;
        if (norm <= r2 && in_region(a, b) && std::gcd(a, b) == 1) found.push_back({norm, rng.next(), {a, b}});
      }
    }
    if (found.size() < count) continue;
    std::sort(found.begin(), found.end(), [](const Candidate& p, const Candidate& q) {
      return p.norm != q.norm ? p.norm < q.norm : p.tie < q.tie;
    });
    std::vector<Vec> out(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = found[i].v;
    return out;
  }
}

// Fisher-Yates with the project's generator.
template <class T>
void shuffle(std::vector<T>& items, Rng& rng) {
  for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[rng.below(i)]);
}

// `size` flags of which exactly `set` are 1, at uniformly random positions.
std::vector<char> random_flags(std::size_t size, std::size_t set, Rng& rng);

// `total` split into `parts` summands that differ by at most 1, the larger ones at random places.
std::vector<std::size_t> balanced_split(std::size_t total, std::size_t parts, Rng& rng);

// The vertices (counter-clockwise, from (0, 0)) of a strictly convex lattice polygon with n >= 3
// vertices whose edges are the shortest primitive vectors: pairs {v, -v}, plus the triangle
// (1, 0), (0, 1), (-1, -1) when n is odd. For n >= 4 every turn is at most 90 degrees.
std::vector<Vec> convex_lattice_polygon(std::size_t n, Rng& rng);

// A convex arc with `interior` vertices over a chord of `length`: edge vectors (a, b), a >= 1, in a
// local frame whose x-axis is the chord, with strictly increasing slopes (every vertex turns left) and
// b summing to 0, so the arc leaves the chord's start and rejoins its end, bulging to its right
// (negative b first). `reps` are primitive (a, b) with b >= 1, shortest first; the arc uses the first
// interior/2 of them, each as (a, -b) and (a, b). Between the halves goes one flat vector when
// interior is even, else (m, -1), (m', 1) with m' >= m, m >= min_middle and beyond
// every used a, so that 1/m is below every used slope. The middle's free length absorbs the chord,
// which must be at least convex_arc_min_length(...). Every |slope| is at most the larger of 1/min_middle
// and the used reps' largest b/a.
std::int64_t convex_arc_min_length(std::size_t interior, const std::vector<Vec>& reps,
                                   std::int64_t min_middle);
std::vector<Vec> convex_arc(std::size_t interior, std::int64_t length, const std::vector<Vec>& reps,
                            std::int64_t min_middle);

// Points for the vertices, translated so that the bounding box is centred on the origin.
std::vector<Point> centred_points(const std::vector<Vec>& vertices);

// Points for the vertices, as they are.
std::vector<Point> points_of(const std::vector<Vec>& vertices);

// n distinct lattice points drawn uniformly from the square [-half_side, half_side]^2, in random order.
std::vector<Vec> distinct_random_points(std::size_t n, std::int64_t half_side, Rng& rng);

// Whether some three consecutive vertices of the cycle are collinear.
bool has_collinear_vertices(const std::vector<Vec>& cycle);

// A polygon template, counter-clockwise, whose chosen edges may bulge outward as convex arcs to take
// extra vertices (x-pattern, x2-pairs). bulges[i] says whether edge i -> i+1 may bulge.
struct Outline {
  std::vector<Vec> vertices;
  std::vector<char> bulges;

  void corner(Vec v) {
    vertices.push_back(v);
    bulges.push_back(1);
  }
  // A thin notch: mouth_start, the reflex tip, mouth_end; only the edge leaving the mouth may bulge.
  void slit(Vec mouth_start, Vec tip, Vec mouth_end) {
    vertices.insert(vertices.end(), {mouth_start, tip, mouth_end});
    bulges.insert(bulges.end(), {0, 0, 1});
  }
};

// The primitive lattice vector along v (v divided by the gcd of its coordinates).
Vec primitive_direction(Vec v);

// The outline with n - outline.vertices.size() extra vertices shared out among the bulging edges in
// proportion to their lengths (the remainder to random ones), each edge's share as a convex arc bulging
// outward within 18.5 degrees of the edge (local vectors (a, b) with |b| < a/3, arc middles (m, +-1),
// m >= 4), the outline scaled up by the least integer that lets every arc fit its edge. Every vertex
// where an arc starts or ends must turn left by more than 37 degrees in the outline, so that it stays
// convex. The extra vertices are placed by `rng`.
std::vector<Vec> padded_outline(const Outline& outline, std::size_t n, Rng& rng);

}  // namespace pd::gen
