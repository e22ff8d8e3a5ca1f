// Keil's dynamic program for the minimum convex decomposition without Steiner points, with narrowest
// pairs (Keil & Snoeyink, 001, Sec. 3): the engine shared by `keil` (pairs kept in a search structure)
// and `keil-snoeyink` (pairs kept in stacks S and T, Algorithm 1), which differ only in the Query type
// that answers "the last pair that keeps p_j convex".
//
// Subproblems (Sec. 3.1): every diagonal d_ik (i < k) with a reflex endpoint, plus the edge d_0(n-1)
// with p_0 reflex (the vertices are renumbered so). w_ik is the least number of diagonals in a convex
// decomposition of P_ik (the chain p_i..p_k closed by d_ik); the narrowest pairs (s, t) say which
// diagonals or edges d_is and d_tk bound the piece on d_ik in the minimum decompositions whose piece is
// not contained, near d_ik, in another's. Fronts of pairs are kept in increasing order of s (and so of
// t): the stack S_ik reads them from the top, T_ik from the bottom (one array, two pointers).
//
// Solving P_ik (Sec. 3.2): with p_i reflex, TypeA(i, j, k) uses d_jk and merges the piece on d_ij
// (a pair popped from T_ij) or cuts d_ij; with p_i not reflex (so p_k reflex), TypeB(i, j, k) uses d_ij
// and merges the piece on d_jk (a pair popped from S_jk) or cuts d_jk. TypeA(i, j, k) runs for
// increasing k at fixed (i, j), TypeB(i, j, k) for decreasing i at fixed (j, k), so a pair popped
// because it is wider than a later pair that keeps p_j convex is never needed again (proof of
// Theorem 2). Deviation: Algorithm 1 solves by size; here left ends go down and right ends up, an
// order with the same two properties that keeps each left end's fronts together in memory.
//
// Degenerate input: the paper assumes that a piece's triangle (i, j, k) next to d_ik is never flat.
// With collinear vertices (180-degree vertices, a vertex on the extension of an edge or a diagonal) two
// things happen that the paper's cases miss, and this engine adds exactly two cases for them:
//  1. A straight side of a piece through further vertices (i, v1, .., t collinear): the piece's side
//     from i to t is several edges and diagonals in a row, not one diagonal. Such "chains" are links
//     like diagonals (built once from the visibility lists, O(n r) of them); a chain is only ever cut,
//     never merged, and its weight is the sum over its parts. TypeA takes a chain for d_ij, TypeB for
//     d_jk.
//  2. A piece whose angle at p_k is exactly 180 degrees (its side before k continues d_ik beyond k): no
//     triangle (i, t, k) exists. Then p_k is reflex (or p_k is p_(n-1) and flat, which is therefore
//     made a subproblem endpoint as well), the piece is R' + triangle (i, j, k) + F for its last vertex
//     j off the line of d_ik, and F is a piece on d_jk in P_jk whose pair ends at t*, the vertex that
//     k sees exactly opposite i. TypeAFlat(i, j, k) looks F up in P_jk's front and R' in P_ij's front
//     by binary search. Such a piece can never be merged into a larger one (its angle at k is already
//     180 degrees), so it contributes only its weight: when it is strictly lighter, the front of P_ik
//     is emptied and the piece is remembered for reconstruction. In general position TypeAFlat never
//     runs, and the bound stays O(n r^2); in degenerate input each TypeAFlat costs O(log n).
// Pieces may have 180-degree vertices; every convexity test is the exact `orient(...) >= 0`.
//
// Time O(n r^2) plus the visibility lists (O(n log n) + O(n r), visibility.h); space O(n r) for the
// link table and O(n r^2) for the fronts in the worst case.
#pragma once

#include "core/decomposition.h"
#include "engines/search/visibility.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace pd::narrowest {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::int32_t kNoLink = -1;
constexpr std::int32_t kPlainEdge = -2;  // an edge between two non-special vertices: weight -1, no data
constexpr std::int32_t kInfinite = std::numeric_limits<std::int32_t>::max();

enum class How : std::uint8_t { kMergeA, kCutA, kMergeB, kCutB };

