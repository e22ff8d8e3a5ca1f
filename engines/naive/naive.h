// Chazelle's naive convex decomposition (thesis 000, Sec. 2.2.1), shared by `naive`, `naive-chains`
// and the last step of Chazelle-Dobkin (STEP 5, Sec. 2.3.6.6: "finish the decomposition using the naive
// algorithm, adding one polygon for each remaining notch").
//
// Each notch v in turn is resolved by one segment from v, inside its range, up to the first point
// where it meets the boundary of P or an earlier segment; that point is never a vertex of the graph G
// built so far (thesis: "we can always manage not to hit any line at either of its endpoints"). So
// every segment adds one piece, every vertex of G has degree 2 or 3, and P with r notches ends in
// exactly r + 1 convex pieces (Theorem 1).
//
// The direction: the extension of the notch's incoming edge (prev(v), v), a boundary direction of the
// range, chosen over the thesis's bisector because it is given by two input points, so that every
// test against the polygon's vertices is an exact predicate on doubles. When the extension's first
// contact with G is a vertex, or passes through vertices before its first crossing, the segment is
// turned into the range by the repair of Figure 2.5-b (see naive.cpp), by an angle atan(2^-k). Steiner
// points are exact rationals, each where two lines given by input points (and such k) meet, so their
// bit length does not grow along chains of segments ending on earlier segments.
#pragma once

#include "core/decomposition.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pd {

// The naive decomposition of p: one segment per notch, in index order; exactly r + 1 convex pieces.
// Every polygon edge is tested against every segment's ray: O(n r) time, O(n) space.
Decomposition naive_decomposition(const Polygon& p, Counters& counters);

// Resolves each of `notches` (in that order) in the decomposition `d`, whose existing cuts and Steiner
// points count as lines of G, and returns d with the new segments; the cuts d had are split where new
// segments end on them. Each listed notch gains one segment, hence one piece.
// Pre: every listed vertex is reflex in p and has no cut at it; every other vertex of d (polygon
// vertices, Steiner points, vertices of the existing cuts) has an angle of at most 180 degrees in each
// face of d it bounds. In short: d is a partial convex decomposition whose only reflex corners are
// the listed notches, as after Chazelle-Dobkin's patterns.
Decomposition naive_complete(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                             Counters& counters);

// naive_complete with the boundary searched through its convex chains (naive_chains.cpp, Theorem 4):
// O(n) to cut the boundary into chains, then O(r log(n/r)) per listed notch against the boundary
// and O(k) against the k segments of d and of the notches resolved before it. The same decomposition.
// Counts "pseudo_notches", "chain_searches" and "binary_search_steps" in place of "edge_tests".
Decomposition naive_complete_chains(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                                    Counters& counters);

// The graph representation of a decomposition (thesis, "How do we represent a convex
// decomposition?"): adjacency lists of the plane graph of P's boundary and the cuts, every vertex of
// degree 2 or 3 (fact 2 of Sec. 2.2.1), each list in counter-clockwise order.
struct NaiveGraph {
  std::vector<std::array<VertexId, 3>> adjacent;
  std::vector<std::uint8_t> degree;
};

// Lays out a naive decomposition as its graph representation. O(n + k log k) for k Steiner points (they
// are sorted along the edges they lie on). Throws std::invalid_argument when a vertex would have
// degree above 3.
NaiveGraph naive_graph(const Polygon& p, const Decomposition& d);

// Theorem 2: the pieces (the polygon representation) from the graph representation in O(n + r). Each
// piece is walked from one of its boundary edges, taking at every vertex the neighbour that turns
// least to the left; every piece of a naive decomposition has a boundary edge of P on it.
std::vector<Piece> naive_pieces(const Polygon& p, const Decomposition& d, const NaiveGraph& g);

namespace naive {

// The perturbed ray of one notch v: the extension of edge (prev(v), v) beyond v, turned by an
// infinitesimal angle counter-clockwise, into the notch's range. A point exactly on the extension
// ahead of v is then right of the ray; a point on its line behind v is left of it. No vertex is ever on
// the perturbed ray, so every crossing is proper.
enum class Place : std::uint8_t { Left, Right, Ahead, Behind };  // Ahead, Behind: on the extension's line
inline int side_of(Place place) { return place == Place::Left || place == Place::Behind ? 1 : -1; }

class Decomposer;

// The shot of one notch, as a search of the polygon's boundary sees it.
class Shot {
 public:
  Shot(Decomposer& g, const Polygon& p, std::size_t notch) : g_(g), p_(p), v_(notch) {}
  std::size_t notch() const { return v_; }
  const Point& from() const { return p_[p_.prev(v_)]; }  // the extension runs from here through v
  const Point& origin() const { return p_[v_]; }
  Place place(std::size_t w) const;  // polygon vertex w (not v) relative to the extension
  // Polygon edge (i, i+1), whose ends are on different sides of the perturbed ray.
  void offer_edge(std::size_t i, bool first_is_right);
  // Polygon vertex w, on the extension ahead of v.
  void offer_ahead(std::size_t w);

 private:
  Decomposer& g_;
  const Polygon& p_;
  std::size_t v_;
};

// How the polygon's edges are searched for a shot's first crossing.
class BoundarySearch {
 public:
  virtual ~BoundarySearch() = default;
  // Offers the shot at least the nearest polygon edge it crosses ahead of its notch and the nearest
  // polygon vertex on its extension ahead (none of the notch's own two edges). Offering more is fine.
  virtual void search(Shot& shot) = 0;
};

// Runs the naive decomposition over d for the listed notches, searching the boundary with `search`.
// Counts "segments" (shots), "edge_crossings" (polygon edges offered), "segment_tests", "repairs"
// (shots turned off their extension), "repair_tests" (notches tested for a repair), "steiner_points".
Decomposition resolve(const Polygon& p, Decomposition d, const std::vector<VertexId>& notches,
                      BoundarySearch& search, Counters& counters);

// The notches of p, in index order.
std::vector<VertexId> notches_of(const Polygon& p);

}  // namespace naive
}  // namespace pd
