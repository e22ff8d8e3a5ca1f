// naive-chains: Chazelle's naive decomposition searched through convex chains (B. Chazelle,
// Computational Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.2.2, Figure 2.6, Theorems 3
// and 4).
//
// Time O(n + r^2 log(n/r)), space O(n) (Theorem 4): an O(n) pass finds the notches and cuts the
// boundary between consecutive notches into maximal convex chains, whose m endpoints are the
// pseudo-notches, m <= 2(1 + r) (Theorem 3, counted as "pseudo_notches"); then each of the r shots
// intersects its ray with every chain in O(log k) for a chain of k edges, and with the O(r) segments
// drawn before. Pre: a simple counter-clockwise polygon; collinear vertices allowed. Output: the same
// guarantees as `naive` (naive.h): exactly r + 1 convex pieces, r exact Steiner points, every vertex
// of degree 2 or 3; with the same shots in the same order, the same decomposition as `naive`.
//
// Reconstructed: Chapter 4, where the thesis intersects a line with a convex chain in O(log k), is not
// part of the text we have. The chain's edge directions turn counter-clockwise through less than a
// full turn, so, measured from the chain's first edge, they are sorted by angle: two binary searches
// find the edges where the direction passes the ray's direction and its opposite, i.e. the chain's
// vertices farthest left and right of the ray's line. Between them the signed distance to that line
// is monotone, and a binary search in each of the at most three runs finds where the chain crosses the
// perturbed ray (at most once per run) and the vertices it has exactly on the line. All of it with
// exact predicates on the input points.
//
// The chains are the thesis's (greedy, maximal); building them skips the tests of the closing angles
// where they provably pass (see ChainBuilder), so that the O(n) pass costs about one predicate per
// vertex: it is what this algorithm spends most of its time on when r is small.
#include "algorithms/naive.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pd {
namespace {

// Exact signs of cross(q - p, s - r) and (q - p) . (s - r) on input points. The pass over all n
// vertices evaluates the first at every vertex, so they get the semi-static filter CGAL gives its
// orientation predicate (CGAL's four-point predicates have only its slower interval filter): each is
// the sum of two products of differences of input doubles, each difference rounded once, so CGAL's
// error bound for the orientation determinant holds with the same constant, and with the dot
// product's own magnitudes. Outside the filter's range, or when it cannot decide, the sign is
// computed in rationals.
[[gnu::noinline]] int exact_sign_of(const Point& p, const Point& q, const Point& r, const Point& s, bool cross) {
  const QPoint P = to_exact(p), Q = to_exact(q), R = to_exact(r), S = to_exact(s);
  const Rational ax = Q.x() - P.x(), ay = Q.y() - P.y(), bx = S.x() - R.x(), by = S.y() - R.y();
  const Rational value = cross ? Rational(ax * by - ay * bx) : Rational(ax * bx + ay * by);
  return CGAL::sign(value);
}

constexpr double kFilterBound = 8.8872057372592798e-16;

// The difference q - p of two input points, rounded (a rounded difference has the exact one's sign).
struct Edge {
  Edge(const Point& p, const Point& q) : x(q.x() - p.x()), y(q.y() - p.y()) {}
  // Which quarter turn [0, 90), [90, 180), [180, 270), [270, 360) the direction is in. Exact.
  int quadrant() const {
    const bool upper = (y > 0) | ((y == 0) & (x > 0));  // [0, 180); written to compile without branches
    return upper ? int(x <= 0) : 2 + int(x >= 0);
  }
  double x, y;
};

// Sign of cross(u, w) for rounded differences u and w when the filter settles it, else kUnsettled.
constexpr int kUnsettled = 2;
inline int filtered_cross_sign(const Edge& u, const Edge& w) {
  const double max_x = std::max(std::abs(u.x), std::abs(w.x)), max_y = std::max(std::abs(u.y), std::abs(w.y));
  const double low = std::min(max_x, max_y), high = std::max(max_x, max_y);
  if (low >= 1e-146 && high < 1e153) {
    const double det = u.x * w.y - u.y * w.x, eps = kFilterBound * low * high;
    if (det > eps) return 1;
    if (det < -eps) return -1;
  }
  // A rounded difference is zero exactly when the difference is: when both products vanish that way
  // (as for two axis-parallel edges, common in real polygons) the sign is 0, which no bound settles.
  if ((u.x == 0 || w.y == 0) && (u.y == 0 || w.x == 0)) return 0;
  return kUnsettled;
}

inline int cross_sign(const Point& p, const Point& q, const Point& r, const Point& s) {
  const int sign = filtered_cross_sign(Edge(p, q), Edge(r, s));
  return sign != kUnsettled ? sign : exact_sign_of(p, q, r, s, true);
}

inline int dot_sign(const Point& p, const Point& q, const Point& r, const Point& s) {
  const Edge u(p, q), w(r, s);
  const double high = std::max(std::max(std::abs(u.x), std::abs(u.y)), std::max(std::abs(w.x), std::abs(w.y)));
  if (high >= 1e-146 && high < 1e153) {
    const double dot = u.x * w.x + u.y * w.y, eps = kFilterBound * high * high;
    if (dot > eps) return 1;
    if (dot < -eps) return -1;
  }
  if ((u.x == 0 || w.x == 0) && (u.y == 0 || w.y == 0)) return 0;
  return exact_sign_of(p, q, r, s, false);
}

// A convex chain: `edges` edges from polygon vertex `start` on, counter-clockwise, such that every
// prefix closes into a convex polygon; `lead` of its first edges point the same way as the first.
struct Chain {
  std::size_t start, edges, lead;
};

// Figure 2.6 in one pass round the boundary from its first notch: the boundary between two notches is
// cut greedily into maximal convex chains. A chain from y_s is extended by the next edge while the
// polygon y_s .. y_k stays convex; between notches the boundary turns left everywhere, so only its
// angles at y_s and y_k can be reflex. Until the boundary has turned through more than 180 degrees
// from the chain's first edge, every vertex is left of every edge's line and those angles need no
// test. How far it has turned is known to a quarter turn from the quadrants the edges' directions
// pass through (comparisons only); an exact test is needed only when it has crossed two quadrant
// boundaries. So most vertices cost one predicate, the notch test.
class ChainBuilder {
 public:
  explicit ChainBuilder(const Polygon& p) : p_(p) {}

