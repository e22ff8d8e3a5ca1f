// geos-cdt on collinear (180-degree) vertices. GEOS's ear clipper can skip flat corners
// (PolygonEarClipper::setSkipFlatCorners), and a triangulation without them is not one of the polygon;
// its constrained Delaunay triangulation keeps them in GEOS 3.11. Pinned here, so that a GEOS that
// drops them shows as a failure, not only as invalid results among the peers'.
#include "core/registry.h"
#include "core/validate.h"
#include "tests/lattice_polygons.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace pd {
namespace {

Validation run_geos_cdt(const Polygon& p) {
  Counters counters;
  const Decomposition d = find_algorithm("geos-cdt")->run(p, counters);
  EXPECT_TRUE(d.steiner.empty());
  EXPECT_EQ(d.pieces->size(), p.size() - 2);
  return validate(p, d, Kind::Triangulation, false);
}

TEST(GeosCdt, KeepsCollinearVerticesAsCorners) {
  const std::vector<std::vector<Point>> rings = {
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}},
      {{0, 0}, {4, 0}, {4, 1}, {3, 1}, {2, 1}, {1, 1}, {1, 2}, {1, 3}, {1, 4}, {0, 4}, {0, 2}},
      {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 1}, {0, 2}, {0, 1}},
  };
  for (const auto& ring : rings) {
    const Validation v = run_geos_cdt(Polygon::make(ring));
    EXPECT_TRUE(v.ok) << v.reason;
  }
}

// Random lattice polygons: collinear vertices, and vertices on the extensions of edges, everywhere.
TEST(GeosCdt, IsValidOnLatticePolygons) {
  std::mt19937 rng(7);
  for (int k = 0; k < 300; ++k) {
    const Polygon p = lattice::lattice_polygon(8 + k % 17, 7, rng);
    const Validation v = run_geos_cdt(p);
    EXPECT_TRUE(v.ok) << "lattice polygon " << k << ": " << v.reason;
  }
}

}  // namespace
}  // namespace pd
