// Degenerate test polygons on small integer lattices, shared by the tests of the optimal programs and
// of Chazelle-Dobkin's views: collinear vertices, 180-degree vertices, and extensions of edges and
// diagonals that end exactly at vertices are everywhere.
#pragma once

#include "core/polygon.h"

#include <optional>
#include <random>
#include <utility>
#include <vector>

namespace pd::lattice {

// Whether `ring` is a simple polygon as it is: Polygon::make neither refuses it nor drops or merges a
// repeated vertex.
inline bool simple_as_given(const std::vector<Point>& ring) {
  try {
    return Polygon::make(ring).size() == ring.size();
  } catch (const PolygonError&) {
    return false;
  }
}

// A random simple polygon on a small lattice, grown from a triangle by replacing an edge ab with a, c, b
// for a random lattice point c while the result stays simple: collinear vertices, vertices on the
// extensions of edges and diagonals, and 180-degree vertices are everywhere.
inline Polygon lattice_polygon(std::size_t n, int grid, std::mt19937& rng) {
  std::uniform_int_distribution<int> coord(0, grid - 1);
  while (true) {
    std::vector<Point> ring;
    for (int k = 0; k < 3; ++k) ring.emplace_back(coord(rng), coord(rng));
    if (!simple_as_given(ring)) continue;
    for (int attempt = 0; ring.size() < n && attempt < 400; ++attempt) {
      std::vector<Point> grown = ring;
      const auto at = std::uniform_int_distribution<std::size_t>(0, ring.size() - 1)(rng);
      grown.insert(grown.begin() + static_cast<std::ptrdiff_t>(at) + 1, Point(coord(rng), coord(rng)));
      if (simple_as_given(grown)) ring = grown;
    }
    if (ring.size() == n) return Polygon::make(ring);
  }
}

// A rectangle with every lattice point of its boundary as a vertex, a few of them moved off the
// boundary (notches and bumps), and some of the rest dropped: long runs of 180-degree vertices, and
// edge and diagonal extensions that end exactly at vertices.
inline std::optional<Polygon> notched_rectangle(std::mt19937& rng) {
  const int w = 3 + static_cast<int>(rng() % 8), h = 3 + static_cast<int>(rng() % 8);
  std::vector<std::pair<int, int>> ring;
  for (int x = 0; x < w; ++x) ring.emplace_back(x, 0);
  for (int y = 0; y < h; ++y) ring.emplace_back(w, y);
  for (int x = w; x > 0; --x) ring.emplace_back(x, h);
  for (int y = h; y > 0; --y) ring.emplace_back(0, y);
  auto points = [](const std::vector<std::pair<int, int>>& xy) {
    std::vector<Point> out;
    for (auto [x, y] : xy) out.emplace_back(x, y);
    return out;
  };
  for (int k = 1 + static_cast<int>(rng() % 5); k > 0; --k) {
    const auto before = ring;
    auto& v = ring[rng() % ring.size()];
    v.first += static_cast<int>(rng() % 5) - 2;
    v.second += static_cast<int>(rng() % 5) - 2;
    if (!simple_as_given(points(ring))) ring = before;
  }
  std::vector<std::pair<int, int>> kept;
  for (const auto& v : ring)
    if (rng() % 3 != 0) kept.push_back(v);
  if (!simple_as_given(points(kept))) return std::nullopt;
  return Polygon::make(points(kept));
}

}  // namespace pd::lattice
