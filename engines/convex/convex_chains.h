// Greene's double dynamic program for convex decompositions without Steiner points: the engine shared
// by `greene-dp` (fewest pieces) and `min-ink` (least total diagonal length), which differ only in the
// Cost type (how a decomposition is weighed, and how two weights are compared).
//
// Outer program: a subproblem for every diagonal d_ak (a < k) with a reflex endpoint, and for the edge
// d_0(n-1) (the vertices are renumbered so that p_0 is reflex). Its value W(a, k) is the best
// decomposition of P_ak (the chain p_a..p_k closed by d_ak). In an optimal decomposition every diagonal
// has a reflex endpoint (removing one between two non-reflex vertices leaves a convex union, fewer
// pieces and less ink), so these subproblems suffice.
//
// Inner program: the piece R on d_ak is a convex polygon a = v_0 < v_1 < ... < v_m < v_(m+1) = k whose
// sides are edges or diagonals with a reflex endpoint, and
//     W(a, k) = min over such R of  sum over R's sides other than d_ak of  side(v_i, v_(i+1)),
// side = 0 for an edge and "the diagonal itself + W(v_i, v_(i+1))" for a diagonal. R is built as a
// chain from a: g(x, y) is the best chain ending with side x -> y, g(x, y) = side(x, y) + min g(w, x)
// over the sides w -> x that turn left or go straight at x (orient(w, x, y) >= 0). For fixed x the
// admissible w form a prefix of x's incoming sides in counter-clockwise order, growing as y advances
// (Observation 1), so a pointer and a running minimum per x serve all y: one chain program costs
// O(E_a), the sides among the vertices that a reaches. R closes at k when it is convex at k
// (orient(t, k, a) >= 0) and at a (orient(k, a, v_1) >= 0). At a non-reflex a the angle of R is part
// of p_a's, so convexity at a is automatic and one chain program gives W(a, k) for every k. At a
// reflex a, convexity at a depends on v_1, so there is one chain program per first side a -> v_1:
// O(n) programs of O(n r) each, O(n^2 r^2) over all reflex a (Greene's bound). Subproblems are solved
// for a = n-1 down to 0: every side of R lies in a subproblem with a larger left end.
//
// Exact and degenerate input: sides are edges or diagonals (never through a vertex); consecutive
// vertices of R may be collinear with their neighbours (180-degree vertices of R), and R's vertices are
// those a sees, or reaches along a straight run of sides through reflex or flat vertices. Every test is
// the exact `orient`. No general-position assumption is needed: no triangle is ever formed.
//
// Time O(n^2 r^2) (plus O(n^2) visibility from every vertex), space O(n r) for the subproblems plus the
// pieces' vertex lists.
#pragma once

#include "core/decomposition.h"
#include "engines/search/visibility.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace pd::chains {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

template <class Cost>
class Program {
  using Value = typename Cost::Value;

 public:
  Program(const Polygon& p, Cost& cost) : p_(p), n_(p.size()), cost_(cost) {}

  Decomposition run(Counters& counters) {
    Decomposition d;
    if (!renumber()) return d;
    build_links();
    for (std::uint32_t a = static_cast<std::uint32_t>(n_); a-- > 0;) solve_from(a);
    reconstruct(d);
    report(counters);
    return d;
  }

 private:
  struct Link {
    std::uint32_t lo, hi;
    bool diagonal;            // a cut when used as a side (not an edge, not d_0(n-1))
    std::uint32_t length_id;  // the Cost's segment id (diagonals)
    std::uint32_t piece_begin, piece_end;  // the best piece on it: its vertices, in pieces_
  };

  // ---- set-up ----

  bool renumber() {
    rot_ = p_.first_reflex();
    if (rot_ == n_) return false;
    reflex_.assign(n_, 0);
    for (std::uint32_t x = 0; x < n_; ++x) reflex_[x] = turn(prev_of(x), x, next_of(x)) < 0;
    return true;
  }

