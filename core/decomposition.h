// What an algorithm returns: the cut graph, not a copy of the pieces.
//
// Vertex ids: 0..n-1 are the polygon's vertices in counter-clockwise order (Polygon indices);
// n + k is Steiner point k. A cut is a segment between two vertex ids whose interior contains no other
// vertex of the decomposition (an algorithm splits its own segments at T-junctions). A Steiner point on
// the polygon's boundary names the boundary edge (i, i+1) it lies on. A triangulation is n-3 cuts; a
// diagonal-only convex decomposition into k pieces is k-1 cuts.
//
// Peers (CGAL) return pieces, not cuts: they set `pieces` directly, so that what they return is
// reported and validated as returned.
#pragma once

#include "core/geometry.h"
#include "core/polygon.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pd {

// What an algorithm makes: the validator checks its pieces against the kind.
enum class Kind { Triangulation, Partition, Convex, Cut };
const char* kind_name(Kind k);

// An algorithm's own operation counts. Algorithms count in local integers inside hot loops and store
// the totals here once, at the end.
using Counters = std::map<std::string, std::int64_t>;

using VertexId = std::uint32_t;
constexpr std::int64_t kInterior = -1;

struct SteinerPoint {
  QPoint point;
  std::int64_t boundary_edge = kInterior;  // i when the point lies inside edge (i, i+1); else kInterior
};

struct Cut {
  VertexId a, b;
};

using Piece = std::vector<VertexId>;  // a counter-clockwise cycle of vertex ids

struct Decomposition {
  std::vector<SteinerPoint> steiner;
  std::vector<Cut> cuts;
  std::optional<std::vector<Piece>> pieces;  // set by peers only
  std::optional<double> own_seconds;         // set by external algorithms: their own timing of the call

  VertexId add_steiner(const QPoint& p, std::int64_t boundary_edge = kInterior);
  void add_cut(std::size_t a, std::size_t b) {
    cuts.push_back({static_cast<VertexId>(a), static_cast<VertexId>(b)});
  }
};

// All vertex positions of a decomposition, exact: the polygon's vertices, then the Steiner points.
std::vector<QPoint> exact_points(const Polygon& p, const Decomposition& d);

// The pieces (bounded faces) of the polygon cut by d.cuts, each a counter-clockwise cycle listing every
// decomposition vertex on its boundary. Returns d.pieces as they are when a peer set them. Untimed: the
// one shared routine for output, SVG and validation. Throws std::invalid_argument with a reason when
// the cuts do not form a graph it can take (ids out of range, a cut from a vertex to itself, a
// repeated cut, a Steiner point on no edge it names, two edges overlapping at a vertex). Without
// Steiner points and holes the faces are found from the vertex order alone (diagonals inside a polygon
// that do not cross leave each vertex in boundary order), so cuts that cross or leave the polygon give
// faces that are clockwise or not convex, which the validator names; otherwise the edges at each
// vertex are sorted by angle, exactly.
std::vector<Piece> pieces_of(const Polygon& p, const Decomposition& d);

}  // namespace pd
