// geos-cdt: GEOS's constrained Delaunay triangulation of the polygon (peer).
//
// GEOS 3.11.1 (Debian libgeos-dev), C API GEOSConstrainedDelaunayTriangulation_r (geos_c.h, GEOS >=
// 3.10), one reentrant context per thread. It runs geos::triangulate::polygon::
// ConstrainedDelaunayTriangulator::triangulatePolygon: the polygon normalised (shell clockwise),
// PolygonEarClipper's ear clipping (flat corners kept, so every vertex is a triangle corner), then
// TriDelaunayImprover's Delaunay flips, at most 200 scans over the triangles, after which it stops
// silently: on notch-heavy at n = 10^4 it leaves 1,936 of 9,997 diagonals that its own in-circle test
// would flip, so the result is a triangulation, not always a Delaunay one.
//
// Time O(n^3) worst case; GEOS states no bound, this is from its source. The clipper walks the ring
// round and round and meets an ear within one turn of the m corners left; each convex corner asks a
// packed R-tree of the vertices for those in the ear's bounding box, which is up to m of them (leaves
// keep their removed vertices until all are gone). n ears, O(n) corners each, O(n) per corner; the
// flips add O(n), the adjacency map O(n) expected. The spiral family grows so: 8.1 times the time from
// n = 2000 to 4000, nearly all in the R-tree queries. Orientation is double-double after a
// floating-point filter; the in-circle test is long double without a filter ("not robust", its source
// says). Pre: a simple counter-clockwise polygon (collinear vertices are fine).
//
// GEOS returns coordinates only: each triangle corner is mapped back to the polygon vertex with the
// same coordinates (they are distinct); a corner matching none is reported as a Steiner point, so that
// validation records the result as invalid. Each triangle is made counter-clockwise by reversing its
// cycle; nothing else is changed. The whole call is timed, as for cgal-cdt: building the GEOS polygon,
// the triangulation, reading the triangles out and mapping them back (which a user who needs vertex
// ids pays too; under 4% of the time on random at n = 10^5).
#include "core/registry.h"

#include <geos_c.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pd {
namespace {

// A GEOS context handle and the last error message GEOS reported on it. A context is not thread-safe,
// so each thread has its own.
class GeosContext {
 public:
  GeosContext() : handle_(GEOS_init_r()) {
    GEOSContext_setErrorMessageHandler_r(handle_, &GeosContext::remember, &message_);
  }
  ~GeosContext() { GEOS_finish_r(handle_); }
  GeosContext(const GeosContext&) = delete;
  GeosContext& operator=(const GeosContext&) = delete;

  GEOSContextHandle_t handle() const { return handle_; }
  void forget_message() { message_.clear(); }
  // GEOS signals an error by a NULL return, the reason by the handler.
  [[noreturn]] void fail(const std::string& call) const {
    throw std::runtime_error(call + " failed: " + (message_.empty() ? "GEOS gave no reason" : message_));
  }

 private:
  static void remember(const char* message, void* userdata) {
    *static_cast<std::string*>(userdata) = message;
  }

  GEOSContextHandle_t handle_;
  std::string message_;
};

GeosContext& thread_context() {
  thread_local GeosContext context;
  return context;
}

struct GeometryDeleter {
  GEOSContextHandle_t handle;
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(handle, g); }
};
using Geometry = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

// The polygon as a GEOS polygon: its vertices in order, the ring closed by repeating vertex 0.
Geometry geos_polygon(GeosContext& ctx, const Polygon& p) {
  std::vector<double> xy;
  xy.reserve(2 * (p.size() + 1));
  for (std::size_t i = 0; i <= p.size(); ++i) {
    const Point& v = p[i == p.size() ? 0 : i];
    xy.push_back(v.x());
    xy.push_back(v.y());
  }
  GEOSContextHandle_t h = ctx.handle();
  const auto size = static_cast<unsigned>(p.size() + 1);
  GEOSCoordSequence* seq = GEOSCoordSeq_copyFromBuffer_r(h, xy.data(), size, 0, 0);
  if (!seq) ctx.fail("GEOSCoordSeq_copyFromBuffer_r");
  GEOSGeometry* ring = GEOSGeom_createLinearRing_r(h, seq);  // owns seq from here, also when it fails
  if (!ring) ctx.fail("GEOSGeom_createLinearRing_r");
  GEOSGeometry* polygon = GEOSGeom_createPolygon_r(h, ring, nullptr, 0);  // owns ring, also when it fails
  if (!polygon) ctx.fail("GEOSGeom_createPolygon_r");
  return Geometry(polygon, {h});
}

