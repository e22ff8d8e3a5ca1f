#include "generators/lattice.h"

namespace pd::gen {

bool angle_less(Vec u, Vec v) {
  // Directions in [0, pi) come first; within a half-turn the cross product orders exactly.
  const auto first_half = [](Vec w) { return w.y > 0 || (w.y == 0 && w.x > 0); };
  if (first_half(u) != first_half(v)) return first_half(u);
  return cross(u, v) > 0;
}

std::vector<char> random_flags(std::size_t size, std::size_t set, Rng& rng) {
  std::vector<char> flags(size, 0);
  std::fill(flags.begin(), flags.begin() + static_cast<std::ptrdiff_t>(set), 1);
  shuffle(flags, rng);
  return flags;
}

std::vector<std::size_t> balanced_split(std::size_t total, std::size_t parts, Rng& rng) {
  const std::vector<char> larger = random_flags(parts, total % parts, rng);
  std::vector<std::size_t> out(parts);
  for (std::size_t i = 0; i < parts; ++i) out[i] = total / parts + static_cast<std::size_t>(larger[i]);
  return out;
}

std::vector<Vec> convex_lattice_polygon(std::size_t n, Rng& rng) {
  std::vector<Vec> edges;
  const bool odd = n % 2 == 1;
  if (odd) edges = {{1, 0}, {0, 1}, {-1, -1}};
  // One representative of each pair {v, -v}: the half-plane a > 0, or a == 0 and b > 0. With the
  // triangle, its directions are taken.
  const auto representative = [odd](std::int64_t a, std::int64_t b) {
    if (a == 0 && b <= 0) return false;
    if (odd && ((a == 1 && b == 0) || (a == 0 && b == 1) || (a == 1 && b == 1))) return false;
    return true;
  };
  for (Vec v : shortest_primitive_vectors((n - edges.size()) / 2, representative, rng)) {
    edges.push_back(v);
    edges.push_back(-v);
  }
  // Distinct directions summing to zero, sorted by angle: the turns are all strictly left.
  std::sort(edges.begin(), edges.end(), angle_less);
  std::vector<Vec> vertices(n);
  for (std::size_t i = 1; i < n; ++i) vertices[i] = vertices[i - 1] + edges[i - 1];
  return vertices;
}

namespace {

// The run m of an arc's middle vectors (m, -1), (m', 1): 1/m must be below every used slope b/a >= 1/a.
std::int64_t arc_middle(std::size_t interior, const std::vector<Vec>& reps, std::int64_t min_middle) {
  std::int64_t middle = min_middle;
  for (std::size_t i = 0; i < interior / 2; ++i) middle = std::max(middle, reps[i].x + 1);
  return middle;
}

}  // namespace

std::int64_t convex_arc_min_length(std::size_t interior, const std::vector<Vec>& reps,
                                   std::int64_t min_middle) {
  std::int64_t length = interior % 2 == 0 ? 1 : 2 * arc_middle(interior, reps, min_middle);
  for (std::size_t i = 0; i < interior / 2; ++i) length += 2 * reps[i].x;
  return length;
}

std::vector<Vec> convex_arc(std::size_t interior, std::int64_t length, const std::vector<Vec>& reps,
                            std::int64_t min_middle) {
  std::vector<Vec> used(reps.begin(), reps.begin() + static_cast<std::ptrdiff_t>(interior / 2));
  std::sort(used.begin(), used.end(), slope_less);
  std::int64_t rest = length;
  for (Vec v : used) rest -= 2 * v.x;

  std::vector<Vec> arc;
  arc.reserve(interior + 1);
  for (auto it = used.rbegin(); it != used.rend(); ++it) arc.push_back({it->x, -it->y});
  if (interior % 2 == 0) {
    arc.push_back({rest, 0});
  } else {
    const std::int64_t middle = arc_middle(interior, reps, min_middle);
    arc.push_back({middle, -1});
    arc.push_back({rest - middle, 1});
  }
  for (Vec v : used) arc.push_back(v);
  return arc;
}

std::vector<Point> centred_points(const std::vector<Vec>& vertices) {
  std::int64_t min_x = vertices[0].x, max_x = min_x, min_y = vertices[0].y, max_y = min_y;
  for (Vec v : vertices) {
    min_x = std::min(min_x, v.x);
    max_x = std::max(max_x, v.x);
    min_y = std::min(min_y, v.y);
    max_y = std::max(max_y, v.y);
  }
  // Floor of the midpoint, so that the centring is the same integer shift everywhere.
  const auto mid = [](std::int64_t lo, std::int64_t hi) {
    const std::int64_t sum = lo + hi;
    return sum >= 0 ? sum / 2 : -((-sum + 1) / 2);
  };
  const Vec centre{mid(min_x, max_x), mid(min_y, max_y)};
  std::vector<Point> points;
  points.reserve(vertices.size());
  for (Vec v : vertices) {
    points.emplace_back(static_cast<double>(v.x - centre.x), static_cast<double>(v.y - centre.y));
  }
  return points;
}

std::vector<Point> points_of(const std::vector<Vec>& vertices) {
  std::vector<Point> points;
  points.reserve(vertices.size());
  for (const Vec& p : vertices) points.emplace_back(static_cast<double>(p.x), static_cast<double>(p.y));
  return points;
}

std::vector<Vec> distinct_random_points(std::size_t n, std::int64_t half_side, Rng& rng) {
  std::vector<Vec> v;
  const auto less = [](Vec a, Vec b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  const auto same = [](Vec a, Vec b) { return a.x == b.x && a.y == b.y; };
  while (v.size() < n) {
    while (v.size() < n) v.push_back({rng.between(-half_side, half_side), rng.between(-half_side, half_side)});
    std::sort(v.begin(), v.end(), less);
    v.erase(std::unique(v.begin(), v.end(), same), v.end());
  }
  shuffle(v, rng);
  return v;
}

bool has_collinear_vertices(const std::vector<Vec>& cycle) {
  const std::size_t n = cycle.size();
  for (std::size_t i = 0; i < n; ++i)
    if (cross(cycle[(i + 1) % n] - cycle[i], cycle[(i + 2) % n] - cycle[(i + 1) % n]) == 0) return true;
  return false;
}

Vec primitive_direction(Vec v) {
  const std::int64_t g = std::gcd(v.x, v.y);
  return {v.x / g, v.y / g};
}

namespace {

constexpr std::int64_t kArcMiddle = 4;  // arc middles (m, +-1) keep |b| < a/3

// Each bulging edge's length in steps of its primitive direction; 0 for the edges that do not bulge.
std::vector<std::int64_t> bulge_steps(const Outline& outline) {
  const std::size_t size = outline.vertices.size();
  std::vector<std::int64_t> steps(size, 0);
  for (std::size_t i = 0; i < size; ++i) {
    const Vec d = outline.vertices[(i + 1) % size] - outline.vertices[i];
    if (outline.bulges[i]) steps[i] = std::gcd(d.x, d.y);
  }
  return steps;
}

// `extra` arc vertices per edge, in proportion to the edges' steps, the remainder to random edges.
std::vector<std::size_t> share_out(const std::vector<std::int64_t>& steps, std::size_t extra, Rng& rng) {
  const std::int64_t total = std::accumulate(steps.begin(), steps.end(), std::int64_t{0});
  std::vector<std::size_t> arc(steps.size(), 0), bulging;
  std::size_t given = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] == 0) continue;
    arc[i] = static_cast<std::size_t>(static_cast<__int128>(extra) * steps[i] / total);
    given += arc[i];
    bulging.push_back(i);
  }
  const std::vector<char> one_more = random_flags(bulging.size(), extra - given, rng);
  for (std::size_t k = 0; k < bulging.size(); ++k) arc[bulging[k]] += static_cast<std::size_t>(one_more[k]);
  return arc;
}

}  // namespace