// A narrowest pair (s, t) of a subproblem's front and how it was made: j is t for TypeA, s for TypeB;
// `child` is the merged pair's index in the pool (merges only).
struct Pair {
  std::uint32_t s, t;
  std::uint32_t child;
  How how;
};

enum class LinkKind : std::uint8_t { kEdge, kDiagonal, kChain, kRoot };

// An edge, diagonal or chain between lo < hi with a special endpoint. Diagonals (and the root) are
// subproblems: weight and front (in Solved, kept apart because the combination steps read little
// else) and, when a 180-degree piece wins, `flat`.
struct Link {
  std::uint32_t lo, hi;
  std::uint32_t first, last;        // chains: the vertex after lo and the vertex before hi
  std::uint32_t opp_lo, opp_hi;     // real links: the vertex seen from lo (hi) exactly opposite hi (lo)
  std::int32_t part_a, part_b;      // chains: the two links it is made of, lo side first
  std::int32_t flat;
};

struct Solved {
  std::int32_t weight;
  std::uint32_t front_begin, front_end;
  LinkKind kind;
};

// A 180-degree piece: F (a pair of P_jk) plus the triangle (i, j, k), plus a merged pair of P_ij or a
// cut of d_ij (merged == kNone).
struct FlatPiece {
  std::uint32_t j, f_pair, merged;
};

struct Stats {
  std::int64_t type_a = 0, type_b = 0, type_a_flat = 0, pushes = 0, pops = 0, visibility_triangles = 0;
};

template <class Query>
class Program {
 public:
  explicit Program(const Polygon& p) : p_(p), n_(p.size()) {}

  Decomposition run(Counters& counters) {
    Decomposition d;
    if (!renumber()) return d;
    build_links();
    build_chains();
    solve_subproblems();
    reconstruct(d);
    report(counters);
    return d;
  }

 private:
  // ---- renumbering and links ----

  // Vertex 0 of the program is a reflex vertex of p (Sec. 3.2); false when p has none (p is convex).
  bool renumber() {
    rot_ = p_.first_reflex();
    if (rot_ == n_) return false;
    reflex_.assign(n_, 0);
    special_.assign(n_, 0);
    for (std::uint32_t x = 0; x < n_; ++x) {
      const int turn = orient(pt(x == 0 ? n_ - 1 : x - 1), pt(x), pt(x + 1 == n_ ? 0 : x + 1));
      reflex_[x] = turn < 0;
      special_[x] = turn < 0 || (x == n_ - 1 && turn == 0);
      if (reflex_[x]) reflex_list_.push_back(x);
      if (special_[x]) rank_.push_back(x);
    }
    rank_of_.assign(n_, kNone);
    for (std::uint32_t r = 0; r < rank_.size(); ++r) rank_of_[rank_[r]] = r;
    return true;
  }

  const Point& pt(std::uint32_t x) const { return p_[(x + rot_) % n_]; }
  std::uint32_t original(std::uint32_t x) const { return static_cast<std::uint32_t>((x + rot_) % n_); }
  std::int32_t& row(std::uint32_t special_vertex, std::uint32_t u) {
    return rows_[static_cast<std::size_t>(rank_of_[special_vertex]) * n_ + u];
  }
  std::int32_t row_at(std::uint32_t special_vertex, std::uint32_t u) const {
    return rows_[static_cast<std::size_t>(rank_of_[special_vertex]) * n_ + u];
  }

  // One link per edge or diagonal with a special endpoint, shared by both endpoints' rows; the
  // opposite vertices by a two-pointer sweep round each special vertex (Observation 1).
  void build_links() {
    VisibilityGraph graph(p_);
    rows_.assign(rank_.size() * n_, kNoLink);
    std::vector<std::uint32_t> seen;
    for (std::uint32_t x : rank_) {
      seen.clear();
      graph.visible_from(original(x), seen, stats_.visibility_triangles);
      for (std::uint32_t& u : seen) u = static_cast<std::uint32_t>((u + n_ - rot_) % n_);
      for (std::uint32_t u : seen) {
        std::int32_t id = special_[u] && row(u, x) != kNoLink ? row(u, x) : new_real_link(x, u);
        row(x, u) = id;
      }
      set_opposites(x, seen);
      visible_count_ += seen.size();
    }
  }