  const Point& pt(std::uint32_t x) const { return p_[(x + rot_) % n_]; }
  std::uint32_t original(std::uint32_t x) const { return static_cast<std::uint32_t>((x + rot_) % n_); }
  int turn(std::uint32_t a, std::uint32_t b, std::uint32_t c) const { return orient(pt(a), pt(b), pt(c)); }
  std::uint32_t prev_of(std::uint32_t x) const { return x == 0 ? static_cast<std::uint32_t>(n_ - 1) : x - 1; }
  std::uint32_t next_of(std::uint32_t x) const { return x + 1 == n_ ? 0 : x + 1; }
  std::uint32_t& link_at(std::uint32_t lo, std::uint32_t hi) { return link_of_[static_cast<std::size_t>(lo) * n_ + hi]; }
  std::uint32_t link_between(std::uint32_t lo, std::uint32_t hi) const {
    return link_of_[static_cast<std::size_t>(lo) * n_ + hi];
  }

  // Visibility from every vertex; a link for every edge and every diagonal with a reflex endpoint;
  // each vertex's incoming links (from lower indices) in counter-clockwise order.
  void build_links() {
    VisibilityGraph graph(p_);
    seen_start_.assign(n_ + 1, 0);
    std::vector<std::uint32_t> row;
    for (std::uint32_t x = 0; x < n_; ++x) {
      row.clear();
      graph.visible_from(original(x), row, visibility_triangles_);
      for (std::uint32_t u : row) seen_.push_back(static_cast<std::uint32_t>((u + n_ - rot_) % n_));
      seen_start_[x + 1] = static_cast<std::uint32_t>(seen_.size());
    }
    find_opposites();
    link_of_.assign(n_ * n_, kNone);
    incoming_start_.assign(n_ + 1, 0);
    for (std::uint32_t y = 0; y < n_; ++y) {
      for (std::uint32_t s = seen_start_[y]; s < seen_start_[y + 1]; ++s) {
        const std::uint32_t x = seen_[s];
        if (x < y && (reflex_[x] || reflex_[y] || x + 1 == y || (x == 0 && y == n_ - 1))) incoming_.push_back(new_link(x, y));
      }
      std::sort(incoming_.begin() + incoming_start_[y], incoming_.end(),
                [&](std::uint32_t l, std::uint32_t m) { return links_[l].lo < links_[m].lo; });
      incoming_start_[y + 1] = static_cast<std::uint32_t>(incoming_.size());
    }
    cost_.freeze();
    values_.assign(links_.size(), cost_.infinite());
  }

  std::uint32_t new_link(std::uint32_t x, std::uint32_t y) {
    Link l{x, y, y != x + 1 && !(x == 0 && y == n_ - 1), 0, 0, 0};
    if (l.diagonal) l.length_id = cost_.add_segment(pt(x), pt(y));
    links_.push_back(l);
    link_at(x, y) = static_cast<std::uint32_t>(links_.size() - 1);
    return link_at(x, y);
  }

  // For each reflex x and each u it sees, the vertex x sees exactly opposite u: a two-pointer sweep
  // round x (the list is in counter-clockwise order).
  void find_opposites() {
    opposite_.assign(seen_.size(), kNone);
    for (std::uint32_t x = 0; x < n_; ++x) {
      if (!reflex_[x]) continue;
      const std::uint32_t first = seen_start_[x], last = seen_start_[x + 1];
      for (std::uint32_t a = first, b = first; a < last; ++a) {
        b = std::max(b, a + 1);
        while (b < last && turn(x, seen_[a], seen_[b]) > 0) ++b;
        if (b < last && turn(x, seen_[a], seen_[b]) == 0) opposite_[a] = seen_[b], opposite_[b] = seen_[a];
      }
    }
  }

  // The vertex that reflex x sees exactly opposite u (which x sees), or kNone.
  std::uint32_t opposite(std::uint32_t x, std::uint32_t u) const {
    const auto first = seen_.begin() + seen_start_[x], last = seen_.begin() + seen_start_[x + 1];
    const auto offset = [&](std::uint32_t v) { return (v + n_ - x) % n_; };
    const auto it = std::lower_bound(first, last, u, [&](std::uint32_t a, std::uint32_t b) { return offset(a) < offset(b); });
    return opposite_[static_cast<std::size_t>(it - seen_.begin())];
  }

  // The vertex after cur on the line from prev through cur, when the line goes on inside p along a
  // side: through a reflex vertex, or a flat one reached along an edge. The index may go either way
  // (a piece's straight side through its closing vertex k runs on to lower indices).
  std::uint32_t straight_on(std::uint32_t prev, std::uint32_t cur) const {
    if (reflex_[cur]) return opposite(cur, prev);
    if (turn(prev_of(cur), cur, next_of(cur)) != 0) return kNone;
    if (prev == prev_of(cur)) return next_of(cur);
    if (prev == next_of(cur)) return prev_of(cur);
    return kNone;
  }

