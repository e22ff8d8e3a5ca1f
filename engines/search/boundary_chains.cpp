// Convex chains of a polygon's boundary and segment searches over them: see boundary_chains.h.
#include "engines/search/boundary_chains.h"

namespace pd::boundary {

int exact_sign_of(const Point& p, const Point& q, const Point& r, const Point& s, bool cross) {
  const QPoint P = to_exact(p), Q = to_exact(q), R = to_exact(r), S = to_exact(s);
  const Rational ax = Q.x() - P.x(), ay = Q.y() - P.y(), bx = S.x() - R.x(), by = S.y() - R.y();
  const Rational value = cross ? Rational(ax * by - ay * bx) : Rational(ax * bx + ay * by);
  return CGAL::sign(value);
}

namespace {

// Figure 2.6 in one pass round a ring from its first notch: the ring between two notches is cut
// greedily into maximal convex chains. A chain from y_s is extended by the next edge while the
// polygon y_s .. y_k stays convex; between notches the boundary turns left everywhere, so only its
// angles at y_s and y_k can be reflex. Until the boundary has turned through more than 180 degrees
// from the chain's first edge, every vertex is left of every edge's line and those angles need no
// test. How far it has turned is known to a quarter turn from the quadrants the edges' directions
// pass through (comparisons only); an exact test is needed only when it has crossed two quadrant
// boundaries. So most vertices cost one predicate, the notch test.
class ChainBuilder {
 public:
  ChainBuilder(const Polygon& p, std::size_t ring) : p_(p), begin_(p.ring_begin(ring)), end_(p.ring_end(ring)) {}

  // The ring's notches in index order, and its chains from its first notch on; false, and nothing
  // added, when the ring has no notch.
  bool build(std::vector<VertexId>& notches, std::vector<Chain>& chains) {
    std::size_t first = begin_;
    while (first < end_ && cross_sign(p_[p_.prev(first)], p_[first], p_[first], p_[p_.next(first)]) >= 0) ++first;
    if (first == end_) return false;
    notches.push_back(static_cast<VertexId>(first));
    std::size_t d = first, e = p_.next(first);  // d precedes e
    Edge before(p_[d], p_[e]);
    int before_quadrant = before.quadrant();
    start_chain(first);
    while (e != first) {
      const std::size_t e1 = p_.next(e);
      const Edge after(p_[e], p_[e1]);
      const int after_quadrant = after.quadrant();
      int t = filtered_cross_sign(before, after);
      if (t == kUnsettled) t = exact_sign_of(p_[d], p_[e], p_[e], p_[e1], true);
      if (t < 0) notches.push_back(static_cast<VertexId>(e));
      if (t < 0 || !extends(e, e1, t, (after_quadrant - before_quadrant) & 3)) {
        chains.push_back(chain_to(e));
        start_chain(e);
      }
      before = after, before_quadrant = after_quadrant;
      d = e, e = e1;
    }
    chains.push_back(chain_to(e));
    return true;
  }

 private:
  // The chain from y_s to y_e (the whole ring when they are one vertex).
  Chain chain_to(std::size_t e) const {
    const std::size_t size = end_ - begin_, edges = e > s_ ? e - s_ : e + size - s_;
    return {s_, edges, lead_, end_, size};
  }

  void start_chain(std::size_t s) {
    s_ = s, s1_ = p_.next(s), lead_ = 1, quadrants_ = 0, straight_ = true, within_half_turn_ = true;
  }