struct CoordinatesHash {
  std::size_t operator()(const std::pair<double, double>& xy) const {
    const std::size_t hx = std::hash<double>{}(xy.first);
    return hx ^ (std::hash<double>{}(xy.second) + 0x9e3779b97f4a7c15ULL + (hx << 6) + (hx >> 2));
  }
};

// Vertex ids by exact coordinates: the polygon's vertices, then the Steiner points met so far.
class VertexIds {
 public:
  explicit VertexIds(const Polygon& p) : n_(p.size()) {
    ids_.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      ids_.emplace(std::make_pair(p[i].x(), p[i].y()), static_cast<VertexId>(i));
  }

  // The id of the vertex at (x, y); a point that is no polygon vertex becomes a Steiner point of d.
  VertexId at(double x, double y, Decomposition& d) {
    const auto [it, added] = ids_.try_emplace({x, y}, static_cast<VertexId>(n_ + d.steiner.size()));
    if (added) d.add_steiner(QPoint(x, y));
    return it->second;
  }

 private:
  std::size_t n_;
  std::unordered_map<std::pair<double, double>, VertexId, CoordinatesHash> ids_;
};

// One output triangle (any polygon GEOS returns) as a counter-clockwise cycle of vertex ids: its
// exterior ring without the closing repeat, reversed when clockwise.
Piece piece_of(GeosContext& ctx, const GEOSGeometry* triangle, VertexIds& ids, Decomposition& d) {
  GEOSContextHandle_t h = ctx.handle();
  const GEOSGeometry* ring = GEOSGetExteriorRing_r(h, triangle);
  if (!ring) ctx.fail("GEOSGetExteriorRing_r");
  const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(h, ring);
  if (!seq) ctx.fail("GEOSGeom_getCoordSeq_r");
  unsigned size = 0;
  if (!GEOSCoordSeq_getSize_r(h, seq, &size)) ctx.fail("GEOSCoordSeq_getSize_r");
  std::vector<Point> corners;
  Piece piece;
  for (unsigned i = 0; i + 1 < size; ++i) {
    double x = 0, y = 0;
    if (!GEOSCoordSeq_getXY_r(h, seq, i, &x, &y)) ctx.fail("GEOSCoordSeq_getXY_r");
    corners.emplace_back(x, y);
    piece.push_back(ids.at(x, y, d));
  }
  // The filtered exact orientation for a triangle, the exact area only for anything else GEOS returns.
  const bool clockwise = corners.size() == 3 ? orient(corners[0], corners[1], corners[2]) < 0
                                             : twice_signed_area(corners) < 0;
  if (clockwise) std::reverse(piece.begin(), piece.end());
  return piece;
}

Decomposition geos_cdt(const Polygon& p, Counters& counters) {
  GeosContext& ctx = thread_context();
  ctx.forget_message();
  const Geometry polygon = geos_polygon(ctx, p);
  const Geometry triangles(GEOSConstrainedDelaunayTriangulation_r(ctx.handle(), polygon.get()),
                           {ctx.handle()});
  if (!triangles) ctx.fail("GEOSConstrainedDelaunayTriangulation_r");
  const int count = GEOSGetNumGeometries_r(ctx.handle(), triangles.get());
  if (count < 0) ctx.fail("GEOSGetNumGeometries_r");
  VertexIds ids(p);
  Decomposition d;
  d.pieces.emplace();
  d.pieces->reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const GEOSGeometry* triangle = GEOSGetGeometryN_r(ctx.handle(), triangles.get(), i);
    if (!triangle) ctx.fail("GEOSGetGeometryN_r");
    d.pieces->push_back(piece_of(ctx, triangle, ids, d));
  }
  counters["geos_triangles"] = count;
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "geos-cdt", .kind = Kind::Triangulation, .time_bound = "n^3",
                    .pieces_bound = "== n-2",
                    .source = "GEOS 3.11.1 GEOSConstrainedDelaunayTriangulation_r (ear clipping, Delaunay flips)",
                    .peer = "GEOS 3.11.1", .run = geos_cdt});

}  // namespace pd
