// Exhaustive search over sets of non-crossing diagonals, for small polygons (n <= 12): the judge of the
// optimal convex decomposition programs. It shares no code with them: diagonals are tested against
// every edge and vertex (O(n) each), sets are enumerated by backtracking, and each set's pieces are
// found by walking faces and tested for convexity (180-degree vertices allowed).
#pragma once

#include "core/polygon.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace pd::brute {

struct Diagonal {
  std::uint32_t a, b;  // a < b
};

// Whether segment p_a p_b lies strictly inside p apart from its endpoints (no vertex on it).
inline bool is_diagonal(const Polygon& p, std::size_t a, std::size_t b) {
  const std::size_t n = p.size();
  if (a == b || p.next(a) == b || p.prev(a) == b) return false;
  for (std::size_t v = 0; v < n; ++v) {
    if (v == a || v == b) continue;
    if (orient(p[a], p[b], p[v]) == 0 && CGAL::collinear_are_strictly_ordered_along_line(p[a], p[v], p[b]))
      return false;
  }
  for (std::size_t e = 0; e < n; ++e) {
    const std::size_t f = p.next(e);
    if (e == a || e == b || f == a || f == b) continue;
    const int s1 = orient(p[a], p[b], p[e]), s2 = orient(p[a], p[b], p[f]);
    const int s3 = orient(p[e], p[f], p[a]), s4 = orient(p[e], p[f], p[b]);
    if (s1 * s2 <= 0 && s3 * s4 <= 0 && !(s1 == 0 && s2 == 0)) return false;
  }
  // Inside near both ends: strictly left of one of the two edges at a reflex or flat vertex, of both
  // at a convex one.
  auto inside_at = [&](std::size_t v, std::size_t w) {
    const int ahead = orient(p[v], p[p.next(v)], p[w]), behind = orient(p[p.prev(v)], p[v], p[w]);
    if (orient(p[p.prev(v)], p[v], p[p.next(v)]) > 0) return ahead > 0 && behind > 0;
    return ahead > 0 || behind > 0;
  };
  return inside_at(a, b) && inside_at(b, a);
}

inline std::vector<Diagonal> all_diagonals(const Polygon& p) {
  std::vector<Diagonal> out;
  for (std::uint32_t a = 0; a < p.size(); ++a)
    for (std::uint32_t b = a + 1; b < p.size(); ++b)
      if (is_diagonal(p, a, b)) out.push_back({a, b});
  return out;
}

// Two diagonals of a simple polygon cross exactly when their endpoints interleave round the boundary.
inline bool cross(const Diagonal& x, const Diagonal& y) {
  auto strictly_between = [](std::uint32_t lo, std::uint32_t v, std::uint32_t hi) { return lo < v && v < hi; };
  if (x.a == y.a || x.a == y.b || x.b == y.a || x.b == y.b) return false;
  return strictly_between(x.a, y.a, x.b) != strictly_between(x.a, y.b, x.b);
}

// The faces of p cut by `set`, each a counter-clockwise cycle of vertex indices. Around a vertex the
// edges and diagonals are in the order of their other ends counted from v + 1 (Keil & Snoeyink's
// Observation 1, a property of simple polygons rather than of any algorithm here).
inline std::vector<std::vector<std::uint32_t>> faces(const Polygon& p, const std::vector<Diagonal>& set) {
  const std::uint32_t n = static_cast<std::uint32_t>(p.size());
  std::vector<std::vector<std::uint32_t>> around(n);
  for (std::uint32_t v = 0; v < n; ++v) around[v] = {(v + 1) % n, (v + n - 1) % n};
  for (const Diagonal& d : set) around[d.a].push_back(d.b), around[d.b].push_back(d.a);
  for (std::uint32_t v = 0; v < n; ++v)
    std::sort(around[v].begin(), around[v].end(), [&](std::uint32_t x, std::uint32_t y) {
      return (x + n - v) % n < (y + n - v) % n;
    });
  // The face left of u -> v continues with v -> w, w just before u in v's counter-clockwise order.
  auto turn = [&](std::uint32_t u, std::uint32_t v) {
    const auto& row = around[v];
    const std::size_t at = std::find(row.begin(), row.end(), u) - row.begin();
    return row[at - 1];
  };
  std::vector<std::vector<std::uint32_t>> out;
  std::vector<std::vector<char>> used(n);
  for (std::uint32_t v = 0; v < n; ++v) used[v].assign(around[v].size(), 0);
  for (std::uint32_t v = 0; v < n; ++v)
    for (std::size_t h = 0; h + 1 < around[v].size(); ++h) {
      if (used[v][h]) continue;
      std::vector<std::uint32_t> face;
      std::uint32_t u = v, w = around[v][h];
      while (true) {
        const std::size_t at = std::find(around[u].begin(), around[u].end(), w) - around[u].begin();
        if (used[u][at]) break;
        used[u][at] = 1;
        face.push_back(u);
        const std::uint32_t x = turn(u, w);
        u = w, w = x;
      }
      out.push_back(face);
    }
  return out;
}

inline bool convex_face(const Polygon& p, const std::vector<std::uint32_t>& face) {
  for (std::size_t i = 0; i < face.size(); ++i) {
    const std::uint32_t a = face[(i + face.size() - 1) % face.size()], b = face[i], c = face[(i + 1) % face.size()];
    if (orient(p[a], p[b], p[c]) < 0) return false;
  }
  return true;
}

// Calls `visit` with every set of pairwise non-crossing diagonals of at most `max_size` diagonals whose
// faces are all convex.
inline void each_convex_decomposition(const Polygon& p, std::size_t max_size,
                                      const std::function<void(const std::vector<Diagonal>&)>& visit) {
  const std::vector<Diagonal> diagonals = all_diagonals(p);
  std::vector<Diagonal> set;
  std::function<void(std::size_t)> grow = [&](std::size_t from) {
    bool convex = true;
    for (const auto& f : faces(p, set)) convex = convex && convex_face(p, f);
    if (convex) visit(set);
    if (set.size() == max_size) return;
    for (std::size_t d = from; d < diagonals.size(); ++d) {
      bool free = true;
      for (const Diagonal& x : set) free = free && !cross(x, diagonals[d]);
      if (!free) continue;
      set.push_back(diagonals[d]);
      grow(d + 1);
      set.pop_back();
    }
  };
  grow(0);
}

// The fewest convex pieces of p cut by diagonals.
inline std::size_t min_convex_pieces(const Polygon& p) {
  std::size_t best = p.size();
  for (std::size_t k = 0; best == p.size(); ++k)
    each_convex_decomposition(p, k, [&](const std::vector<Diagonal>& set) { best = std::min(best, set.size() + 1); });
  return best;
}

}  // namespace pd::brute
