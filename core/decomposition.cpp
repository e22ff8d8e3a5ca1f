#include "core/decomposition.h"

#include "core/sort_rows.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace pd {

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Triangulation: return "triangulation";
    case Kind::Partition: return "partition";
    case Kind::Convex: return "convex";
    case Kind::Cut: return "cut";
  }
  return "?";
}

VertexId Decomposition::add_steiner(const QPoint& p, std::int64_t boundary_edge) {
  steiner.push_back({p, boundary_edge});
  return static_cast<VertexId>(steiner.size() - 1);  // offset by n at the caller
}

std::vector<QPoint> exact_points(const Polygon& p, const Decomposition& d) {
  std::vector<QPoint> pts;
  pts.reserve(p.size() + d.steiner.size());
  for (const Point& v : p.vertices()) pts.push_back(to_exact(v));
  for (const SteinerPoint& s : d.steiner) pts.push_back(s.point);
  return pts;
}

namespace {

[[noreturn]] void malformed(const std::string& why) { throw std::invalid_argument(why); }

// The boundary as one cycle of vertex ids per ring, with each Steiner point placed inside the edge it
// names, ordered along that edge.
using Cycles = std::vector<std::vector<VertexId>>;

Cycles boundary_cycles(const Polygon& p, const Decomposition& d, const std::vector<QPoint>* pts) {
  const std::size_t n = p.size();
  std::map<std::size_t, std::vector<VertexId>> on_edge;
  for (std::size_t k = 0; k < d.steiner.size(); ++k) {
    const std::int64_t e = d.steiner[k].boundary_edge;
    if (e == kInterior) continue;
    if (e < 0 || static_cast<std::size_t>(e) >= n)
      malformed("Steiner point " + std::to_string(n + k) + " names boundary edge " + std::to_string(e) +
                ", which does not exist");
    const QPoint &a = (*pts)[e], &b = (*pts)[p.next(e)], &s = (*pts)[n + k];
    if (orient(a, b, s) != 0 || !CGAL::collinear_are_strictly_ordered_along_line(a, s, b))
      malformed("Steiner point " + std::to_string(n + k) + " is not inside boundary edge " +
                std::to_string(e) + "-" + std::to_string(p.next(e)));
    on_edge[e].push_back(static_cast<VertexId>(n + k));
  }
  Cycles cycles(p.ring_count());
  for (std::size_t r = 0; r < p.ring_count(); ++r) {
    std::vector<VertexId>& cycle = cycles[r];
    cycle.reserve(p.ring_end(r) - p.ring_begin(r));
    for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) {
      cycle.push_back(static_cast<VertexId>(i));
      auto it = on_edge.find(i);
      if (it == on_edge.end()) continue;
      const QPoint& a = (*pts)[i];
      std::sort(it->second.begin(), it->second.end(), [&](VertexId s, VertexId t) {
        return CGAL::squared_distance(a, (*pts)[s]) < CGAL::squared_distance(a, (*pts)[t]);
      });
      cycle.insert(cycle.end(), it->second.begin(), it->second.end());
    }
  }
  return cycles;
}

struct HalfEdge {
  VertexId from, to;
};

// Counter-clockwise angular order of directions out of a common centre: first the half-plane
// (upwards, or rightwards along the horizontal), then the turn. Exact.
template <class P>
struct AngularLess {
  const std::vector<P>& pts;
  const P& centre;
  int half(const P& q) const {
    return (q.y() > centre.y() || (q.y() == centre.y() && q.x() > centre.x())) ? 0 : 1;
  }
  bool operator()(VertexId a, VertexId b) const {
    const int ha = half(pts[a]), hb = half(pts[b]);
    if (ha != hb) return ha < hb;
    return orient(centre, pts[a], pts[b]) > 0;
  }
};

// A half-edge's place in a Rotation: 32 bits, half the memory traffic of size_t on 10^6-vertex
// triangulations (sorted_rotation refuses a graph of 2^32 half-edges or more).
using HalfEdgeId = std::uint32_t;

// Each vertex's outgoing half-edges, sorted counter-clockwise (compressed rows), with each
// half-edge's twin.
struct Rotation {
  std::vector<HalfEdgeId> start;  // row of vertex v: [start[v], start[v+1])
  std::vector<VertexId> origin, target;
  std::vector<HalfEdgeId> twin;

  // The face to the left of u->v continues along the half-edge just before v->u in v's
  // counter-clockwise order.
  HalfEdgeId next_in_face(HalfEdgeId h) const {
    const HalfEdgeId back = twin[h];
    const VertexId v = target[h];
    return back == start[v] ? start[v + 1] - 1 : back - 1;
  }
};

