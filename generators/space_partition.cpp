// Family `space-partition`: a random polygon by recursive space partitioning, after Auer and Held's
// RPG (T. Auer, M. Held, "Heuristics for the Generation of Random Polygons", CCCG 1996, Sec. 2, "Space
// partitioning").
//
// Shape: n distinct random lattice points of the square [-2^29, 2^29]^2. Two random points s and t
// split the others by the line st; a chain from s to t runs through those on its right, one from t
// back to s through those on its left (so the polygon is counter-clockwise). A chain from a to b through a point set S takes a random
// c of S and a random line through c that crosses the segment ab strictly inside (through
// a + k (b - a) / 2^20, k random in 1 .. 2^20 - 1), and is the chain from a to c through the points of S
// on a's side of that line, then the chain from c to b through those on b's side.
// Feasible: 3 <= n <= 2,000,000; r is an outcome, never chosen.
// Complexity: O(n log n) expected, O(n^2) worst (a quicksort's recursion; kept on an explicit stack).
// A split line through a point of S, or s, t collinear with another point, is drawn again; a polygon
// with a point drawn as c on the line ab, or three consecutive collinear vertices (each with
// probability about n / 2^29), is drawn again whole, from the same generator.
// Why simple: each chain from a to b through S lies in the convex hull of S, a and b; the split line
// leaves a's part and b's part strictly on its two sides, so their hulls meet only at c, and the two
// top-level hulls lie on the two sides of st. By induction the chains meet only at shared ends.
// Coordinates: below 2^29 in magnitude.
#include "generators/family.h"
#include "generators/lattice.h"

#include <algorithm>

namespace pd {
namespace {

using gen::Vec;

constexpr std::int64_t kHalfSide = std::int64_t{1} << 29;
constexpr std::int64_t kSplits = std::int64_t{1} << 20;  // the split point's denominator

// The sign of cross(q - c, p - c) for the split point q = a + k (b - a) / kSplits, scaled by kSplits.
int side_of_split(Vec a, Vec b, std::int64_t k, Vec c, Vec p) {
  const __int128 qx = static_cast<__int128>(kSplits) * (a.x - c.x) + static_cast<__int128>(k) * (b.x - a.x);
  const __int128 qy = static_cast<__int128>(kSplits) * (a.y - c.y) + static_cast<__int128>(k) * (b.y - a.y);
  const __int128 value = qx * (p.y - c.y) - qy * (p.x - c.x);
  return (value > 0) - (value < 0);
}

// One task of the explicit stack: a chain from a to b through the points `inside`, or one vertex.
struct Task {
  Vec a, b;
  std::vector<Vec> inside;
  bool vertex_only;  // emit a
};

// Appends the interior vertices of a chain from a to b through every point of `inside`; false when a
// point drawn as c lies on the line ab (no split line through it separates a from b).
bool append_chain(Vec a, Vec b, std::vector<Vec> inside, Rng& rng, std::vector<Vec>& out) {
  std::vector<Task> stack;
  stack.push_back({a, b, std::move(inside), false});
  while (!stack.empty()) {
    Task t = std::move(stack.back());
    stack.pop_back();
    if (t.vertex_only) {
      out.push_back(t.a);
      continue;
    }
    if (t.inside.empty()) continue;
    const std::size_t pick = rng.below(t.inside.size());
    const Vec c = t.inside[pick];
    if (gen::cross(t.b - t.a, c - t.a) == 0) return false;
    t.inside.erase(t.inside.begin() + static_cast<std::ptrdiff_t>(pick));
    std::vector<Vec> near_a, near_b;
    while (true) {
      const std::int64_t k = rng.between(1, kSplits - 1);
      const int sa = side_of_split(t.a, t.b, k, c, t.a);
      near_a.clear(), near_b.clear();
      bool on_line = false;
      for (const Vec p : t.inside) {
        const int s = side_of_split(t.a, t.b, k, c, p);
        if (s == 0) {
          on_line = true;
          break;
        }
        (s == sa ? near_a : near_b).push_back(p);
      }
      if (!on_line) break;
    }
    // Emitted in order: the chain a..c, then c, then the chain c..b (the stack is last in, first out).
    stack.push_back({c, t.b, std::move(near_b), false});
    stack.push_back({c, c, {}, true});
    stack.push_back({t.a, c, std::move(near_a), false});
  }
  return true;
}

// The polygon, or nothing when a draw met a collinear point on the way.
std::optional<std::vector<Vec>> partition_polygon(std::size_t n, Rng& rng) {
  std::vector<Vec> points = gen::distinct_random_points(n, kHalfSide, rng);
  while (true) {
    const Vec s = points[0], t = points[1];
    std::vector<Vec> left, right;
    bool collinear = false;
    for (std::size_t i = 2; i < n && !collinear; ++i) {
      const __int128 side = gen::cross(t - s, points[i] - s);
      collinear = side == 0;
      (side > 0 ? left : right).push_back(points[i]);
    }
    if (collinear) {
      gen::shuffle(points, rng);
      continue;
    }
    // Counter-clockwise: out through the points right of st, back through those left of it.
    std::vector<Vec> polygon{s};
    if (!append_chain(s, t, std::move(right), rng, polygon)) return std::nullopt;
    polygon.push_back(t);
    if (!append_chain(t, s, std::move(left), rng, polygon)) return std::nullopt;
    return polygon;
  }
}

std::vector<Point> make_space_partition(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::optional<std::vector<Vec>> drawn;
  do drawn = partition_polygon(n, rng);
  while (!drawn || gen::has_collinear_vertices(*drawn));
  return gen::points_of(*drawn);
}

}  // namespace

REGISTER_FAMILY(outcome_family("space-partition",
                               "random points joined by chains in recursively split half-planes (RPG's space partitioning)",
                               3, gen::kMaxVertices, make_space_partition));

}  // namespace pd