  std::int32_t new_real_link(std::uint32_t a, std::uint32_t b) {
    Link l{};
    l.lo = std::min(a, b), l.hi = std::max(a, b);
    const bool edge = l.hi == l.lo + 1 || (l.lo == 0 && l.hi == n_ - 1);
    l.first = l.hi, l.last = l.lo;
    l.opp_lo = l.opp_hi = kNone;
    l.part_a = l.part_b = kNoLink;
    l.flat = -1;
    links_.push_back(l);
    solved_.push_back({edge ? -1 : kInfinite, 0, 0, edge ? LinkKind::kEdge : LinkKind::kDiagonal});
    return static_cast<std::int32_t>(links_.size() - 1);
  }

  void set_opposites(std::uint32_t x, const std::vector<std::uint32_t>& ccw) {
    std::size_t b = 0;
    for (std::size_t a = 0; a < ccw.size(); ++a) {
      b = std::max(b, a + 1);
      while (b < ccw.size() && orient(pt(x), pt(ccw[a]), pt(ccw[b])) > 0) ++b;
      if (b < ccw.size() && orient(pt(x), pt(ccw[a]), pt(ccw[b])) == 0) {
        opposite_slot(x, ccw[a]) = ccw[b];
        opposite_slot(x, ccw[b]) = ccw[a];
      }
    }
  }

  std::uint32_t& opposite_slot(std::uint32_t x, std::uint32_t u) {
    Link& l = links_[row(x, u)];
    return l.lo == x ? l.opp_lo : l.opp_hi;
  }
  // The vertex that special x sees exactly opposite u, or kNone.
  std::uint32_t opposite(std::uint32_t x, std::uint32_t u) const {
    const std::int32_t id = row_at(x, u);
    if (id < 0) return kNone;
    const Link& l = links_[id];
    return l.lo == x ? l.opp_lo : l.opp_hi;
  }

  // The edge or diagonal between a < b (not a chain), or kNoLink.
  std::int32_t real_link(std::uint32_t a, std::uint32_t b) const {
    std::int32_t id = kNoLink;
    if (special_[b]) id = row_at(b, a);
    else if (special_[a]) id = row_at(a, b);
    if (id >= 0 && solved_[id].kind == LinkKind::kChain) return kNoLink;
    if (id == kNoLink && b == a + 1) return kPlainEdge;
    return id;
  }

  // ---- chains: straight runs of links through reflex or flat vertices ----

  // The vertex after `cur` on the straight line from `prev` through `cur`, on the index side given by
  // `forward`, when the line continues inside p along an edge or a diagonal; else kNone. Only a vertex
  // whose angle is at least 180 degrees lets a straight line through: a reflex vertex (its opposite
  // vertex), or a flat vertex reached along an edge (the next edge).
  std::uint32_t straight_on(std::uint32_t prev, std::uint32_t cur, bool forward) const {
    std::uint32_t next = kNone;
    if (reflex_[cur]) {
      next = opposite(cur, prev);
    } else if (orient(pt(prev_of(cur)), pt(cur), pt(next_of(cur))) == 0) {
      if (forward && prev + 1 == cur && cur + 1 < n_) next = cur + 1;
      if (!forward && cur + 1 == prev && cur > 0) next = cur - 1;
    }
    if (next == kNone || (forward ? next <= cur : next >= cur)) return kNone;
    return next;
  }
  std::uint32_t prev_of(std::uint32_t x) const { return x == 0 ? static_cast<std::uint32_t>(n_ - 1) : x - 1; }
  std::uint32_t next_of(std::uint32_t x) const { return x + 1 == n_ ? 0 : x + 1; }

  // Chains from each special vertex x: forward ones (x < the far end) for TypeA's d_ij, backward ones
  // for TypeB's d_jk, each stored in x's row.
  void build_chains() {
    std::vector<std::uint32_t> starts;
    for (std::uint32_t x : rank_) {
      starts.clear();
      for (std::uint32_t u = 0; u < n_; ++u)
        if (row(x, u) >= 0) starts.push_back(u);
      for (std::uint32_t u : starts) extend_chain(x, u, u > x);
    }
  }

