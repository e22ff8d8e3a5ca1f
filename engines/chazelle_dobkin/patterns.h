// Pattern detection for Chazelle and Dobkin's optimal convex decomposition with Steiner points
// (B. Chazelle, Computational Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.3.2-2.3.4):
// the building blocks that `chazelle-dobkin-n5` (Sec. 2.3) and `chazelle-dobkin` (Sec. 2.4) share.
//
// An Xk-pattern (Definition 2.2) is a tree in P whose degree-1 and degree-2 nodes are notches whose
// reflex angles its edges resolve, and whose degree-3 nodes (Steiner points) have no reflex angle. Each
// pattern of a set of compatible patterns saves one piece over the naive decomposition (Theorem 7).
// Y-patterns are assembled from X2- and X3-like joints between notches "adapted" to the subtrees
// already hanging at them (Corollary 14.1); this file decides those joints:
//   - X2 (Theorem 13): notches a, b are joined by one segment when ab is a diagonal (R(a, ab) = ab)
//     and ab resolves the angle still open at a and at b.
//   - X3 (Theorem 14): notches a, b, c are joined through one Steiner point S. The thesis's conditions
//     are: a, b, c in boundary order turn the same way as the triangle abc (1); from each notch the
//     extreme segments r_ij, l_ji towards the other two exist (2) and meet pairwise in C, A, B (3);
//     the hexagon Q = a C b A c B has a non-empty kernel (4), and S is any point of that kernel.
//
// The reconstruction of Theorem 14's segments r_ij and l_ji (garbled in the OCR text, Figures 2.21
// and 2.22 lost), the proof that condition 3 needs no test of its own, degenerate position (arms,
// regions that are a segment or a point), Corollary 14.2's extreme point, X4 (Theorem 15) and the
// interval-arithmetic filter: docs/algorithms/chazelle-dobkin-patterns.md.
// Deviation: superranges (Theorem 11) are replaced by trees of geodesics from each notch
// (engines/chazelle_dobkin/geodesics.h), in the same O(n + r^2 log n) in all (the same page says how,
// and how the tests hold these views to walks of a triangulation). Every test after it costs what
// Theorems 13-15 say: O(1), or O(r log(n/r)) for a segment against the boundary in X4's tips.
//
// Exact: every test is an orientation on exact rationals; Steiner points are exact rationals.
#pragma once

#include "core/decomposition.h"
#include "engines/search/boundary_chains.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace pd::cd {

// A notch with the two arms that bound the angle still to be resolved there: turning
// counter-clockwise from the forward arm to the backward arm sweeps that angle. A bare notch v has
// its polygon edges as arms (forward through v+1, backward through v-1); a notch adapted to a subtree
// hanging at it (Corollary 14.1) has that subtree's edge as one arm.
struct AdaptedNotch {
  std::size_t notch;  // index into Patterns::notches()
  QPoint forward;     // a point of the forward arm other than the notch
  QPoint backward;    // a point of the backward arm other than the notch
};

// The region of Steiner points of an X3 test (engines/chazelle_dobkin/patterns.cpp).
template <class P>
struct Region;

// Points with interval coordinates, for filters in front of exact computations.
using IntervalKernel = CGAL::Simple_cartesian<CGAL::Interval_nt<false>>;

// The directions allowed at a notch for its edge to a Steiner point: the cone of the X with
// orient(v, lower, X) > 0 and orient(v, upper, X) < 0, less than 180 degrees wide (or a half-plane),
// with its arms (= 0) when `closed`. A notch's joint is closed where the angle still open there is
// reflex: its arms are the extensions of that angle's sides, and an edge along one leaves 180
// degrees on one side and resolves the angle. It is open where the angle is not reflex (its arms
// are then the angle's sides, which an edge may not run along), and so are the branches (a branch's
// arms are a side of P, which an edge may not run along, and an extension, along which an edge
// resolves the notch and so is no branch).
struct Joint {
  Joint(std::size_t notch, QPoint lower, QPoint upper, bool closed);

  std::size_t notch;
  QPoint lower, upper;
  bool closed;
  // lower and upper on intervals, for the filter of the X3 test.
  IntervalKernel::Point_2 lower_approx, upper_approx;
};

// Where the views across the notches (transition) come from: trees of geodesics, O(n + r^2 log n) in
// all (both programs); or walks of a triangulation, O(n log n + n r + r^2 log n), which share no code
// with them and which the tests hold them to (see the header comment).
enum class Views : std::uint8_t { kGeodesics, kTriangulation };

class Patterns {
 public:
  // Notches, the boundary's convex chains (O(n)) and the views from each notch across every other.
  explicit Patterns(const Polygon& p, Views views = Views::kGeodesics);
  // The chain search refers to this object's rational vertices.
  Patterns(const Patterns&) = delete;
  Patterns& operator=(const Patterns&) = delete;

  // The notches, in counter-clockwise (index) order.
  const std::vector<VertexId>& notches() const { return notches_; }
  const QPoint& notch_point(std::size_t notch) const { return exact_[notches_[notch]]; }
  const AdaptedNotch& bare(std::size_t notch) const { return bare_[notch]; }

  // The cone that resolves what is left of the angle at a: between the extensions of its arms beyond
  // it while that angle is reflex, between the arms themselves once it is not. A bare notch's is
  // computed once; the program keeps the joint of each subtree (it asks for them O(r^3) times).
  Joint joint(const AdaptedNotch& a) const;
  const Joint& bare_joint(std::size_t notch) const { return bare_joint_[notch]; }
  // The directions of an edge hanging at a bare notch that leave the angle on its other side reflex:
  // on the forward side (between the forward edge and the extension of the backward edge), or on the
  // backward side.
  const Joint& forward_branch(std::size_t notch) const { return forward_branch_[notch]; }
  const Joint& backward_branch(std::size_t notch) const { return backward_branch_[notch]; }

