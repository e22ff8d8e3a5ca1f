// libFuzzer target for every registered algorithm on degenerate polygons, which text mutation rarely
// reaches: each input byte is a point of the 16 x 16 lattice (high and low nibble), the points are
// joined in angular order about their centroid (a star-shaped ring, so usually simple, with runs of
// collinear vertices and near-touching edges), and the first byte picks a placement: as is, or scaled
// and moved towards 2^31, where differences of coordinates lose bits in floating point. Accepted
// polygons go through the same checks as fuzz-run (tests/reliability.h); a finding aborts.
#include "tests/reliability.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

// (scale, offset) of each placement.
constexpr double kPlacements[][2] = {{1, 0}, {1, 2147483000.0}, {134217728.0, 0}, {-134217727.0, 0}, {1024, -2147483648.0}};

std::vector<pd::Point> star_ring(const std::uint8_t* data, std::size_t size) {
  std::vector<std::pair<int, int>> lattice;
  for (std::size_t i = 1; i < size; ++i) lattice.emplace_back(data[i] >> 4, data[i] & 15);
  std::sort(lattice.begin(), lattice.end());
  lattice.erase(std::unique(lattice.begin(), lattice.end()), lattice.end());
  double cx = 0, cy = 0;
  for (const auto& [x, y] : lattice) cx += x, cy += y;
  cx /= static_cast<double>(lattice.size()), cy /= static_cast<double>(lattice.size());
  std::stable_sort(lattice.begin(), lattice.end(), [&](const auto& a, const auto& b) {
    return std::atan2(a.second - cy, a.first - cx) < std::atan2(b.second - cy, b.first - cx);
  });
  const auto& [scale, offset] = kPlacements[data[0] % std::size(kPlacements)];
  std::vector<pd::Point> ring;
  for (const auto& [x, y] : lattice) ring.emplace_back(x * scale + offset, y * scale + offset);
  return ring;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pd::reliability;
  if (size < 4 || size > kFuzzMaxVertices + 1) return 0;
  std::optional<pd::Polygon> polygon;
  try {
    polygon = pd::Polygon::make(star_ring(data, size));
  } catch (const pd::PolygonError&) {
    return 0;
  }
  if (const auto finding = first_finding(run_every_algorithm(*polygon, kFuzzWork))) {
    std::fprintf(stderr, "finding: %s\n", finding->c_str());
    std::abort();
  }
  return 0;
}