  void extend_chain(std::uint32_t x, std::uint32_t u, bool forward) {
    std::int32_t so_far = row(x, u);
    std::uint32_t prev = x, cur = u;
    for (std::uint32_t next = straight_on(prev, cur, forward); next != kNone; next = straight_on(prev, cur, forward)) {
      const std::int32_t piece = forward ? real_link(cur, next) : real_link(next, cur);
      Link c{};
      c.opp_lo = c.opp_hi = kNone;
      c.flat = -1;
      if (forward) {
        c.lo = x, c.hi = next, c.first = u, c.last = cur, c.part_a = so_far, c.part_b = piece;
      } else {
        c.lo = next, c.hi = x, c.first = cur, c.last = u, c.part_a = piece, c.part_b = so_far;
      }
      links_.push_back(c);
      solved_.push_back({kInfinite, 0, 0, LinkKind::kChain});
      ++chains_;
      so_far = static_cast<std::int32_t>(links_.size() - 1);
      row(x, next) = so_far;
      prev = cur, cur = next;
    }
  }

  // A chain's weight is the sum over its parts, each cut: computed on first use, when its parts are
  // solved (they lie inside the subproblem that uses the chain).
  std::int32_t weight(std::int32_t id) {
    if (id == kPlainEdge) return -1;
    if (solved_[id].kind != LinkKind::kChain || solved_[id].weight != kInfinite) return solved_[id].weight;
    std::vector<std::int32_t> spine;  // chains whose weight waits for the next one's
    for (std::int32_t c = id; c >= 0 && solved_[c].kind == LinkKind::kChain && solved_[c].weight == kInfinite;
         c = rest_of_chain(c))
      spine.push_back(c);
    for (auto c = spine.rbegin(); c != spine.rend(); ++c)
      solved_[*c].weight = weight(links_[*c].part_a) + weight(links_[*c].part_b) + 1;
    return solved_[id].weight;
  }
  // The part of a chain that may itself be a chain (the other is one edge or diagonal).
  std::int32_t rest_of_chain(std::int32_t c) const {
    const Link& l = links_[c];
    return l.part_a >= 0 && solved_[l.part_a].kind == LinkKind::kChain ? l.part_a : l.part_b;
  }
  bool has_front(std::int32_t id) const {
    return id >= 0 && (solved_[id].kind == LinkKind::kDiagonal || solved_[id].kind == LinkKind::kRoot);
  }
  std::uint32_t first_of(std::int32_t id, std::uint32_t hi) const {
    return id >= 0 && solved_[id].kind == LinkKind::kChain ? links_[id].first : hi;
  }
  std::uint32_t last_of(std::int32_t id, std::uint32_t lo) const {
    return id >= 0 && solved_[id].kind == LinkKind::kChain ? links_[id].last : lo;
  }

  // ---- the dynamic program ----

  // Algorithm 1 solves subproblems by size. Any order that solves P_ij and P_jk before P_ik, calls
  // TypeA(i, j, k) for increasing k at fixed (i, j) and TypeB(i, j, k) for decreasing i at fixed
  // (j, k) keeps the proof of Theorem 2 (a popped pair is never needed again); this one, left ends
  // from the last vertex down and right ends upwards, also keeps all fronts of one left end next to
  // each other in memory, where TypeA reads them.
  void solve_subproblems() {
    query_.reserve(links_.size() + 1);
    for (std::uint32_t i = static_cast<std::uint32_t>(n_); i-- > 0;) {
      if (reflex_[i]) {
        for (std::uint32_t k = i + 2; k < n_; ++k) {
          if (i == 0 && k == n_ - 1) {
            solve_type_a(make_root());
          } else {
            const std::int32_t id = row(i, k);
            if (id >= 0 && solved_[id].kind == LinkKind::kDiagonal) solve_type_a(id);
          }
        }
      } else {
        for (std::uint32_t k : rank_) {
          if (k <= i + 1) continue;
          const std::int32_t id = row(k, i);
          if (id >= 0 && solved_[id].kind == LinkKind::kDiagonal) solve_type_b(id);
        }
      }
    }
  }

