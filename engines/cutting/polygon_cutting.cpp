// The polygon-cutting theorem: Chazelle, "How to Divide a Polygon Fairly", CMU-CS tech. report, April
// 1982 (paper 004), Section 2: the preprocessing (2, lists LP, LH, LV), Theorem 3 (2.2, a vertical chord
// AB whose two sides weigh at most 2C/3, by recursive median-line pruning; see 4b) and Theorem 1 (2.3,
// from AB to a diagonal: the hulls H1 and H2, the triangulation of the domain of safety H* by the
// two-pointer walk of Lemma 5, the scan of Lemma 6).
//
// Time: O(n log n) preprocessing of the top polygon (sorting, a sweep), then O(m) per cut of a part of
// m vertices: every list, boundary node and candidate vertex is touched a bounded number of times; the
// counts are returned (CutWork) so that the bound can be checked from counts. Space O(n).
// Pre: a simple counter-clockwise polygon (collinear vertices allowed); weights 0/1 with C != 1; at
// least 4 vertices. Guarantee: a diagonal (interior inside the polygon, no vertex on it) whose two parts
// each weigh at most 2C/3, its endpoints weighing 0 in both (exact integer test 3*max <= 2C).
//
// Reconstructions and deviations (docs/algorithms/polygon-cutting.md, items 1-7): symbolic
// perturbation for "no two vertices share an x-coordinate", LV from a sweep, the median line among
// R's vertices, pruning by windows; Theorems 2 and 3 are false as stated (a fair chord need not
// exist; a fair half-chord from a vertex does, item 4b); Theorem 1's hulls replaced by shortest
// paths where Q1 is not convex (item 5), built by Andrew's monotone chain (item 6); Lemma 6's scan
// and why it finds a fair cut for C >= 2 (item 7). C = 1 is refused (see why_no_fair_cut).
#include "engines/cutting/polygon_cutting.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace pd {

std::optional<std::string> why_no_fair_cut(std::size_t n, std::int64_t C) {
  if (n < 4) return std::string("a triangle has no diagonal");
  if (C == 1)
    return std::string("the weights total C=1: a fair cut must end at the one weighted vertex, which need not "
                       "have a diagonal (the theorem assumes C > 2)");
  return std::nullopt;
}

std::vector<int> vertex_weights(const Polygon& p, WeightRule rule) {
  std::vector<int> w(p.size(), 1);
  if (rule == WeightRule::Reflex)
    for (std::size_t i = 0; i < p.size(); ++i) w[i] = p.is_reflex(i) ? 1 : 0;
  return w;
}

