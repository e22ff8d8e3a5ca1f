// Strictly convex lattice holes in the cells of a square grid, shared by the families with holes
// (convex-holes, comb-holes): integer arithmetic driven by pd::Rng, the same bytes on every machine.
#pragma once

#include "core/polygon.h"
#include "generators/lattice.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pd::gen {

struct Box {
  std::int64_t x0, y0, x1, y1;
};

Box box_of(const std::vector<Vec>& v);
void translate(std::vector<Vec>& v, Vec by);

// h strictly convex lattice polygons with r vertices in all (shared out as evenly as the seed allows,
// each at least 3; pre: 3h <= r), counter-clockwise, each with its box's corner at the origin, and the
// side of a square cell that holds any of them with a margin of 1 all round.
struct HoleGrid {
  std::vector<std::vector<Vec>> holes;
  std::int64_t cell = 0;

  HoleGrid(std::size_t r, std::size_t h, Rng& rng);
  std::int64_t cells_per_side() const;  // g = ceil(sqrt(h))
  std::int64_t side() const { return cells_per_side() * cell; }
  // The holes, clockwise, each centred in its own cell of the g x g grid whose lower left corner is
  // `corner`, the cells picked by `rng`: every hole point at least 1 inside the grid's square.
  std::vector<Ring> placed(Vec corner, Rng& rng) const;
};

}  // namespace pd::gen