  std::int32_t make_root() {
    root_ = new_real_link(0, static_cast<std::uint32_t>(n_ - 1));
    solved_[root_] = {kInfinite, 0, 0, LinkKind::kRoot};
    solved_[root_].weight = kInfinite;
    return root_;
  }

  // The front of the subproblem being solved: the pairs of least weight so far, at the pool's end.
  struct Builder {
    std::size_t begin;
    std::int32_t best = kInfinite;
    std::int32_t flat_best = kInfinite;
    FlatPiece flat{};
  };

  // Keeps the lighter; among equals, TypeA's pairs arrive with increasing t = j, so the new pair is
  // dropped when the top is at least as narrow at p_i.
  void offer_a(Builder& b, std::int32_t w, std::uint32_t s, std::uint32_t j, How how, std::uint32_t child) {
    if (!lighter_or_equal(b, w)) return;
    if (pool_.size() > b.begin && pool_.back().s >= s) return;
    push(s, j, how, child);
  }
  // TypeB's pairs arrive with increasing s = j: the new pair pops those no narrower at p_k.
  void offer_b(Builder& b, std::int32_t w, std::uint32_t j, std::uint32_t t, How how, std::uint32_t child) {
    if (!lighter_or_equal(b, w)) return;
    while (pool_.size() > b.begin && pool_.back().t >= t) pool_.pop_back(), ++stats_.pops;
    push(j, t, how, child);
  }
  bool lighter_or_equal(Builder& b, std::int32_t w) {
    if (w > b.best) return false;
    if (w < b.best) {
      stats_.pops += static_cast<std::int64_t>(pool_.size() - b.begin);
      pool_.resize(b.begin);
      b.best = w;
    }
    return true;
  }
  void push(std::uint32_t s, std::uint32_t t, How how, std::uint32_t child) {
    pool_.push_back({s, t, child, how});
    ++stats_.pushes;
  }

  void solve_type_a(std::int32_t id) {
    const std::uint32_t i = links_[id].lo, k = links_[id].hi;
    Builder b{pool_.size()};
    std::uint32_t t_star = special_[k] ? opposite(k, i) : kNone;
    if (t_star != kNone && (t_star <= i || t_star >= k)) t_star = kNone;
    auto each_j = [&](std::uint32_t j) {
      const std::int32_t ij = row(i, j), jk = real_link(j, k);
      if (ij == kNoLink || jk == kNoLink) return;
      type_a(b, i, j, k, ij, jk);
      if (t_star != kNone && j < t_star) type_a_flat(b, i, j, k, ij, jk, t_star);
    };
    if (special_[k]) {
      for (std::uint32_t j = i + 1; j < k; ++j) each_j(j);
    } else {
      for (auto it = std::upper_bound(reflex_list_.begin(), reflex_list_.end(), i);
           it != reflex_list_.end() && *it < k - 1; ++it)
        each_j(*it);
      each_j(k - 1);
    }
    finish(id, b);
  }

  void solve_type_b(std::int32_t id) {
    const std::uint32_t i = links_[id].lo, k = links_[id].hi;
    Builder b{pool_.size()};
    auto each_j = [&](std::uint32_t j) {
      const std::int32_t ij = real_link(i, j), jk = row(k, j);
      if (ij == kNoLink || jk == kNoLink) return;
      type_b(b, i, j, k, ij, jk);
    };
    each_j(i + 1);
    for (auto it = std::upper_bound(reflex_list_.begin(), reflex_list_.end(), i + 1);
         it != reflex_list_.end() && *it < k; ++it)
      each_j(*it);
    finish(id, b);
  }

  // TypeA(i, j, k): d_jk is used; the piece on d_ij merges with the triangle (i, j, k) when the last
  // pair of T_ij that keeps p_j convex also keeps p_i convex; otherwise d_ij is cut.
  void type_a(Builder& b, std::uint32_t i, std::uint32_t j, std::uint32_t k, std::int32_t ij, std::int32_t jk) {
    ++stats_.type_a;
    const std::int32_t w = weight(ij) + weight(jk);
    if (has_front(ij)) {
      const Solved& l = solved_[ij];
      const std::uint32_t q = query_.last_keeping_a(ij, pool_, l.front_begin, l.front_end, [&](const Pair& c) {
        return orient(pt(c.t), pt(j), pt(k)) >= 0;
      });
      if (q != kNone && orient(pt(k), pt(i), pt(pool_[q].s)) >= 0) return offer_a(b, w + 1, pool_[q].s, j, How::kMergeA, q);
    }
    offer_a(b, w + 2, first_of(ij, j), j, How::kCutA, kNone);
  }