namespace cutting {

constexpr std::uint32_t kNone = ~std::uint32_t{0};

namespace {

std::vector<std::int64_t> prefix_sums(const std::vector<int>& w) {
  std::vector<std::int64_t> s(w.size() + 1, 0);
  for (std::size_t k = 0; k < w.size(); ++k) s[k + 1] = s[k] + w[k];
  return s;
}

std::vector<Id> lex_order(const Polygon& p) {
  std::vector<Id> order(p.size());
  std::iota(order.begin(), order.end(), Id{0});
  std::sort(order.begin(), order.end(), [&](Id a, Id b) { return p[a] < p[b]; });
  return order;
}

// Whether edge pq lies below edge rs where both meet the current sweep line (they never cross). The
// later-starting edge's left end is tested against the other's line.
bool below(const std::vector<Point>& v, const std::vector<std::uint32_t>& rank, Id p, Id q, Id r, Id s) {
  if (rank[p] > rank[q]) std::swap(p, q);
  if (rank[r] > rank[s]) std::swap(r, s);
  if (p == r) return orient(v[p], v[q], v[s]) > 0;
  if (rank[p] < rank[r]) return orient(v[p], v[q], v[r]) > 0;
  return orient(v[r], v[s], v[p]) < 0;
}

std::vector<Id> topological_order(std::size_t n, const std::vector<std::pair<Id, Id>>& pairs) {
  std::vector<std::uint32_t> start(n + 1, 0), indegree(n, 0);
  for (const auto& [lo, hi] : pairs) ++start[lo + 1], ++indegree[hi];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Id> above(pairs.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& [lo, hi] : pairs) above[fill[lo]++] = hi;
  std::vector<Id> ready, order;
  for (Id e = 0; e < n; ++e)
    if (indegree[e] == 0) ready.push_back(e);
  while (!ready.empty()) {
    const Id e = ready.back();
    ready.pop_back();
    order.push_back(e);
    for (std::uint32_t k = start[e]; k < start[e + 1]; ++k)
      if (--indegree[above[k]] == 0) ready.push_back(above[k]);
  }
  if (order.size() != n) throw std::logic_error("polygon cutting: the vertical order of the edges has a cycle");
  return order;
}

// LV: edges named by their first vertex, every edge before each edge above it.
std::vector<Id> vertical_order(const Polygon& poly, const std::vector<Id>& lh, const std::vector<std::uint32_t>& rank) {
  const std::vector<Point>& v = poly.vertices();
  auto edge_before = [&](Id e, Id f) { return below(v, rank, e, Id(poly.next(e)), f, Id(poly.next(f))); };
  std::set<Id, decltype(edge_before)> sweep(edge_before);
  std::vector<decltype(sweep)::iterator> where(v.size());
  std::vector<std::pair<Id, Id>> pairs;
  for (const Id x : lh) {
    const Id incident[2] = {Id(poly.prev(x)), x};
    auto far_end = [&](Id e) { return e == x ? Id(poly.next(x)) : e; };
    for (const Id e : incident) {
      if (rank[far_end(e)] > rank[x]) continue;
      const auto it = where[e];
      if (it != sweep.begin() && std::next(it) != sweep.end()) pairs.emplace_back(*std::prev(it), *std::next(it));
      sweep.erase(it);
    }
    for (const Id e : incident) {
      if (rank[far_end(e)] < rank[x]) continue;
      const auto it = sweep.insert(e).first;
      where[e] = it;
      if (it != sweep.begin()) pairs.emplace_back(*std::prev(it), e);
      if (std::next(it) != sweep.end()) pairs.emplace_back(e, *std::next(it));
    }
  }
  return topological_order(v.size(), pairs);
}

// A convex hull as a counter-clockwise cycle of indices into the points, keeping the points that lie on
// its edges; `flat` when all points are collinear (the cycle is then the points in order).
struct Hull {
  std::vector<std::size_t> cycle;
  bool flat;
};

// Andrew's monotone chain; the points come in (x, y) order, so this is linear.
Hull hull_of(const std::vector<Point>& p) {
  const std::size_t m = p.size();
  Hull h{{}, true};
  for (std::size_t i = 1; i + 1 < m && h.flat; ++i) h.flat = orient(p[0], p[m - 1], p[i]) == 0;
  if (h.flat) {
    h.cycle.resize(m);
    std::iota(h.cycle.begin(), h.cycle.end(), std::size_t{0});
    return h;
  }
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.cycle.size();
    for (std::size_t step = 0; step < m; ++step) {
      const std::size_t i = pass == 0 ? step : m - 1 - step;
      while (h.cycle.size() >= base + 2 &&
             orient(p[h.cycle[h.cycle.size() - 2]], p[h.cycle.back()], p[i]) < 0)
        h.cycle.pop_back();
      h.cycle.push_back(i);
    }
    h.cycle.pop_back();
  }
  return h;
}

// The hull boundary from point `from` to point `to`, clockwise (along the line for a flat hull).
std::vector<std::size_t> clockwise_path(const Hull& h, std::size_t from, std::size_t to) {
  const auto find = [&](std::size_t i) {
    const auto it = std::find(h.cycle.begin(), h.cycle.end(), i);
    if (it == h.cycle.end()) throw std::logic_error("polygon cutting: a corner of a hull region is not on its hull");
    return static_cast<std::size_t>(it - h.cycle.begin());
  };
  std::size_t at = find(from);
  const std::size_t end = find(to), m = h.cycle.size();
  std::vector<std::size_t> path{h.cycle[at]};
  while (at != end) {
    at = h.flat ? (end > at ? at + 1 : at - 1) : (at + m - 1) % m;
    path.push_back(h.cycle[at]);
  }
  return path;
}

}  // namespace

// The concrete median line: side(p) < 0 exactly for the vertices of rank below the split.
struct Cutter::Line {
  Rational mx, my, tilt;

  Rational side(const Point& p) const { return (Rational(p.x()) - mx) + tilt * (Rational(p.y()) - my); }
  QPoint crossing(const Point& p, const Point& q) const {
    const Rational sp = side(p), t = sp / (sp - side(q));
    const Rational px(p.x()), py(p.y());
    return QPoint(px + t * (Rational(q.x()) - px), py + t * (Rational(q.y()) - py));
  }
};

