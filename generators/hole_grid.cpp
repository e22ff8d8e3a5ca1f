// Convex lattice holes in a grid: see hole_grid.h.
#include "generators/hole_grid.h"

namespace pd::gen {

Box box_of(const std::vector<Vec>& v) {
  Box b{v[0].x, v[0].y, v[0].x, v[0].y};
  for (const Vec& p : v) b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  return b;
}

void translate(std::vector<Vec>& v, Vec by) {
  for (Vec& p : v) p = p + by;
}

HoleGrid::HoleGrid(std::size_t r, std::size_t h, Rng& rng) {
  for (const std::size_t k : balanced_split(r, h, rng)) {
    holes.push_back(convex_lattice_polygon(k, rng));
    const Box b = box_of(holes.back());
    translate(holes.back(), {-b.x0, -b.y0});
    cell = std::max({cell, b.x1 - b.x0 + 2, b.y1 - b.y0 + 2});
  }
}

std::int64_t HoleGrid::cells_per_side() const {
  std::int64_t g = 1;
  while (static_cast<std::size_t>(g * g) < holes.size()) ++g;
  return g;
}

std::vector<Ring> HoleGrid::placed(Vec corner, Rng& rng) const {
  const std::int64_t g = cells_per_side();
  std::vector<std::size_t> cells(static_cast<std::size_t>(g * g));
  std::iota(cells.begin(), cells.end(), 0);
  shuffle(cells, rng);
  std::vector<Ring> rings;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const std::int64_t cx = static_cast<std::int64_t>(cells[i]) % g, cy = static_cast<std::int64_t>(cells[i]) / g;
    std::vector<Vec> hole = holes[i];
    const Box b = box_of(hole);
    translate(hole, {corner.x + cx * cell + (cell - b.x1) / 2, corner.y + cy * cell + (cell - b.y1) / 2});
    std::reverse(hole.begin(), hole.end());
    rings.push_back(points_of(hole));
  }
  return rings;
}

}  // namespace pd::gen