  // ---- one left end a ----

  // The vertices a piece with vertex a and higher vertices can have: those a sees, and those a
  // reaches along straight runs of sides. V_[0] = a; then increasing index, which is counter-clockwise
  // order round a (a vertex reached along a run has the angle of the run, and no vertex a sees lies
  // between it and the run's vertices in index order: they are cut off by the run).
  void gather(std::uint32_t a) {
    V_.assign(1, a);
    for (std::uint32_t s = seen_start_[a]; s < seen_start_[a + 1]; ++s) {
      const std::uint32_t u = seen_[s];
      if (u < a) continue;
      V_.push_back(u);
      for (std::uint32_t prev = a, cur = u, next = straight_on(prev, cur); next != kNone && next > a;
           prev = cur, cur = next, next = straight_on(prev, cur))
        V_.push_back(next);
    }
    std::sort(V_.begin() + 1, V_.end());
    position_.resize(n_, kNone);
    for (std::uint32_t i = 0; i < V_.size(); ++i) position_[V_[i]] = i;
    in_start_.assign(V_.size() + 1, 0);
    in_from_.clear();
    in_link_.clear();
    for (std::uint32_t yi = 1; yi < V_.size(); ++yi) {
      const std::uint32_t y = V_[yi];
      for (std::uint32_t e = incoming_start_[y]; e < incoming_start_[y + 1]; ++e) {
        const std::uint32_t x = links_[incoming_[e]].lo;
        if (x >= a && position_[x] != kNone) in_from_.push_back(position_[x]), in_link_.push_back(incoming_[e]);
      }
      in_start_[yi + 1] = static_cast<std::uint32_t>(in_from_.size());
    }
  }

  void solve_from(std::uint32_t a) {
    gather(a);
    g_.assign(in_from_.size(), cost_.infinite());
    pred_.assign(in_from_.size(), kNone);
    if (reflex_[a]) solve_from_reflex(a);
    else solve_from_non_reflex(a);
    for (std::uint32_t v : V_) position_[v] = kNone;
  }

  bool is_subproblem(std::uint32_t a, std::uint32_t y) const {
    const std::uint32_t l = link_between(a, y);
    return l != kNone && (links_[l].diagonal || (a == 0 && y == n_ - 1));
  }
  std::uint32_t first_side_slot(std::uint32_t yi) const {
    return in_start_[yi] < in_start_[yi + 1] && in_from_[in_start_[yi]] == 0 ? in_start_[yi] : kNone;
  }

  // One chain program from a with every first side: W(a, y) for every reflex y.
  void solve_from_non_reflex(std::uint32_t a) {
    first_side_in_g_ = true;
    start_chains(1);
    for (std::uint32_t yi = 1; yi < V_.size(); ++yi) {
      extend_to(yi, 1);
      const std::uint32_t y = V_[yi];
      if (is_subproblem(a, y)) {
        const std::uint32_t best = close_at(a, yi, 1);
        if (best == kNone) throw std::logic_error("greene: subproblem without a decomposition");
        store_piece(link_between(a, y), g_[best], best);
      }
      const std::uint32_t first = first_side_slot(yi);
      if (first != kNone) g_[first] = side(in_link_[first]);
    }
  }

  // One chain program per first side a -> s, for s in increasing order: W(a, s) is final before the
  // program from s needs it (its pieces only use first sides a -> s' with s' < s).
  void solve_from_reflex(std::uint32_t a) {
    first_side_in_g_ = false;
    best_.assign(V_.size(), cost_.infinite());
    best_piece_.assign(V_.size(), {});
    for (std::uint32_t si = 1; si < V_.size(); ++si) {
      const std::uint32_t first = first_side_slot(si);
      if (first == kNone) continue;
      finish_from_reflex(a, si);
      run_from_first_side(a, si, first);
    }
    for (std::uint32_t yi = 1; yi < V_.size(); ++yi) finish_from_reflex(a, yi);
  }