Cutter::Cutter(const Polygon& top)
    : top_(top), lh_(lex_order(top)), rank_(top.size()), pos_(top.size(), kNone), side_(top.size(), 0) {
  const std::size_t n = top.size();
  for (std::size_t r = 0; r < n; ++r) rank_[lh_[r]] = static_cast<std::uint32_t>(r);
  lower_x_.resize(n);
  higher_x_.resize(n);
  auto x = [&](std::size_t r) { return top[lh_[r]].x(); };
  for (std::size_t r = 0; r < n; ++r)
    lower_x_[r] = r > 0 && x(r - 1) == x(r) ? lower_x_[r - 1] : static_cast<std::int64_t>(r) - 1;
  for (std::size_t r = n; r-- > 0;)
    higher_x_[r] = r + 1 < n && x(r + 1) == x(r) ? higher_x_[r + 1] : static_cast<std::int64_t>(r) + 1;
  y_min_ = y_max_ = top[0].y();
  for (const Point& v : top.vertices()) y_min_ = std::min(y_min_, v.y()), y_max_ = std::max(y_max_, v.y());
  lv_ = vertical_order(top, lh_, rank_);
}

Part Cutter::whole() const {
  Part part{std::vector<Id>(top_.size()), lh_, lv_};
  std::iota(part.cycle.begin(), part.cycle.end(), Id{0});
  return part;
}

std::pair<Part, Part> Cutter::split(const Part& part, std::size_t i, std::size_t j) {
  const std::size_t n = part.cycle.size();
  Part first, second;
  for (std::size_t k = i;; k = (k + 1) % n) {
    first.cycle.push_back(part.cycle[k]);
    side_[part.cycle[k]] = 1;
    if (k == j) break;
  }
  for (std::size_t k = j;; k = (k + 1) % n) {
    second.cycle.push_back(part.cycle[k]);
    side_[part.cycle[k]] = k == i || k == j ? 3 : 2;
    if (k == i) break;
  }
  for (const Id v : part.lh) {
    if (side_[v] & 1) first.lh.push_back(v);
    if (side_[v] & 2) second.lh.push_back(v);
  }
  // An edge belongs to the side of its first vertex; the diagonal's ends start one edge on each side.
  for (const Id e : part.lv) (side_[e] == 1 || e == part.cycle[i] ? first : second).lv.push_back(e);
  return {std::move(first), std::move(second)};
}

void Cutter::index(const Part& part) {
  for (std::size_t k = 0; k < part.cycle.size(); ++k) pos_[part.cycle[k]] = static_cast<std::uint32_t>(k);
}

bool Cutter::edge_below(Id p, Id q, Id r, Id s) const { return below(top_.vertices(), rank_, p, q, r, s); }

Cutter::Line Cutter::median_line(std::uint32_t split) const {
  const Point& u = top_[lh_[split - 1]];
  const Point& w = top_[lh_[split]];
  if (u.x() < w.x()) return {(Rational(u.x()) + Rational(w.x())) / 2, Rational(0), Rational(0)};
  return tilted_line(u, (Rational(u.y()) + Rational(w.y())) / 2, split);
}

Cutter::Line Cutter::line_through(std::uint32_t rank) const {
  const Point& v = top_[lh_[rank]];
  const std::int64_t r = rank;
  const bool alone_on_its_vertical = lower_x_[rank] == r - 1 && higher_x_[rank] == r + 1;
  if (alone_on_its_vertical) return {Rational(v.x()), Rational(0), Rational(0)};
  return tilted_line(v, Rational(v.y()), rank);
}

// The line through (at.x, my), `rank` being a vertex with that x, tilted by a slope small enough that
// it separates every vertex off it as the (x, y) order does.
Cutter::Line Cutter::tilted_line(const Point& at, const Rational& my, std::uint32_t rank) const {
  const Rational mx(at.x());
  std::optional<Rational> gap;
  if (lower_x_[rank] >= 0) gap = mx - Rational(top_[lh_[lower_x_[rank]]].x());
  if (higher_x_[rank] < static_cast<std::int64_t>(top_.size())) {
    const Rational g = Rational(top_[lh_[higher_x_[rank]]].x()) - mx;
    if (!gap || g < *gap) gap = g;
  }
  if (!gap) throw std::logic_error("polygon cutting: all vertices on one vertical line");
  const Rational reach = std::max(Rational(y_max_) - my, my - Rational(y_min_)) + 1;
  return {mx, my, *gap / (2 * reach)};
}

std::pair<QPoint, QPoint> Cutter::chord_points(const Part& part, const Chord& chord) const {
  const Line line = chord.at_vertex ? line_through(chord.split) : median_line(chord.split);
  const std::size_t n = part.cycle.size();
  auto at = [&](std::size_t e) { return line.crossing(top_[part.cycle[e]], top_[part.cycle[(e + 1) % n]]); };
  return {at(chord.edge), chord.at_vertex ? to_exact(top_[part.cycle[chord.end]]) : at(chord.end)};
}

