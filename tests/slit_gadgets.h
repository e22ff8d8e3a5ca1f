// Hand-made polygons whose optimum needs X4-patterns, for the tests of the Steiner-optimal programs
// and of the independent checker.
#pragma once

#include "core/polygon.h"

#include <utility>
#include <vector>

namespace pd::gadgets {

// m copies of a four-slit gadget side by side in one 80m x 60 rectangle. Each gadget has two slits in
// the bottom edge and two in the top, the left two aimed at (80g - 10, 0), the right two at
// (80g + 10, 0), each range about 10 degrees wide: no diagonal and no single Steiner point resolves two
// of a gadget's tips together, but the X4-pattern through both points resolves all four. The ranges of
// different gadgets point away from each other. m = 1 is the checker's "four slits" (5 pieces with
// diagonals only, 4 with the X4-pattern).
inline Polygon four_slit_gadgets(int m) {
  std::vector<Point> v;
  v.emplace_back(-40, -30);
  for (int g = 0; g < m; ++g) {
    const double x = 80.0 * g;
    for (auto [dx, dy] : {std::pair{-21, -30}, {-16, -18}, {-19, -30}, {19, -30}, {16, -18}, {21, -30}}) v.emplace_back(x + dx, dy);
  }
  v.emplace_back(80.0 * m - 40, -30);
  v.emplace_back(80.0 * m - 40, 30);
  for (int g = m; g-- > 0;) {
    const double x = 80.0 * g;
    for (auto [dx, dy] : {std::pair{21, 30}, {16, 18}, {19, 30}, {-19, 30}, {-16, 18}, {-21, 30}}) v.emplace_back(x + dx, dy);
  }
  v.emplace_back(-40, 30);
  return Polygon::make(v);
}

}  // namespace pd::gadgets