  void finish_from_reflex(std::uint32_t a, std::uint32_t yi) {
    const std::uint32_t y = V_[yi];
    if (!is_subproblem(a, y) || cost_.finite(values_[link_between(a, y)])) return;
    if (!cost_.finite(best_[yi])) throw std::logic_error("greene: subproblem without a decomposition");
    const std::uint32_t l = link_between(a, y);
    values_[l] = best_[yi];
    links_[l].piece_begin = static_cast<std::uint32_t>(pieces_.size());
    pieces_.insert(pieces_.end(), best_piece_[yi].begin(), best_piece_[yi].end());
    links_[l].piece_end = static_cast<std::uint32_t>(pieces_.size());
    ++subproblems_;
  }

  void run_from_first_side(std::uint32_t a, std::uint32_t si, std::uint32_t first) {
    ++chain_programs_;
    std::fill(g_.begin(), g_.end(), cost_.infinite());
    start_chains(si);
    g_[first] = cost_.zero();
    pred_[first] = kNone;
    const std::uint32_t s = V_[si];
    const Value first_cost = side(in_link_[first]);
    for (std::uint32_t yi = si + 1; yi < V_.size(); ++yi) {
      const std::uint32_t y = V_[yi];
      if (turn(y, a, s) < 0) break;  // the piece would be reflex at a, for y and every later vertex
      extend_to(yi, si);
      if (!is_subproblem(a, y)) continue;
      const std::uint32_t best = close_at(a, yi, si);
      if (best == kNone) continue;
      const Value total = cost_.plus(first_cost, g_[best]);
      if (cost_.less(total, best_[yi], [&](std::vector<std::uint32_t>& out) { slot_terms(best, out), side_terms(in_link_[first], out); },
                     [&](std::vector<std::uint32_t>& out) { piece_terms(best_piece_[yi], out); })) {
        best_[yi] = total;
        best_piece_[yi] = piece_of_slot(best);
      }
    }
  }

  // Every chain starts afresh from V_[from]: pointers at the first incoming side.
  void start_chains(std::uint32_t from) {
    admitted_.assign(V_.size(), 0);
    running_.assign(V_.size(), cost_.infinite());
    running_slot_.assign(V_.size(), kNone);
    for (std::uint32_t xi = from; xi < V_.size(); ++xi) admitted_[xi] = in_start_[xi];
  }

  // g for every side x -> y with x at or after V_[from] (x = a only as a first side, set elsewhere).
  void extend_to(std::uint32_t yi, std::uint32_t from) {
    for (std::uint32_t e = in_start_[yi]; e < in_start_[yi + 1]; ++e) {
      const std::uint32_t xi = in_from_[e];
      if (xi < from) continue;
      admit(xi, yi);
      if (!cost_.finite(running_[xi])) continue;
      ++chain_steps_;
      g_[e] = cost_.plus(running_[xi], side(in_link_[e]));
      pred_[e] = running_slot_[xi];
    }
  }

  // Admits x's incoming sides w -> x that turn left or go straight into x -> y.
  void admit(std::uint32_t xi, std::uint32_t yi) {
    const std::uint32_t x = V_[xi], y = V_[yi];
    std::uint32_t& next = admitted_[xi];
    for (; next < in_start_[xi + 1] && turn(V_[in_from_[next]], x, y) >= 0; ++next) {
      if (!cost_.finite(g_[next])) continue;
      const std::uint32_t candidate = next, incumbent = running_slot_[xi];
      if (cost_.less(g_[candidate], running_[xi], [&](std::vector<std::uint32_t>& out) { slot_terms(candidate, out); },
                     [&](std::vector<std::uint32_t>& out) { slot_terms(incumbent, out); })) {
        running_[xi] = g_[candidate];
        running_slot_[xi] = candidate;
      }
    }
  }

  // The best side t -> y closing a piece convex at y (orient(t, y, a) >= 0: a prefix of y's incoming
  // sides), t at or after V_[from] and t != a.
  std::uint32_t close_at(std::uint32_t a, std::uint32_t yi, std::uint32_t from) {
    const std::uint32_t y = V_[yi];
    std::uint32_t best = kNone;
    for (std::uint32_t e = in_start_[yi]; e < in_start_[yi + 1]; ++e) {
      const std::uint32_t ti = in_from_[e];
      if (ti == 0 || ti < from) continue;
      if (turn(V_[ti], y, a) < 0) break;
      if (!cost_.finite(g_[e])) continue;
      const std::uint32_t incumbent = best;
      if (best == kNone || cost_.less(g_[e], g_[best], [&](std::vector<std::uint32_t>& out) { slot_terms(e, out); },
                                      [&](std::vector<std::uint32_t>& out) { slot_terms(incumbent, out); }))
        best = e;
    }
    return best;
  }