  // The notches in index order, and the chains from the first notch on.
  void build(std::vector<VertexId>& notches, std::vector<Chain>& chains) {
    const std::size_t n = p_.size();
    std::size_t first = 0;
    while (first < n && cross_sign(p_[p_.prev(first)], p_[first], p_[first], p_[p_.next(first)]) >= 0) ++first;
    if (first == n) return;
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
        chains.push_back({s_, distance(s_, e), lead_});
        start_chain(e);
      }
      before = after, before_quadrant = after_quadrant;
      d = e, e = e1;
    }
    chains.push_back({s_, distance(s_, e), lead_});
  }

 private:
  std::size_t distance(std::size_t from, std::size_t to) const {
    return to > from ? to - from : to + p_.size() - from;
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
  std::size_t s_ = 0, s1_ = 0, lead_ = 1, quadrants_ = 0;
  bool straight_ = true, within_half_turn_ = true;
};

// The O(log k) intersection of a shot's perturbed ray with every convex chain.
class ChainSearch : public naive::BoundarySearch {
 public:
  ChainSearch(const Polygon& p, std::vector<Chain> chains) : p_(p), chains_(std::move(chains)) {}

  void search(naive::Shot& shot) override {
    shot_ = &shot;
    a_ = &shot.from(), v_ = &shot.origin();
    for (const Chain& c : chains_) {
      chain_ = &c;
      // The notch's own edges are not searched: they are the first edge of one chain and the last of
      // another.
      const std::size_t lo = c.start == shot.notch() ? 1 : 0;
      const std::size_t hi = (c.start + c.edges) % p_.size() == shot.notch() ? c.edges - 1 : c.edges;
      if (lo < hi) search_chain(lo, hi);
    }
  }

  std::int64_t steps() const { return steps_; }
  std::int64_t searches() const { return searches_; }

 private:
  std::size_t id(std::size_t j) const {
    const std::size_t k = chain_->start + j;
    return k < p_.size() ? k : k - p_.size();
  }
  const Point& x(std::size_t j) const { return p_[id(j)]; }

  void search_chain(std::size_t lo, std::size_t hi) {
    ++searches_;
    if (hi - lo <= kShortChain) return scan(lo, hi);
    std::size_t cuts[4] = {lo, first_edge_reaching(lo, hi, 1), first_edge_reaching(lo, hi, -1), hi};
    std::sort(cuts + 1, cuts + 3);
    for (int k = 0; k < 3; ++k)
      if (cuts[k] < cuts[k + 1]) search_run(cuts[k], cuts[k + 1]);
  }