// Theorem 3. Nodes 0..n-1 of the boundary list are the part's vertices (by position); later nodes are
// crossings of median lines with edges. A vertex node's link runs along its edge; a crossing node's
// link runs along its edge or, once it starts a window, along the line to the other end of the window.
class SeparatorSearch {
 public:
  SeparatorSearch(const Cutter& cutter, const Part& part, const std::vector<int>& weights, CutWork& work)
      : c_(cutter), part_(part), n_(part.cycle.size()), prefix_(prefix_sums(weights)), C_(prefix_.back()),
        next_(n_), dead_(n_, 0), edge_of_(n_, kNone), entry_(n_, kNone), work_(work) {
    for (std::size_t k = 0; k < n_; ++k) next_[k] = static_cast<std::uint32_t>(succ(k));
  }

  Chord run() {
    std::vector<std::uint32_t> vertices = positions(part_.lh);
    edges_ = positions(part_.lv);
    diagonals_ = diagonal_edges();
    for (;;) {
      ++work_.levels;
      edges_ = live(edges_);
      diagonals_ = live(diagonals_);
      if (vertices.size() == 1) return half_chord(vertices[0]);
      if (vertices.size() == 0) throw std::logic_error("polygon cutting: the median-line recursion lost every vertex");
      const std::uint32_t split = rank(vertices[vertices.size() / 2 - 1]) + 1;
      const std::vector<std::uint32_t> crossing = crossing_edges(split);
      if (crossing.size() % 2 != 0) throw std::logic_error("polygon cutting: a median line meets the boundary an odd number of times");
      std::vector<std::uint32_t> nodes;
      for (const std::uint32_t e : crossing) nodes.push_back(insert_crossing(e));
      for (std::size_t t = 0; t < crossing.size(); t += 2) {
        if (dead_[nodes[t]]) continue;
        const std::int64_t forward = forward_weight(crossing[t], crossing[t + 1]);
        if (3 * forward >= C_ && 3 * forward <= 2 * C_) return {crossing[t], crossing[t + 1], false, split};
        if (3 * forward < C_)
          excise(nodes[t], nodes[t + 1]);
        else
          excise(nodes[t + 1], nodes[t]);
      }
      std::vector<std::uint32_t> left;
      for (const std::uint32_t k : vertices)
        if (!dead_[k]) left.push_back(k);
      vertices = std::move(left);
    }
  }

 private:
  std::size_t succ(std::size_t k) const { return k + 1 == n_ ? 0 : k + 1; }
  std::size_t pred(std::size_t k) const { return k == 0 ? n_ - 1 : k - 1; }
  std::int64_t weight(std::size_t k) const { return prefix_[k + 1] - prefix_[k]; }
  std::uint32_t rank(std::size_t k) const { return c_.rank_[part_.cycle[k]]; }
  bool crosses(std::size_t e, std::uint32_t split) const { return (rank(e) < split) != (rank(succ(e)) < split); }
  bool below(std::size_t e, std::size_t f) const {
    return c_.edge_below(part_.cycle[e], part_.cycle[succ(e)], part_.cycle[f], part_.cycle[succ(f)]);
  }
  bool edge_alive(std::uint32_t e) const { return !dead_[e] || (entry_[e] != kNone && !dead_[entry_[e]]); }

  std::vector<std::uint32_t> positions(const std::vector<Id>& ids) {
    std::vector<std::uint32_t> out;
    out.reserve(ids.size());
    for (const Id v : ids) out.push_back(c_.pos_[v]);
    work_.visits += static_cast<std::int64_t>(ids.size());
    return out;
  }

