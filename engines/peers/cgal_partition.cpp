// The CGAL Partition_2 calls of the peers cgal-optimal, cgal-hertel-mehlhorn, cgal-greene and
// cgal-y-monotone.
//
// CGAL 5.5, Partition_2 (Hert and Schirra): optimal_convex_partition_2 (Greene's O(n^4) dynamic
// program), approx_convex_partition_2 (Hertel-Mehlhorn on a triangulation, <= 4 OPT),
// greene_approx_convex_partition_2 (Greene's O(n log n) approximation, <= 4 OPT) and
// y_monotone_partition_2 (plane sweep, O(n log n)). Pre: a simple counter-clockwise polygon.
//
// Peers keep their own behaviour: the pieces CGAL returns are reported as returned (only collinear
// boundary vertices a piece skips are listed again), valid or not; CGAL's own checks are off
// (CGAL_NDEBUG), as in a user's release build. CGAL 5.5's optimal partition is known to return invalid
// or non-minimal results on some simple polygons, and to depend on the starting vertex (CGAL issue
// 4398).
//
// One deviation, for CGAL 5.5's sweep in y_monotone_partition_2 (which greene_approx_convex_partition_2
// also runs): on some simple polygons with a collinear (180-degree) vertex it looks up an edge that is
// not in its status tree and, with its checks off, dereferences the tree's end: heap corruption and a
// crash (data/fuzz-regressions/fuzz-lattice-cgal-y-monotone-crash.txt, found by fuzz-lattice). So
// cgal-y-monotone and cgal-greene are given the polygon without its collinear vertices, which CGAL's
// index traits allow without copying (they see only the other vertex ids); the dropped vertices come
// back in the pieces like any skipped collinear vertex. cgal-optimal and cgal-hertel-mehlhorn get
// every vertex: a collinear vertex can end a diagonal of theirs.
//
// The four calls share this one translation unit, and each peer's file in algorithms/ registers its
// own: Partition_2 is heavy to compile, and each translation unit that includes it costs the test build
// about half a minute.
#include "engines/peers/cgal_partition.h"

#include "engines/peers/peer_pieces.h"

#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>
#include <CGAL/property_map.h>

#include <iterator>
#include <list>
#include <vector>

namespace pd {
namespace {

using IndexTraits = CGAL::Partition_traits_2<Kernel, CGAL::Pointer_property_map<Point>::type>;
using IndexPolygon = IndexTraits::Polygon_2;

// Which vertices CGAL is given.
enum class Vertices { All, WithoutCollinear };

std::vector<std::size_t> vertex_ids(const Polygon& p, Vertices which) {
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (which == Vertices::All || orient(p[p.prev(i)], p[i], p[p.next(i)]) != 0) ids.push_back(i);
  return ids;
}

template <class PartitionFn>
Decomposition run_partition(const Polygon& p, Counters& counters, Vertices which, PartitionFn partition) {
  std::vector<Point> points = p.vertices();
  const std::vector<std::size_t> ids = vertex_ids(p, which);
  const IndexTraits traits(CGAL::make_property_map(points));
  std::list<IndexPolygon> result;
  partition(ids.begin(), ids.end(), std::back_inserter(result), traits);
  Decomposition d;
  d.pieces.emplace();
  for (const IndexPolygon& poly : result) {
    Piece piece(poly.vertices_begin(), poly.vertices_end());
    d.pieces->push_back(with_collinear_boundary_vertices(p, piece));
  }
  counters["cgal_pieces"] = static_cast<std::int64_t>(result.size());
  return d;
}

}  // namespace

Decomposition cgal_optimal(const Polygon& p, Counters& c) {
  return run_partition(p, c, Vertices::All, [](auto b, auto e, auto out, const auto& t) { CGAL::optimal_convex_partition_2(b, e, out, t); });
}
Decomposition cgal_hertel_mehlhorn(const Polygon& p, Counters& c) {
  return run_partition(p, c, Vertices::All, [](auto b, auto e, auto out, const auto& t) { CGAL::approx_convex_partition_2(b, e, out, t); });
}
Decomposition cgal_greene(const Polygon& p, Counters& c) {
  return run_partition(p, c, Vertices::WithoutCollinear, [](auto b, auto e, auto out, const auto& t) {
    CGAL::greene_approx_convex_partition_2(b, e, out, t);
  });
}
Decomposition cgal_y_monotone(const Polygon& p, Counters& c) {
  return run_partition(p, c, Vertices::WithoutCollinear, [](auto b, auto e, auto out, const auto& t) {
    CGAL::y_monotone_partition_2(b, e, out, t);
  });
}

}  // namespace pd