  // TypeB(i, j, k): d_ij is used; the piece on d_jk merges with the triangle (i, j, k) when the last
  // pair of S_jk that keeps p_j convex also keeps p_k convex; otherwise d_jk is cut.
  void type_b(Builder& b, std::uint32_t i, std::uint32_t j, std::uint32_t k, std::int32_t ij, std::int32_t jk) {
    ++stats_.type_b;
    const std::int32_t w = weight(ij) + weight(jk);
    if (has_front(jk)) {
      const Solved& l = solved_[jk];
      const std::uint32_t q = query_.last_keeping_b(jk, pool_, l.front_begin, l.front_end, [&](const Pair& c) {
        return orient(pt(i), pt(j), pt(c.s)) >= 0;
      });
      if (q != kNone && orient(pt(pool_[q].t), pt(k), pt(i)) >= 0) return offer_b(b, w + 1, j, pool_[q].t, How::kMergeB, q);
    }
    offer_b(b, w + 2, j, last_of(jk, j), How::kCutB, kNone);
  }

  // TypeAFlat(i, j, k): the piece R' + triangle (i, j, k) + F with F's side t* -> k continuing d_ik, so
  // that the piece is flat at p_k. F is P_jk's pair ending at t*; R' is P_ij's narrowest pair keeping
  // p_j convex next to F (found by binary search: these calls do not follow T_ij's order), or d_ij
  // is cut.
  void type_a_flat(Builder& b, std::uint32_t i, std::uint32_t j, std::uint32_t k, std::int32_t ij, std::int32_t jk,
                   std::uint32_t t_star) {
    if (!has_front(jk)) return;
    ++stats_.type_a_flat;
    const Solved& f_link = solved_[jk];
    const auto f_first = pool_.begin() + f_link.front_begin, f_last = pool_.begin() + f_link.front_end;
    const auto f = std::lower_bound(f_first, f_last, t_star, [](const Pair& c, std::uint32_t t) { return c.t < t; });
    if (f == f_last || f->t != t_star) return;
    const std::uint32_t x = f->s, f_index = static_cast<std::uint32_t>(f - pool_.begin());
    const std::int32_t w = weight(ij) + weight(jk);
    if (orient(pt(i), pt(j), pt(x)) >= 0) offer_flat(b, w + 1, {j, f_index, kNone});
    if (!has_front(ij)) return;
    const Solved& l = solved_[ij];
    const auto r_first = pool_.begin() + l.front_begin, r_last = pool_.begin() + l.front_end;
    const auto r = std::partition_point(r_first, r_last, [&](const Pair& c) { return orient(pt(c.t), pt(j), pt(x)) >= 0; });
    if (r == r_first || orient(pt(k), pt(i), pt((r - 1)->s)) < 0) return;
    offer_flat(b, w, {j, f_index, static_cast<std::uint32_t>(r - 1 - pool_.begin())});
  }

  void offer_flat(Builder& b, std::int32_t w, FlatPiece piece) {
    if (w < b.flat_best) b.flat_best = w, b.flat = piece;
  }

  void finish(std::int32_t id, Builder& b) {
    Solved& l = solved_[id];
    if (b.flat_best < b.best) {
      stats_.pops += static_cast<std::int64_t>(pool_.size() - b.begin);
      pool_.resize(b.begin);
      l.weight = b.flat_best;
      links_[id].flat = static_cast<std::int32_t>(flats_.size());
      flats_.push_back(b.flat);
    } else {
      l.weight = b.best;
    }
    if (l.weight == kInfinite) throw std::logic_error("narrowest pairs: subproblem without a decomposition");
    l.front_begin = static_cast<std::uint32_t>(b.begin);
    l.front_end = static_cast<std::uint32_t>(pool_.size());
    query_.complete(id, l.front_begin, l.front_end);
    ++subproblems_;
  }