  // A short chain is tested edge by edge, as `naive` does: cheaper than setting up the searches, and
  // still O(1) per chain.
  static constexpr std::size_t kShortChain = 8;
  void scan(std::size_t lo, std::size_t hi) {
    naive::Place before = shot_->place(id(lo));
    if (before == naive::Place::Ahead) shot_->offer_ahead(id(lo));
    for (std::size_t j = lo + 1; j <= hi; ++j) {
      ++steps_;
      const naive::Place at = shot_->place(id(j));
      if (at == naive::Place::Ahead) shot_->offer_ahead(id(j));
      if (naive::side_of(before) != naive::side_of(at)) shot_->offer_edge(id(j - 1), naive::side_of(before) < 0);
      before = at;
    }
  }

  // Angular position, measured counter-clockwise from the chain's first edge d0: 0 for [0, 180), 1
  // for [180, 360), and 2 for an edge that has turned a full circle back to d0's direction.
  int half_of_edge(std::size_t j) const {
    const int c = cross_sign(x(0), x(1), x(j), x(j + 1));
    if (c != 0) return c > 0 ? 0 : 1;
    if (dot_sign(x(0), x(1), x(j), x(j + 1)) <= 0) return 1;
    return j < chain_->lead ? 0 : 2;
  }

  // The first edge in [lo, hi) whose direction is at or past the direction `sense` * (v - a) in the
  // order around d0; hi when there is none. The directions are sorted in that order (the chain turns
  // left by less than a full turn), so this is a binary search.
  std::size_t first_edge_reaching(std::size_t lo, std::size_t hi, int sense) {
    const int c = sense * cross_sign(x(0), x(1), *a_, *v_);
    const bool ahead_of_d0 = sense * dot_sign(x(0), x(1), *a_, *v_) > 0;
    const int half_u = c > 0 ? 0 : c < 0 ? 1 : ahead_of_d0 ? 0 : 1;
    auto before_u = [&](std::size_t j) {
      ++steps_;
      const int h = half_of_edge(j);
      if (h != half_u) return h < half_u;
      return sense * cross_sign(x(j), x(j + 1), *a_, *v_) > 0;
    };
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (before_u(mid)) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  int side_of_line(std::size_t j) {
    ++steps_;
    return orient(*a_, *v_, x(j));
  }

  // First j in [lo, hi] with pred(j), hi + 1 if none; pred is monotone (false, then true).
  template <class Pred>
  std::size_t first(std::size_t lo, std::size_t hi, Pred pred) {
    ++hi;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (pred(mid)) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  }

  // Vertices lo..hi, along which the signed distance to the ray's line is monotone.
  void search_run(std::size_t lo, std::size_t hi) {
    const int rising = cross_sign(*a_, *v_, x(lo), x(hi));
    const int dir = rising == 0 ? 1 : rising;
    // Along the run, dir * side goes -1, 0, +1: [lo, zero) below, [zero, above) on the line.
    const std::size_t zero = first(lo, hi, [&](std::size_t j) { return dir * side_of_line(j) >= 0; });
    const std::size_t above = first(zero, hi, [&](std::size_t j) { return dir * side_of_line(j) > 0; });
    bool on_line_ahead = false;
    if (zero < above) {
      on_line_ahead = shot_->place(id(zero)) == naive::Place::Ahead;
      if (on_line_ahead) shot_->offer_ahead(id(zero)), shot_->offer_ahead(id(above - 1));
    }
    // The perturbed ray puts vertices on the line ahead to the right, those behind to the left.
    const bool left_grows = dir > 0;
    const std::size_t change = left_grows == on_line_ahead ? above : zero;
    if (lo < change && change <= hi) shot_->offer_edge(id(change - 1), left_grows);
  }

  const Polygon& p_;
  std::vector<Chain> chains_;
  naive::Shot* shot_ = nullptr;
  const Point *a_ = nullptr, *v_ = nullptr;
  const Chain* chain_ = nullptr;
  std::int64_t steps_ = 0, searches_ = 0;
};

Decomposition naive_chains(const Polygon& p, Counters& counters) {
  std::vector<VertexId> notches;
  std::vector<Chain> chains;
  ChainBuilder(p).build(notches, chains);
  const std::int64_t pseudo_notches = static_cast<std::int64_t>(chains.size());
  ChainSearch search(p, std::move(chains));
  Decomposition d = naive::resolve(p, Decomposition{}, notches, search, counters);
  counters["pseudo_notches"] = pseudo_notches;
  counters["chain_searches"] = search.searches();
  counters["binary_search_steps"] = search.steps();
  return d;
}

}  // namespace

REGISTER_ALGORITHM(Algorithm{"naive-chains", Kind::Convex, true, false, "n+r^2*log(n/r)", "== r+1",
                             "Chazelle thesis (000) Sec. 2.2.2, Thms 3-4", 1000000, naive_chains});

}  // namespace pd