  std::vector<std::uint32_t> diagonal_edges() {
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < n_; ++k)
      if (part_.cycle[succ(k)] != c_.top_.next(part_.cycle[k])) out.push_back(static_cast<std::uint32_t>(k));
    work_.visits += static_cast<std::int64_t>(n_);
    return out;
  }

  std::vector<std::uint32_t> live(const std::vector<std::uint32_t>& list) {
    std::vector<std::uint32_t> out;
    for (const std::uint32_t e : list)
      if (edge_alive(e)) out.push_back(e);
    work_.visits += static_cast<std::int64_t>(list.size());
    return out;
  }

  // The live edges meeting the line, bottom first: LV's order for top edges, diagonals merged in.
  std::vector<std::uint32_t> crossing_edges(std::uint32_t split) {
    std::vector<std::uint32_t> tops, diags;
    for (const std::uint32_t e : edges_)
      if (crosses(e, split)) tops.push_back(e);
    for (const std::uint32_t d : diagonals_)
      if (crosses(d, split)) diags.push_back(d);
    work_.visits += static_cast<std::int64_t>(edges_.size() + diagonals_.size());
    if (diags.empty()) return tops;
    auto lower = [&](std::uint32_t e, std::uint32_t f) { return below(e, f); };
    std::sort(diags.begin(), diags.end(), lower);
    std::vector<std::uint32_t> all(tops.size() + diags.size());
    std::merge(tops.begin(), tops.end(), diags.begin(), diags.end(), all.begin(), lower);
    return all;
  }

  // The recursion ends with one vertex w left when no chord on a median line is fair (reconstruction
  // 4b): w is then a reflex vertex with both edges on one side, and one of its two vertical extensions,
  // to the edge below and to the edge above the wedge its edges enclose, is a fair half-chord.
  Chord half_chord(std::uint32_t w) {
    const std::uint32_t before = static_cast<std::uint32_t>(pred(w)), r = rank(w);
    const bool rightwards = rank(before) > r;
    if (rightwards != (rank(succ(w)) > r)) throw std::logic_error("polygon cutting: the last vertex is not a split vertex");
    const std::vector<std::uint32_t> crossing = crossing_edges(rightwards ? r + 1 : r);
    const auto at = [&](std::uint32_t e) {
      return static_cast<std::size_t>(std::find(crossing.begin(), crossing.end(), e) - crossing.begin());
    };
    const std::size_t lo = std::min(at(before), at(w)), hi = std::max(at(before), at(w));
    if (hi != lo + 1 || lo % 2 == 0 || hi + 1 >= crossing.size())
      throw std::logic_error("polygon cutting: the last vertex has no wedge of exterior between its edges");
    for (const std::uint32_t e : {crossing[lo - 1], crossing[hi + 1]}) {
      const std::int64_t forward = forward_weight(e, pred(w));
      if (3 * std::max(forward, C_ - forward - weight(w)) <= 2 * C_) return {e, w, true, r};
    }
    throw std::logic_error("polygon cutting: neither vertical extension of the last vertex is fair");
  }

  std::uint32_t insert_crossing(std::uint32_t e) {
    const std::uint32_t from = dead_[e] ? entry_[e] : e;
    const std::uint32_t node = static_cast<std::uint32_t>(next_.size()), after = next_[from];
    next_.push_back(after);
    dead_.push_back(0);
    edge_of_.push_back(e);
    next_[from] = node;
    ++work_.visits;
    return node;
  }

  // Unlinks the arc strictly between crossings `from` and `to` and joins them by a window.
  void excise(std::uint32_t from, std::uint32_t to) {
    std::size_t guard = next_.size();
    for (std::uint32_t u = next_[from]; u != to; u = next_[u]) {
      if (guard-- == 0) throw std::logic_error("polygon cutting: a chord's ends are not on one boundary");
      dead_[u] = 1;
      ++work_.visits;
    }
    next_[from] = to;
    entry_[edge_of_[to]] = to;
  }

  // The weight of positions a+1 .. b, the side of a chord from edge a forward to edge b.
  std::int64_t forward_weight(std::size_t a, std::size_t b) const {
    const std::int64_t from = prefix_[a + 1], to = prefix_[b + 1];
    return b >= a ? to - from : C_ - from + to;
  }

  const Cutter& c_;
  const Part& part_;
  std::size_t n_;
  std::vector<std::int64_t> prefix_;
  std::int64_t C_;
  std::vector<std::uint32_t> next_;
  std::vector<char> dead_;
  std::vector<std::uint32_t> edge_of_, entry_;
  std::vector<std::uint32_t> edges_, diagonals_;  // LV and the diagonals, restricted to live edges
  CutWork& work_;
};

// Theorem 1 from Theorem 3's separator: A inside edge a, B inside edge b (or B the vertex w). The
// concave chains h (vertices a+1 .. b, or a+1 .. w) and k (b+1 .. a, or w .. a) bound the domain of
// safety (a funnel with apex w in the second case); the walk triangulates it; the scan takes the first
// fair edge met.
class SleeveSearch {
 public:
  SleeveSearch(const Cutter& cutter, const Part& part, const std::vector<int>& weights, const Chord& chord,
               CutWork& work)
      : c_(cutter), part_(part), n_(part.cycle.size()), weights_(weights), prefix_(prefix_sums(weights)),
        C_(prefix_.back()), chord_(chord), apex_(chord.at_vertex ? chord.end : kNoVertex), work_(work) {}