  // Whether the segment between notches a and b is a diagonal (R(a, ab) = ab, Theorem 13). O(1).
  bool diagonal(std::size_t a, std::size_t b) const { return sees_notch_[a * notches_.size() + b]; }
  // Whether the segment from a towards `towards` resolves the angle still open at a: both angles it
  // leaves are at most 180 degrees and it does not run along an arm. O(1).
  bool resolves(const AdaptedNotch& a, const QPoint& towards) const;

  // Theorem 13 on adapted notches: whether segment ab is a diagonal that resolves the angles still open
  // at a and at b (180 degrees allowed). O(1).
  bool x2(const AdaptedNotch& a, const AdaptedNotch& b);

  // Theorem 14 on joints a, b, c at distinct notches in counter-clockwise boundary order: a Steiner
  // point S such that Sa, Sb, Sc lie in P, leave S without a reflex angle and each lies in its joint's
  // cone; or nothing. O(1) (see the header comment). `x3` returns the average of the region's
  // vertices; `x3_extreme` the vertex turned furthest around a (counter-clockwise when
  // `counter_clockwise`) if it is a Steiner point, else that vertex moved 1/64 of the way towards the
  // average (Corollary 14.2; see the header comment).
  std::optional<QPoint> x3(const Joint& a, const Joint& b, const Joint& c);
  std::optional<QPoint> x3_extreme(const Joint& a, const Joint& b, const Joint& c, bool counter_clockwise);

  // Theorem 15, with the Steiner points at the tips of Q: the loosest X4-pattern whose first Steiner
  // point joins notches a and b and whose second joins c and d, the four distinct and in
  // counter-clockwise boundary order starting anywhere (so a..b and c..d are the chains the two
  // Steiner points face). Returns the two Steiner points or nothing. O(1) after the tips, then
  // O(r log(n/r)); a tip costs O(r log(n/r)) once.
  std::optional<std::pair<QPoint, QPoint>> x4(std::size_t a, std::size_t b, std::size_t c, std::size_t d);
  // Whether the tip of Q facing the chain from notch a counter-clockwise to notch b exists: x4 finds
  // nothing whose first (or second) Steiner point would be that tip when it does not. O(r log(n/r))
  // the first time, O(1) after.
  bool has_tip(std::size_t a, std::size_t b) { return tip(a, b).has_value(); }

  // Whether the open segment from polygon vertex v to point s lies in P's interior, s included.
  // O(r log(n/r)).
  bool sees(VertexId v, const QPoint& s) const;
  // Whether the closed segment st, between interior points, avoids P's boundary. O(r log(n/r)).
  bool inside(const QPoint& s, const QPoint& t) const;

  // A vertex on the ray from notch `from` along which its view passes across notch `towards`'s
  // boundary position: the first turn of the geodesic from `from` to `towards`, or `towards` itself
  // when it runs straight (see the header comment). Only the ray's direction is meant.
  VertexId transition(std::size_t from, std::size_t towards) const {
    return transition_[from * notches_.size() + towards];
  }

  // Counts "x2_tests", "x2_found", "x3_tests", "x3_found", "x4_tests", "x4_found", "tips" (computed),
  // "tips_found" (that exist), "segment_search_steps" (boxes of the chains' hierarchy visited,
  // binary-search steps and vertices tested by sees and inside), and for the views from geodesics
  // "view_chords" (the chords of their decomposition) and "view_tangent_steps" (orientations of the
  // walks' funnel searches).
  void report(Counters& counters) const;

 private:
  const QPoint& at(VertexId v) const { return exact_[v]; }
  VertexId next(VertexId v) const { return static_cast<VertexId>(p_.next(v)); }
  VertexId prev(VertexId v) const { return static_cast<VertexId>(p_.prev(v)); }
  void compute_transitions(std::size_t from, const std::vector<std::uint32_t>& visible,
                           const std::vector<std::uint32_t>& seen);
  void views_from_triangulation();
  void views_from_geodesics();
  void compute_bare_cones();
  Joint cone(const AdaptedNotch& a) const;
  Region<QPoint> x3_region(const std::array<const Joint*, 3>& joints) const;
  std::optional<QPoint> found(const QPoint& s);
  const std::optional<QPoint>& tip(std::size_t a, std::size_t b);

  const Polygon& p_;
  std::vector<QPoint> exact_;
  mutable boundary::SegmentSearch segments_;  // P's boundary in convex chains, for sees and inside
  std::vector<VertexId> notches_;
  // Per notch: the bare notch, its joint and its two branches.
  std::vector<AdaptedNotch> bare_;
  std::vector<Joint> bare_joint_, forward_branch_, backward_branch_;
  // r x r: whether notch j's vertex is a diagonal's end seen from notch i; the vertex through which
  // notch i's view passes across notch j's boundary position (see the header comment).
  std::vector<char> sees_notch_;
  std::vector<VertexId> transition_;
  // r x r, filled on demand: the tip of Q facing the chain from notch a to notch b (Theorem 15).
  std::vector<char> tip_known_;
  std::vector<std::optional<QPoint>> tip_;
  std::int64_t x2_tests_ = 0, x2_found_ = 0, x3_tests_ = 0, x3_found_ = 0;
  std::int64_t x4_tests_ = 0, x4_found_ = 0, tips_ = 0, tips_found_ = 0, view_chords_ = 0, view_tangent_steps_ = 0;
};

}  // namespace pd::cd