  // Whether the chain y_s .. y_e, with turn t >= 0 at y_e, extends by edge (y_e, y_e1), whose direction
  // is `steps` quadrant boundaries on from the previous edge's (a left turn of less than 180 degrees
  // crosses at most two).
  bool extends(std::size_t e, std::size_t e1, int t, int steps) {
    if (straight_ && t == 0) return ++lead_, true;
    straight_ = false;
    if (within_half_turn_) {
      // After q boundaries the turn from the first edge is strictly between 90 (q - 1) and 90 (q + 1)
      // degrees. A parallel edge at q = 2 points the opposite way: the boundary turns by less than 180
      // degrees at a vertex, so it cannot come round to the first edge's way without passing 180.
      quadrants_ += steps;
      if (quadrants_ <= 1) return true;
      if (quadrants_ == 2 && cross_sign(p_[s_], p_[s1_], p_[e], p_[e1]) >= 0) return true;
      within_half_turn_ = false;
    }
    return orient(p_[e], p_[e1], p_[s_]) >= 0 && orient(p_[e1], p_[s_], p_[s1_]) >= 0;
  }

  const Polygon& p_;
  const std::size_t begin_, end_;
  std::size_t s_ = 0, s1_ = 0, lead_ = 1, quadrants_ = 0;
  bool straight_ = true, within_half_turn_ = true;
};

using Vec = ExactKernel::Vector_2;
using Segment = ExactKernel::Segment_2;

int sign_of(const Rational& v) { return CGAL::sign(v); }
int exact_cross_sign(const Vec& u, const Vec& v) { return sign_of(u.x() * v.y() - u.y() * v.x()); }
int exact_dot_sign(const Vec& u, const Vec& v) { return sign_of(u.x() * v.x() + u.y() * v.y()); }

// A ring without a notch is one chain: the whole ring from its first vertex.
Chain whole_ring(const Polygon& p, std::size_t ring) {
  const std::size_t b = p.ring_begin(ring), size = p.ring_end(ring) - b;
  std::size_t lead = 1;
  while (lead < size && cross_sign(p[b], p[b + 1], p[b + lead], p[p.next(b + lead)]) == 0 &&
         dot_sign(p[b], p[b + 1], p[b + lead], p[p.next(b + lead)]) > 0)
    ++lead;
  return {b, size, lead, b + size, size};
}

// The sign of an interval when it is settled, else kUnsettled.
int settled_sign(const Interval& v) { return certain_sign(v).value_or(kUnsettled); }

// Chains shorter than this are tested edge by edge: cheaper than setting up the searches, still O(1).
constexpr std::size_t kShortChain = 8;

}  // namespace

void split_into_chains(const Polygon& p, std::vector<VertexId>& notches, std::vector<Chain>& chains) {
  // Every hole has notches (a clockwise ring turns right somewhere), so a ring without one is the
  // outer ring, and it needs a chain only when there are holes: a convex polygon has no shot to search.
  for (std::size_t ring = 0; ring < p.ring_count(); ++ring)
    if (!ChainBuilder(p, ring).build(notches, chains) && p.hole_count() > 0) chains.push_back(whole_ring(p, ring));
}

SegmentSearch::SegmentSearch(const Polygon& p, const std::vector<QPoint>& exact) : p_(p), exact_(exact) {
  std::vector<VertexId> notches;
  split_into_chains(p, notches, chains_);
  if (chains_.empty()) chains_.push_back(whole_ring(p, 0));
  while (leaves_ < chains_.size()) leaves_ *= 2;
  boxes_.assign(2 * leaves_, CGAL::Bbox_2());
  for (std::size_t k = 0; k < chains_.size(); ++k) {
    const Chain& c = chains_[k];
    CGAL::Bbox_2& box = boxes_[leaves_ + k];
    for (std::size_t j = 0; j <= c.edges; ++j) box += p[chain_vertex(c, j)].bbox();
  }
  for (std::size_t i = leaves_ - 1; i >= 1; --i) boxes_[i] = boxes_[2 * i] + boxes_[2 * i + 1];
}

// Descends the hierarchy from its root into the nodes whose box can meet the segment.
bool SegmentSearch::meets_boundary(const QPoint& s, const QPoint& t, VertexId skip) {
  s_ = &s, t_ = &t;
  st_ = Segment(s, t);
  u_ = t - s;
  sx_ = Interval(CGAL::to_interval(s.x())), sy_ = Interval(CGAL::to_interval(s.y()));
  ux_ = Interval(CGAL::to_interval(u_.x())), uy_ = Interval(CGAL::to_interval(u_.y()));
  around_ = box_of(s, t);
  std::size_t pending[64] = {1};  // a path's worth of right siblings: the depth is below 64
  std::size_t size = 1;
  while (size > 0) {
    const std::size_t i = pending[--size];
    ++steps_;
    if (!box_meets(boxes_[i])) continue;
    if (i >= leaves_) {
      if (chain_meets(i - leaves_, skip)) return true;
      continue;
    }
    pending[size++] = 2 * i + 1;
    pending[size++] = 2 * i;
  }
  return false;
}

// Whether the box can meet the segment: it meets the segment's box and its corners are not settled
// strictly on one side of the segment's line.
bool SegmentSearch::box_meets(const CGAL::Bbox_2& box) const {
  if (!CGAL::do_overlap(around_, box)) return false;
  CGAL::Protect_FPU_rounding<true> upwards;
  const int sides[4] = {settled_sign(line_side(box.xmin(), box.ymin())), settled_sign(line_side(box.xmax(), box.ymin())),
                        settled_sign(line_side(box.xmin(), box.ymax())), settled_sign(line_side(box.xmax(), box.ymax()))};
  for (const int side : sides)
    if (side != sides[0] || (side != 1 && side != -1)) return true;
  return false;
}

// cross(u, (x, y) - s) in interval arithmetic, for a point of the input. Pre: rounding upwards.
Interval SegmentSearch::line_side(double x, double y) const {
  return ux_ * (Interval(y) - sy_) - uy_ * (Interval(x) - sx_);
}

// Whether chain k, the edges at `skip` left out, meets the segment.
bool SegmentSearch::chain_meets(std::size_t k, VertexId skip) {
  const Chain& c = chains_[k];
  chain_ = &c;
  std::size_t skipped[2] = {c.edges, c.edges};  // the chain's own numbers of the edges left out
  if (skip != kNoVertex) {
    skipped[0] = offset_in_chain(c, p_.prev(skip)), skipped[1] = offset_in_chain(c, skip);
    std::sort(skipped, skipped + 2);
  }
  std::size_t lo = 0;
  for (const std::size_t local : skipped) {
    if (local >= c.edges) break;
    if (lo < local && range_meets(lo, local)) return true;
    lo = local + 1;
  }
  return lo < c.edges && range_meets(lo, c.edges);
}

// Whether edges lo..hi-1 of the chain meet the segment: the chain is cut where its direction passes
// the segment's and the opposite one, into at most three runs along which the signed distance to the
// segment's line is monotone.
bool SegmentSearch::range_meets(std::size_t lo, std::size_t hi) {
  if (hi - lo <= kShortChain) {  // edge by edge: only an edge that reaches the line can meet the segment
    int side_j = side(lo);
    for (std::size_t j = lo; j < hi; ++j) {
      const int side_next = side(j + 1);
      if (side_j * side_next <= 0 && meets(j, j + 1)) return true;
      side_j = side_next;
    }
    return false;
  }
  std::size_t cuts[4] = {lo, first_edge_reaching(lo, hi, 1), first_edge_reaching(lo, hi, -1), hi};
  std::sort(cuts + 1, cuts + 3);
  for (int k = 0; k < 3; ++k)
    if (cuts[k] < cuts[k + 1] && run_meets(cuts[k], cuts[k + 1])) return true;
  return false;
}

// The first edge in [lo, hi) whose direction is at or past `sense` * (t - s) in the order around d0;
// hi when there is none. The directions are sorted in that order, so this is a binary search.
std::size_t SegmentSearch::first_edge_reaching(std::size_t lo, std::size_t hi, int sense) {
  const int c = sense * cross_sign_with_u(0, 1, 1);
  const int half_u = c > 0 ? 0 : c < 0 ? 1 : sense * dot_sign_with_u(0, 1) > 0 ? 0 : 1;
  auto before_u = [&](std::size_t j) {
    ++steps_;
    const int h = half_of_edge(p_, *chain_, j);
    if (h != half_u) return h < half_u;
    return sense * cross_sign_with_u(j, j + 1, 1) > 0;
  };
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (before_u(mid)) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

// Vertices lo..hi, along which the signed distance to the segment's line is monotone: only the edges
// where it reaches the line, the stretch on the line and the edge where it leaves can meet the segment.
bool SegmentSearch::run_meets(std::size_t lo, std::size_t hi) {
  const int rising = cross_sign_with_u(lo, hi, -1);
  const int dir = rising == 0 ? 1 : rising;
  auto first = [&](std::size_t from, int at_least) {
    std::size_t a = from, b = hi + 1;
    while (a < b) {
      const std::size_t mid = a + (b - a) / 2;
      if (dir * side(mid) >= at_least) b = mid;
      else a = mid + 1;
    }
    return a;
  };
  const std::size_t zero = first(lo, 0), above = first(zero, 1);
  if (lo < zero && zero <= hi && meets(zero - 1, zero)) return true;
  if (zero < above && meets(zero, above - 1)) return true;
  return lo < above && above <= hi && meets(above - 1, above);
}

// The side of the segment's line the chain's vertex j is on: the sign of cross(u, x_j - s).
int SegmentSearch::side(std::size_t j) {
  ++steps_;
  const Point& v = input(j);
  int sign;
  {
    CGAL::Protect_FPU_rounding<true> upwards;
    sign = settled_sign(line_side(v.x(), v.y()));
  }
  return sign != kUnsettled ? sign : orient(*s_, *t_, x(j));
}

// The sign of sense * cross(x_to - x_from, u) for chain vertices from and to.
int SegmentSearch::cross_sign_with_u(std::size_t from, std::size_t to, int sense) {
  const Point &a = input(from), &b = input(to);
  int sign;
  {
    CGAL::Protect_FPU_rounding<true> upwards;
    sign = settled_sign((Interval(b.x()) - Interval(a.x())) * uy_ - (Interval(b.y()) - Interval(a.y())) * ux_);
  }
  return sense * (sign != kUnsettled ? sign : exact_cross_sign(x(to) - x(from), u_));
}

// The sign of dot(x_to - x_from, u).
int SegmentSearch::dot_sign_with_u(std::size_t from, std::size_t to) {
  const Point &a = input(from), &b = input(to);
  int sign;
  {
    CGAL::Protect_FPU_rounding<true> upwards;
    sign = settled_sign((Interval(b.x()) - Interval(a.x())) * ux_ + (Interval(b.y()) - Interval(a.y())) * uy_);
  }
  return sign != kUnsettled ? sign : exact_dot_sign(x(to) - x(from), u_);
}

// Whether chain vertex `from` (from == to), the chain's edge from `from` to `to`, or its stretch of
// edges from `from` to `to` along the segment's line, meets the segment.
bool SegmentSearch::meets(std::size_t from, std::size_t to) {
  if (from == to) return st_.has_on(x(from));
  return CGAL::do_intersect(st_, Segment(x(from), x(to)));
}

// The box of segment st, from intervals around its ends' coordinates.
CGAL::Bbox_2 SegmentSearch::box_of(const QPoint& s, const QPoint& t) {
  const Interval sx(CGAL::to_interval(s.x())), sy(CGAL::to_interval(s.y()));
  const Interval tx(CGAL::to_interval(t.x())), ty(CGAL::to_interval(t.y()));
  return CGAL::Bbox_2(std::min(sx.inf(), tx.inf()), std::min(sy.inf(), ty.inf()), std::max(sx.sup(), tx.sup()),
                      std::max(sy.sup(), ty.sup()));
}

}  // namespace pd::boundary