  Diagonal run() {
    const std::size_t a = chord_.edge, e = chord_.end;
    const std::vector<std::size_t> h =
        chord_.at_vertex ? chain({a, succ(a), e, kNoVertex, true}) : chain({a, succ(a), e, succ(e), true});
    std::vector<std::size_t> k =
        chord_.at_vertex ? chain({kNoVertex, e, a, succ(a), false}) : chain({e, succ(e), a, succ(a), false});
    std::reverse(k.begin(), k.end());
    std::size_t t = 0, u = 0;
    while (t + 1 < h.size() || u + 1 < k.size()) {
      ++work_.visits;
      if (advance_h(h, k, t, u)) {
        if (auto d = fair(h[t], h[t + 1])) return *d;
        ++t;
      } else {
        if (auto d = fair(k[u], k[u + 1])) return *d;
        ++u;
      }
      if (t + 1 < h.size() || u + 1 < k.size())
        if (auto d = fair(h[t], k[u])) return *d;
    }
    throw std::logic_error("polygon cutting: no fair diagonal in the domain of safety");
  }

 private:
  static constexpr std::size_t kNoVertex = ~std::size_t{0};

  // One side of the separator: its vertices s .. t, the edge (tail, s) holding one end of the chord and
  // the edge (t, head) the other; a missing tail or head means s or t is the apex. `s_on_a`: whether
  // the end on (tail, s) is A.
  struct Side {
    std::size_t tail, s, t, head;
    bool s_on_a;
  };

  std::size_t succ(std::size_t k) const { return k + 1 == n_ ? 0 : k + 1; }
  const Point& P(std::size_t k) const { return c_.top_[part_.cycle[k]]; }
  QPoint Q(std::size_t k) const { return to_exact(P(k)); }
  std::uint32_t rank(std::size_t k) const { return c_.rank_[part_.cycle[k]]; }
  bool within(const Side& sd, std::size_t k) const { return (k + n_ - sd.s) % n_ <= (sd.t + n_ - sd.s) % n_; }

  const QPoint& lid_at_s(const Side& sd) { return sd.s_on_a ? chord_ends().first : chord_ends().second; }
  const QPoint& lid_at_t(const Side& sd) { return sd.s_on_a ? chord_ends().second : chord_ends().first; }
  const std::pair<QPoint, QPoint>& chord_ends() {
    if (!ends_) ends_ = c_.chord_points(part_, chord_);
    return *ends_;
  }

  // The shortest path from s to t on this side of the separator (reconstruction 5).
  std::vector<std::size_t> chain(const Side& sd) {
    if (sd.s == sd.t) return {sd.s};
    if (sd.tail == kNoVertex || sd.head == kNoVertex) return chain_in_triangle(sd);
    if (orient(P(sd.tail), P(sd.s), P(sd.t)) <= 0) return chain_around_s(sd);
    if (orient(P(sd.s), P(sd.t), P(sd.head)) <= 0) return chain_around_t(sd);
    const Point &tail = P(sd.tail), &s = P(sd.s), &t = P(sd.t), &head = P(sd.head);
    return hull_chain(candidates(sd, [&](std::size_t k) {
                        return orient(tail, s, P(k)) >= 0 && orient(s, t, P(k)) >= 0 && orient(t, head, P(k)) >= 0;
                      }),
                      sd.s, sd.t);
  }

  // A side of a half-chord: Q1 is the triangle (A, s, w) or (w, t, A), always convex.
  std::vector<std::size_t> chain_in_triangle(const Side& sd) {
    const Point &s = P(sd.s), &t = P(sd.t);
    if (sd.tail != kNoVertex) {
      const Point& tail = P(sd.tail);
      return hull_chain(candidates(sd, [&](std::size_t k) { return orient(tail, s, P(k)) >= 0 && orient(s, t, P(k)) >= 0; }),
                        sd.s, sd.t);
    }
    const Point& head = P(sd.head);
    return hull_chain(candidates(sd, [&](std::size_t k) { return orient(s, t, P(k)) >= 0 && orient(t, head, P(k)) >= 0; }),
                      sd.s, sd.t);
  }

  // Q1 has a reflex or flat corner at s. The shortest path from the chord end A on (tail, s) to t is
  // the hull chain of A and the vertices in Q1, facing B: the tangent from A to their hull, then the
  // hull. If s is not on it, s lies under its first edge A m, and the hull chain from s to m in the
  // triangle (A, s, m) leads to it. Q1 is a dart here: the union of the triangle cut off by the line of
  // (tail, s) and the triangle (s, t, X) beyond it, so membership needs no test against A.
  std::vector<std::size_t> chain_around_s(const Side& sd) {
    const Point &tail = P(sd.tail), &s = P(sd.s), &t = P(sd.t), &head = P(sd.head);
    const std::vector<std::size_t> dart = candidates(sd, [&](std::size_t k) {
      return orient(t, head, P(k)) >= 0 && (orient(tail, s, P(k)) >= 0 || orient(s, t, P(k)) >= 0);
    });
    const Hull hull = hull_of(points(dart));
    const std::size_t m = tangent(lid_at_s(sd), dart, hull, true);
    const std::vector<std::size_t> from_m = at_positions(dart, clockwise_path(hull, m, index_in(dart, sd.t)));
    const auto at_s = std::find(from_m.begin(), from_m.end(), sd.s);
    if (at_s != from_m.end()) return {at_s, from_m.end()};
    const Point& pm = P(dart[m]);
    std::vector<std::size_t> under;
    for (const std::size_t k : dart)
      if (orient(tail, s, P(k)) >= 0 && orient(s, pm, P(k)) >= 0) under.push_back(k);
    std::vector<std::size_t> path = hull_chain(under, sd.s, dart[m]);
    path.insert(path.end(), from_m.begin() + 1, from_m.end());
    return path;
  }