  // ---- pieces and their terms ----

  Value side(std::uint32_t link) const {
    const Link& l = links_[link];
    return l.diagonal ? cost_.side(l.length_id, values_[link]) : cost_.zero();
  }

  // The piece's vertices a, v_1, ..., y along the chain ending with slot e.
  std::vector<std::uint32_t> piece_of_slot(std::uint32_t e) const {
    std::vector<std::uint32_t> piece;
    piece.push_back(links_[in_link_[e]].hi);
    for (std::uint32_t s = e; s != kNone; s = pred_[s]) piece.push_back(links_[in_link_[s]].lo);
    std::reverse(piece.begin(), piece.end());
    return piece;
  }

  void store_piece(std::uint32_t l, const Value& v, std::uint32_t e) {
    values_[l] = v;
    const std::vector<std::uint32_t> piece = piece_of_slot(e);
    links_[l].piece_begin = static_cast<std::uint32_t>(pieces_.size());
    pieces_.insert(pieces_.end(), piece.begin(), piece.end());
    links_[l].piece_end = static_cast<std::uint32_t>(pieces_.size());
    ++subproblems_;
  }

  // The Cost's segment ids of every diagonal a value counts: for a side, the diagonal and everything
  // in the best decomposition on its far side.
  void side_terms(std::uint32_t link, std::vector<std::uint32_t>& out) const {
    std::vector<std::uint32_t> todo{link};
    while (!todo.empty()) {
      const Link& l = links_[todo.back()];
      todo.pop_back();
      if (!l.diagonal) continue;
      out.push_back(l.length_id);
      for (std::uint32_t v = l.piece_begin; v + 1 < l.piece_end; ++v) todo.push_back(link_between(pieces_[v], pieces_[v + 1]));
    }
  }
  void slot_terms(std::uint32_t e, std::vector<std::uint32_t>& out) const {
    for (std::uint32_t s = e; s != kNone; s = pred_[s])
      if (in_from_[s] != 0 || first_side_in_g_) side_terms(in_link_[s], out);
  }
  void piece_terms(const std::vector<std::uint32_t>& piece, std::vector<std::uint32_t>& out) const {
    for (std::size_t v = 0; v + 1 < piece.size(); ++v) side_terms(link_between(piece[v], piece[v + 1]), out);
  }

  void reconstruct(Decomposition& d) const {
    std::vector<std::uint32_t> todo{link_between(0, static_cast<std::uint32_t>(n_ - 1))};
    while (!todo.empty()) {
      const Link& l = links_[todo.back()];
      todo.pop_back();
      for (std::uint32_t v = l.piece_begin; v + 1 < l.piece_end; ++v) {
        const std::uint32_t side_link = link_between(pieces_[v], pieces_[v + 1]);
        if (!links_[side_link].diagonal) continue;
        d.add_cut(original(pieces_[v]), original(pieces_[v + 1]));
        todo.push_back(side_link);
      }
    }
  }

  void report(Counters& counters) const {
    counters["subproblems"] = subproblems_;
    counters["chain_programs"] = chain_programs_;
    counters["chain_steps"] = chain_steps_;
    counters["links"] = static_cast<std::int64_t>(links_.size());
    counters["visibility_triangles"] = visibility_triangles_;
    cost_.report(counters);
  }

  const Polygon& p_;
  std::size_t n_;
  Cost& cost_;
  std::size_t rot_ = 0;
  std::vector<char> reflex_;
  std::vector<std::uint32_t> seen_, seen_start_, opposite_;  // visibility lists, counter-clockwise
  std::vector<std::uint32_t> link_of_;                 // n x n, lo < hi
  std::vector<Link> links_;
  std::vector<Value> values_;
  std::vector<std::uint32_t> incoming_, incoming_start_;
  std::vector<std::uint32_t> pieces_;
  // One left end a at a time:
  std::vector<std::uint32_t> V_, position_, in_start_, in_from_, in_link_, pred_, admitted_, running_slot_;
  std::vector<Value> g_, running_, best_;
  std::vector<std::vector<std::uint32_t>> best_piece_;
  bool first_side_in_g_ = true;
  std::int64_t subproblems_ = 0, chain_programs_ = 0, chain_steps_ = 0, visibility_triangles_ = 0;
};

}  // namespace pd::chains