std::vector<Vec> padded_outline(const Outline& outline, std::size_t n, Rng& rng) {
  const std::size_t size = outline.vertices.size();
  const std::vector<std::int64_t> steps = bulge_steps(outline);
  const std::vector<std::size_t> arc = share_out(steps, n - size, rng);

  const std::size_t most = *std::max_element(arc.begin(), arc.end());
  const std::vector<Vec> reps = shortest_primitive_vectors(
      most / 2, [](std::int64_t a, std::int64_t b) { return b >= 1 && 3 * b < a; }, rng);
  // Scale the outline until every arc fits its edge.
  std::int64_t scale = 1;
  for (std::size_t i = 0; i < size; ++i) {
    if (arc[i] == 0) continue;
    const std::int64_t need = convex_arc_min_length(arc[i], reps, kArcMiddle);
    scale = std::max(scale, (need + steps[i] - 1) / steps[i]);
  }

  std::vector<Vec> vertices;
  vertices.reserve(n);
  for (std::size_t i = 0; i < size; ++i) {
    Vec at = scale * outline.vertices[i];
    vertices.push_back(at);
    if (arc[i] == 0) continue;
    // Local (a, b) is a along the edge plus b along its left normal: negative b bulges outward.
    const Vec along = primitive_direction(outline.vertices[(i + 1) % size] - outline.vertices[i]);
    const Vec left{-along.y, along.x};
    const std::vector<Vec> bulge = convex_arc(arc[i], scale * steps[i], reps, kArcMiddle);
    for (std::size_t k = 0; k + 1 < bulge.size(); ++k) {
      at = at + bulge[k].x * along + bulge[k].y * left;
      vertices.push_back(at);
    }
  }
  return vertices;
}

}  // namespace pd::gen