  // Q1 has a reflex or flat corner at t: the mirror image of chain_around_s, around B.
  std::vector<std::size_t> chain_around_t(const Side& sd) {
    const Point &tail = P(sd.tail), &s = P(sd.s), &t = P(sd.t), &head = P(sd.head);
    const std::vector<std::size_t> dart = candidates(sd, [&](std::size_t k) {
      return orient(tail, s, P(k)) >= 0 && (orient(t, head, P(k)) >= 0 || orient(s, t, P(k)) >= 0);
    });
    const Hull hull = hull_of(points(dart));
    const std::size_t m = tangent(lid_at_t(sd), dart, hull, false);
    std::vector<std::size_t> to_m = at_positions(dart, clockwise_path(hull, index_in(dart, sd.s), m));
    const auto at_t = std::find(to_m.begin(), to_m.end(), sd.t);
    if (at_t != to_m.end()) return {to_m.begin(), at_t + 1};
    const Point& pm = P(dart[m]);
    std::vector<std::size_t> under;
    for (const std::size_t k : dart)
      if (orient(pm, t, P(k)) >= 0 && orient(t, head, P(k)) >= 0) under.push_back(k);
    const std::vector<std::size_t> path = hull_chain(under, dart[m], sd.t);
    to_m.insert(to_m.end(), path.begin() + 1, path.end());
    return to_m;
  }

  // The hull vertex next to the chord end `lid` on the hull of the points and the lid, clockwise after
  // it (after_lid) or before it: no point lies left of the line from lid to it (from it to lid); the
  // nearest on a tie. The points all lie on one side of the median line through the lid, where these
  // turns order them.
  std::size_t tangent(const QPoint& lid, const std::vector<std::size_t>& ks, const Hull& hull, bool after_lid) {
    std::size_t best = hull.cycle.front();
    for (const std::size_t i : hull.cycle) {
      ++work_.visits;
      const QPoint q = Q(ks[i]), b = Q(ks[best]);
      const int side = after_lid ? orient(lid, b, q) : orient(b, lid, q);
      if (side > 0 || (side == 0 && i != best && CGAL::collinear_are_ordered_along_line(lid, q, b))) best = i;
    }
    return best;
  }

  std::vector<Point> points(const std::vector<std::size_t>& ks) const {
    std::vector<Point> pts;
    pts.reserve(ks.size());
    for (const std::size_t k : ks) pts.push_back(P(k));
    return pts;
  }
  static std::size_t index_in(const std::vector<std::size_t>& ks, std::size_t k) {
    return static_cast<std::size_t>(std::find(ks.begin(), ks.end(), k) - ks.begin());
  }
  static std::vector<std::size_t> at_positions(const std::vector<std::size_t>& ks, std::vector<std::size_t> path) {
    for (std::size_t& i : path) i = ks[i];
    return path;
  }

  // The side's vertices that lie on its side of the separator's line (the apex, on the line, too) and
  // that `keep` accepts, in (x, y) order.
  template <class Keep>
  std::vector<std::size_t> candidates(const Side& sd, Keep keep) {
    std::vector<std::size_t> out;
    const bool left = rank(sd.tail == kNoVertex ? sd.t : sd.s) < chord_.split;
    for (const Id v : part_.lh) {
      const std::size_t k = c_.pos_[v];
      if (within(sd, k) && (k == apex_ || (rank(k) < chord_.split) == left) && keep(k)) out.push_back(k);
    }
    work_.visits += static_cast<std::int64_t>(part_.lh.size() + out.size());
    return out;
  }

  // The hull of the vertices at positions `ks`, clockwise from `from` to `to`: the chain facing the lid.
  std::vector<std::size_t> hull_chain(const std::vector<std::size_t>& ks, std::size_t from, std::size_t to) const {
    return at_positions(ks, clockwise_path(hull_of(points(ks)), index_in(ks, from), index_in(ks, to)));
  }