// Each vertex's half-edges sorted counter-clockwise, `order(v)` ordering the targets of v's half-edges.
// `edges` holds every edge as a pair of twins (2k, 2k + 1), so a half-edge's twin is found through
// where its partner went: O(E) beyond the sorts of the rows, without searching any row.
template <class Order>
Rotation sorted_rotation(std::size_t m, const std::vector<HalfEdge>& edges, Order order) {
  if (edges.size() >= (std::uint64_t{1} << 32)) malformed("2^32 half-edges or more");
  const auto count = static_cast<HalfEdgeId>(edges.size());
  Rotation rot;
  rot.start.assign(m + 1, 0);
  for (const HalfEdge& h : edges) ++rot.start[h.from + 1];
  std::partial_sum(rot.start.begin(), rot.start.end(), rot.start.begin());
  std::vector<HalfEdgeId> id(count);  // the half-edge (index into edges) at each place
  std::vector<HalfEdgeId> fill(rot.start.begin(), rot.start.end() - 1);
  for (HalfEdgeId h = 0; h < count; ++h) id[fill[edges[h].from]++] = h;
  rot.origin.resize(count);
  rot.target.resize(count);
  for (std::size_t v = 0; v < m; ++v) {
    const auto first = id.begin() + rot.start[v];
    const auto last = id.begin() + rot.start[v + 1];
    const auto targets = order(static_cast<VertexId>(v));
    const auto less = [&](HalfEdgeId a, HalfEdgeId b) { return targets(edges[a].to, edges[b].to); };
    std::sort(first, last, less);
    for (auto it = first; it + 1 < last; ++it)
      if (!less(*it, *(it + 1)))
        malformed("edges " + std::to_string(v) + "-" + std::to_string(edges[*it].to) + " and " + std::to_string(v) +
                  "-" + std::to_string(edges[*(it + 1)].to) + " overlap");
    for (HalfEdgeId k = rot.start[v]; k < rot.start[v + 1]; ++k) {
      rot.origin[k] = static_cast<VertexId>(v);
      rot.target[k] = edges[id[k]].to;
    }
  }
  std::vector<HalfEdgeId> place(count);
  for (HalfEdgeId k = 0; k < count; ++k) place[id[k]] = k;
  rot.twin.resize(count);
  for (HalfEdgeId k = 0; k < count; ++k) rot.twin[k] = place[id[k] ^ 1];
  return rot;
}

// Around each vertex, counter-clockwise by angle: exact, for any plane graph.
template <class P>
auto by_angle(const std::vector<P>& pts) {
  return [&pts](VertexId v) { return AngularLess<P>{pts, pts[v]}; };
}

// Around vertex v of a polygon without holes cut by diagonals, counter-clockwise: the other ends in
// boundary order v+1, v+2, ..., v-1, as diagonals that do not cross must be (Keil-Snoeyink (001),
// Observation 1). No geometry: crossing or overlapping cuts make faces that are not convex or not
// counter-clockwise, which the validator names.
auto in_boundary_order(std::size_t n) {
  return [n](VertexId v) {
    return [n, v](VertexId a, VertexId b) { return (a + n - v) % n < (b + n - v) % n; };
  };
}

// The faces of the plane graph, except those to the left of a ring's first edge walked backwards (the
// outside, and the inside of each hole).
template <class Order>
std::vector<Piece> bounded_faces(std::size_t m, const std::vector<HalfEdge>& edges, const Cycles& rings, Order order) {
  const Rotation rot = sorted_rotation(m, edges, order);
  std::vector<char> used(edges.size(), 0);
  std::vector<Piece> faces;
  Piece face;  // walked here, then copied at its size: one allocation a face
  auto walk = [&](HalfEdgeId s) {
    face.clear();
    for (HalfEdgeId h = s; !used[h]; h = rot.next_in_face(h)) {
      used[h] = 1;
      face.push_back(rot.origin[h]);
    }
    return Piece(face.begin(), face.end());
  };
  for (const std::vector<VertexId>& ring : rings)
    for (HalfEdgeId h = rot.start[ring[1]]; h < rot.start[ring[1] + 1]; ++h)
      if (rot.target[h] == ring[0] && !used[h]) walk(h);
  for (HalfEdgeId s = 0; s < rot.target.size(); ++s)
    if (!used[s]) faces.push_back(walk(s));
  return faces;
}

std::vector<HalfEdge> half_edges(const Decomposition& d, const Cycles& rings, std::size_t m) {
  std::vector<HalfEdge> edges;
  std::vector<std::pair<VertexId, VertexId>> seen;
  edges.reserve(2 * (m + d.cuts.size()));
  seen.reserve(m + d.cuts.size());
  auto add = [&](VertexId a, VertexId b) {  // twins side by side, as sorted_rotation needs them
    edges.push_back({a, b});
    edges.push_back({b, a});
  };
  for (const std::vector<VertexId>& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      add(ring[i], ring[(i + 1) % ring.size()]);
      seen.push_back(std::minmax(ring[i], ring[(i + 1) % ring.size()]));
    }
  for (std::size_t c = 0; c < d.cuts.size(); ++c) {
    const Cut& cut = d.cuts[c];
    if (cut.a >= m || cut.b >= m)
      malformed("cut " + std::to_string(c) + " has an endpoint that is not a vertex");
    if (cut.a == cut.b) malformed("cut " + std::to_string(c) + " joins vertex " + std::to_string(cut.a) + " to itself");
    seen.push_back(std::minmax(cut.a, cut.b));
    add(cut.a, cut.b);
  }
  sort_in_rows(seen, m, [](const std::pair<VertexId, VertexId>& s) { return s.first; });
  const auto dup = std::adjacent_find(seen.begin(), seen.end());
  if (dup != seen.end())
    malformed("segment " + std::to_string(dup->first) + "-" + std::to_string(dup->second) + " appears twice");
  return edges;
}

}  // namespace

std::vector<Piece> pieces_of(const Polygon& p, const Decomposition& d) {
  if (d.pieces) return *d.pieces;
  const std::size_t m = p.size() + d.steiner.size();
  if (d.steiner.empty()) {
    const Cycles rings = boundary_cycles(p, d, nullptr);
    if (p.hole_count() == 0) return bounded_faces(m, half_edges(d, rings, m), rings, in_boundary_order(m));
    return bounded_faces(m, half_edges(d, rings, m), rings, by_angle(p.vertices()));
  }
  const std::vector<QPoint> pts = exact_points(p, d);
  const Cycles rings = boundary_cycles(p, d, &pts);
  return bounded_faces(m, half_edges(d, rings, m), rings, by_angle(pts));
}

}  // namespace pd