  // ---- reconstruction ----

  struct Task {
    enum Kind : std::uint8_t { kLink, kAny, kPair } kind;
    std::int32_t link;
    std::uint32_t pair;
  };

  void reconstruct(Decomposition& d) {
    std::vector<Task> todo{{Task::kAny, root_, 0}};
    while (!todo.empty()) {
      const Task task = todo.back();
      todo.pop_back();
      if (task.kind == Task::kLink) emit_link(d, task.link, todo);
      else if (task.kind == Task::kAny) expand_any(task.link, todo);
      else expand_pair(task.link, task.pair, todo);
    }
  }

  void emit_link(Decomposition& d, std::int32_t id, std::vector<Task>& todo) {
    if (id == kPlainEdge) return;
    const Link& l = links_[id];
    if (solved_[id].kind == LinkKind::kDiagonal) {
      d.add_cut(original(l.lo), original(l.hi));
      todo.push_back({Task::kAny, id, 0});
    } else if (solved_[id].kind == LinkKind::kChain) {
      todo.push_back({Task::kLink, l.part_a, 0});
      todo.push_back({Task::kLink, l.part_b, 0});
    }
  }

  void expand_any(std::int32_t id, std::vector<Task>& todo) {
    const Link& l = links_[id];
    const Solved& solved = solved_[id];
    if (solved.front_begin < solved.front_end) return todo.push_back({Task::kPair, id, solved.front_begin});
    const FlatPiece& f = flats_[l.flat];
    todo.push_back({Task::kPair, real_link(f.j, l.hi), f.f_pair});
    if (f.merged == kNone) todo.push_back({Task::kLink, row(l.lo, f.j), 0});
    else todo.push_back({Task::kPair, row(l.lo, f.j), f.merged});
  }

  void expand_pair(std::int32_t id, std::uint32_t index, std::vector<Task>& todo) {
    const std::uint32_t i = links_[id].lo, k = links_[id].hi;
    const Pair& q = pool_[index];
    switch (q.how) {
      case How::kMergeA:
        todo.push_back({Task::kLink, real_link(q.t, k), 0});
        todo.push_back({Task::kPair, row(i, q.t), q.child});
        break;
      case How::kCutA:
        todo.push_back({Task::kLink, row(i, q.t), 0});
        todo.push_back({Task::kLink, real_link(q.t, k), 0});
        break;
      case How::kMergeB:
        todo.push_back({Task::kLink, real_link(i, q.s), 0});
        todo.push_back({Task::kPair, row(k, q.s), q.child});
        break;
      case How::kCutB:
        todo.push_back({Task::kLink, real_link(i, q.s), 0});
        todo.push_back({Task::kLink, row(k, q.s), 0});
        break;
    }
  }

  void report(Counters& counters) const {
    counters["subproblems"] = subproblems_;
    counters["type_a"] = stats_.type_a;
    counters["type_b"] = stats_.type_b;
    counters["type_a_flat"] = stats_.type_a_flat;
    counters["pair_pushes"] = stats_.pushes;
    counters["pair_pops"] = stats_.pops;
    counters["chains"] = chains_;
    counters["visible_pairs"] = visible_count_;
    counters["visibility_triangles"] = stats_.visibility_triangles;
    counters["pieces"] = solved_[root_].weight + 1;
    query_.report(counters);
  }

  const Polygon& p_;
  std::size_t n_;
  std::size_t rot_ = 0;
  std::vector<char> reflex_, special_;
  std::vector<std::uint32_t> reflex_list_, rank_, rank_of_;
  std::vector<std::int32_t> rows_;
  std::vector<Link> links_;
  std::vector<Solved> solved_;  // parallel to links_
  std::vector<Pair> pool_;
  std::vector<FlatPiece> flats_;
  std::int32_t root_ = kNoLink;
  Query query_;
  Stats stats_;
  std::int64_t subproblems_ = 0, visible_count_ = 0, chains_ = 0;
};

}  // namespace pd::narrowest