  // Lemma 5: whether the next triangle of the walk from diagonal (h[t], k[u]) has its apex on h.
  bool advance_h(const std::vector<std::size_t>& h, const std::vector<std::size_t>& k, std::size_t t,
                 std::size_t u) const {
    const bool more_h = t + 1 < h.size(), more_k = u + 1 < k.size();
    const Point &ht = P(h[t]), &ku = P(k[u]);
    if (!more_h || !more_k) {
      if (orient(ku, ht, P(more_h ? h[t + 1] : k[u + 1])) <= 0)
        throw std::logic_error("polygon cutting: the walk of Lemma 5 met a flat triangle");
      return more_h;
    }
    if (h[t + 1] == k[u + 1]) return true;  // the funnel's last triangle
    const Point &hn = P(h[t + 1]), &kn = P(k[u + 1]);
    const bool h_above = orient(ku, ht, hn) > 0, k_above = orient(ku, ht, kn) > 0;
    if (h_above != k_above) return h_above;
    if (h_above) {
      if (orient(ku, hn, kn) > 0) return true;
      if (orient(ht, hn, kn) > 0) return false;
    }
    throw std::logic_error("polygon cutting: the walk of Lemma 5 found no diagonal");
  }

  // The diagonal (p, q) when both its parts weigh at most 2C/3.
  std::optional<Diagonal> fair(std::size_t p, std::size_t q) const {
    ++work_.visits;
    if (succ(p) == q || succ(q) == p) return std::nullopt;
    const std::int64_t between = q > p ? prefix_[q] - prefix_[p + 1] : C_ - prefix_[p + 1] + prefix_[q];
    const std::int64_t other = C_ - between - weights_[p] - weights_[q];
    if (3 * std::max(between, other) > 2 * C_) return std::nullopt;
    return Diagonal{p, q, between, other};
  }

  const Cutter& c_;
  const Part& part_;
  std::size_t n_;
  const std::vector<int>& weights_;
  std::vector<std::int64_t> prefix_;
  std::int64_t C_;
  Chord chord_;
  std::size_t apex_;
  CutWork& work_;
  std::optional<std::pair<QPoint, QPoint>> ends_;
};

Chord Cutter::vertical_chord(const Part& part, const std::vector<int>& weights, CutWork& work) {
  index(part);
  return SeparatorSearch(*this, part, weights, work).run();
}

Diagonal Cutter::fair_diagonal(const Part& part, const std::vector<int>& weights, CutWork& work) {
  index(part);
  const Chord chord = SeparatorSearch(*this, part, weights, work).run();
  return SleeveSearch(*this, part, weights, chord, work).run();
}

}  // namespace cutting

namespace {

// C, after checking that the weights are 0/1, one per vertex, and that a fair cut is promised.
std::int64_t checked_weight(const Polygon& p, const std::vector<int>& weights) {
  if (weights.size() != p.size())
    throw std::invalid_argument(std::to_string(weights.size()) + " weights for " + std::to_string(p.size()) + " vertices");
  std::int64_t C = 0;
  for (const int w : weights) {
    if (w != 0 && w != 1) throw std::invalid_argument("a weight is " + std::to_string(w) + "; weights are 0 or 1");
    C += w;
  }
  if (const auto why = why_no_fair_cut(p.size(), C)) throw NoFairCut(*why);
  return C;
}

void report(const cutting::CutWork& work, Counters& counters) {
  counters["visits"] = work.visits;
  counters["separator_levels"] = work.levels;
}

}  // namespace

FairCut fair_cut(const Polygon& p, const std::vector<int>& weights, Counters& counters) {
  const std::int64_t C = checked_weight(p, weights);
  cutting::Cutter cutter(p);
  cutting::CutWork work;
  const cutting::Diagonal d = cutter.fair_diagonal(cutter.whole(), weights, work);
  report(work, counters);
  return {d.a, d.b, C, d.C1, d.C2};
}

VerticalCut vertical_cut(const Polygon& p, const std::vector<int>& weights, Counters& counters) {
  const std::int64_t C = checked_weight(p, weights);
  cutting::Cutter cutter(p);
  cutting::CutWork work;
  const cutting::Part whole = cutter.whole();
  const cutting::Chord chord = cutter.vertical_chord(whole, weights, work);
  const auto [A, B] = cutter.chord_points(whole, chord);
  const std::size_t last = chord.at_vertex ? p.prev(chord.end) : chord.end;
  std::int64_t C1 = 0;
  for (std::size_t k = chord.edge; k != last;) {
    k = p.next(k);
    C1 += weights[k];
  }
  report(work, counters);
  return {A, B, chord.edge, chord.end, chord.at_vertex, C, C1, C - C1 - (chord.at_vertex ? weights[chord.end] : 0)};
}

}  // namespace pd
