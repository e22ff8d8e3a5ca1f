// The triangulation of the monotone pieces, and the `monotone` triangulation built on it (its paper,
// bounds and guarantees: algorithms/monotone.cpp); declarations in monotone.h.
//
// The pieces of the partition are found by walking the faces of the plane graph of edges and
// diagonals (each vertex's half-edges sorted around it). Each piece is monotone in the sweep order
// `above`; its two chains are merged top to bottom and triangulated with a stack holding the reflex
// chain not yet triangulated (the slides' cases 1-3). A diagonal is drawn along the stack's own chain
// only when it turns strictly left (orient > 0), so a flat vertex stays on the stack (the slides'
// "reflex or flat") and no triangle is degenerate.
#include "engines/triangulation/monotone.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace pd {
namespace {

// The plane graph of the polygon's edges and the diagonals, as each vertex's outgoing half-edges in
// counter-clockwise order: first v -> next(v), then the diagonals round the interior angle, last
// v -> prev(v). The face to the left of half-edge u -> w continues along the half-edge just before
// w -> u in w's order.
class Rotation {
 public:
  Rotation(const Polygon& p, const std::vector<Cut>& diagonals) : p_(p), start_(p.size() + 1, 0) {
    const std::uint32_t n = static_cast<std::uint32_t>(p.size());
    for (std::uint32_t v = 0; v < n; ++v) start_[v + 1] = 2;
    for (const Cut& c : diagonals) ++start_[c.a + 1], ++start_[c.b + 1];
    for (std::uint32_t v = 0; v < n; ++v) start_[v + 1] += start_[v];
    target_.resize(start_[n]);
    twin_.resize(start_[n]);
    place_diagonals(diagonals);
    for (std::uint32_t v = 0; v < n; ++v) {
      target_[start_[v]] = static_cast<std::uint32_t>(p.next(v));
      target_[last(v)] = static_cast<std::uint32_t>(p.prev(v));
      twin_[start_[v]] = last(p.next(v));
      twin_[last(v)] = start_[p.prev(v)];
    }
  }

  std::uint32_t first(std::uint32_t v) const { return start_[v]; }
  std::uint32_t last(std::size_t v) const { return start_[v + 1] - 1; }
  std::uint32_t target(std::uint32_t h) const { return target_[h]; }
  std::uint32_t next_in_face(std::uint32_t h) const { return twin_[h] - 1; }
  std::size_t half_edges() const { return target_.size(); }

 private:
  // Each diagonal's two half-edges go into the middle of their rows, which are then sorted by angle.
  // A half-edge remembers its diagonal end as 2k (at end a of diagonal k) or 2k+1 (at end b), so that
  // pairing the twins reads no diagonal again.
  void place_diagonals(const std::vector<Cut>& diagonals) {
    const std::size_t n = p_.size();
    std::vector<std::uint32_t> fill(n), end_of(target_.size());
    for (std::size_t v = 0; v < n; ++v) fill[v] = start_[v] + 1;
    for (std::uint32_t k = 0; k < diagonals.size(); ++k) {
      const Cut& c = diagonals[k];
      target_[fill[c.a]] = c.b, end_of[fill[c.a]++] = 2 * k;
      target_[fill[c.b]] = c.a, end_of[fill[c.b]++] = 2 * k + 1;
    }
    std::vector<std::uint32_t> slot(2 * diagonals.size());  // slot[2k]: at end a, slot[2k+1]: at end b
    std::vector<std::pair<std::uint32_t, std::uint32_t>> row;
    for (std::uint32_t v = 0; v < n; ++v) {
      const std::uint32_t begin = start_[v] + 1, end = last(v);
      if (end - begin > 1) sort_row(v, begin, end, end_of, row);
      for (std::uint32_t h = begin; h < end; ++h) slot[end_of[h]] = h;
    }
    for (std::uint32_t k = 0; k < diagonals.size(); ++k) {
      twin_[slot[2 * k]] = slot[2 * k + 1];
      twin_[slot[2 * k + 1]] = slot[2 * k];
    }
  }

  // Counter-clockwise from v -> next(v): first the directions left of that ray, then the rest (a
  // reflex angle exceeds a half-turn). Every diagonal lies strictly inside the interior angle.
  void sort_row(std::uint32_t v, std::uint32_t begin, std::uint32_t end, std::vector<std::uint32_t>& end_of,
                std::vector<std::pair<std::uint32_t, std::uint32_t>>& row) {
    const Point &centre = p_[v], &ray = p_[p_.next(v)];
    auto half = [&](std::uint32_t w) { return orient(centre, ray, p_[w]) > 0 ? 0 : 1; };
    row.clear();
    for (std::uint32_t h = begin; h < end; ++h) row.emplace_back(target_[h], end_of[h]);
    std::sort(row.begin(), row.end(), [&](const auto& a, const auto& b) {
      const int ha = half(a.first), hb = half(b.first);
      return ha != hb ? ha < hb : orient(centre, p_[a.first], p_[b.first]) > 0;
    });
    for (std::uint32_t h = begin; h < end; ++h) std::tie(target_[h], end_of[h]) = row[h - begin];
  }

  const Polygon& p_;
  std::vector<std::uint32_t> start_, target_, twin_;
};

// The stack triangulation of one monotone piece, given as a counter-clockwise cycle of vertices.
class StackTriangulator {
 public:
  StackTriangulator(const Polygon& p, Decomposition& d) : p_(p), d_(d) {}

  void triangulate(const std::vector<std::uint32_t>& cycle) {
    if (cycle.size() == 3) return;
    merge_chains(cycle);
    const std::size_t m = order_.size();
    stack_.assign({0, 1});
    for (std::size_t k = 2; k + 1 < m; ++k) {
      if (on_left_[k] != on_left_[stack_.back()]) {
        fan_across(k);
      } else {
        cut_along_chain(k);
      }
    }
    for (std::size_t s = 1; s + 1 < stack_.size(); ++s) cut(m - 1, stack_[s]);
    steps_ += static_cast<std::int64_t>(m);
  }

  std::int64_t steps() const { return steps_; }

 private:
  // Going counter-clockwise from the top vertex descends the left chain; going clockwise descends
  // the right chain. Merging them lists the piece from top to bottom.
  void merge_chains(const std::vector<std::uint32_t>& cycle) {
    const std::size_t m = cycle.size();
    std::size_t top = 0, bottom = 0;
    for (std::size_t i = 1; i < m; ++i) {
      if (above(p_[cycle[i]], p_[cycle[top]])) top = i;
      if (above(p_[cycle[bottom]], p_[cycle[i]])) bottom = i;
    }
    order_.assign(1, cycle[top]);
    on_left_.assign(1, 0);
    std::size_t left = (top + 1) % m, right = (top + m - 1) % m;
    while (left != bottom || right != bottom) {
      const bool take_left = right == bottom || (left != bottom && above(p_[cycle[left]], p_[cycle[right]]));
      order_.push_back(take_left ? cycle[left] : cycle[right]);
      on_left_.push_back(take_left);
      if (take_left) {
        left = (left + 1) % m;
      } else {
        right = (right + m - 1) % m;
      }
    }
    order_.push_back(cycle[bottom]);
    on_left_.push_back(0);
  }

  // Vertex k is on the other chain than the stack's reflex chain: it sees all of it.
  void fan_across(std::size_t k) {
    for (std::size_t s = 1; s < stack_.size(); ++s) cut(k, stack_[s]);
    stack_.assign({k - 1, k});
    steps_ += 2;
  }

  // Vertex k continues the stack's chain: cut off triangles while the turn is strictly convex.
  void cut_along_chain(std::size_t k) {
    std::size_t last = stack_.back();
    stack_.pop_back();
    while (!stack_.empty() && sees(k, last, stack_.back())) {
      cut(k, stack_.back());
      last = stack_.back();
      stack_.pop_back();
      ++steps_;
    }
    stack_.push_back(last);
    stack_.push_back(k);
  }

  // Whether the diagonal from order k to order s, past order `last` on the same chain, is inside:
  // the triangle (s, last, k) listed down a left chain, or up a right chain, turns strictly left.
  bool sees(std::size_t k, std::size_t last, std::size_t s) const {
    const Point &u = p_[order_[k]], &l = p_[order_[last]], &t = p_[order_[s]];
    return on_left_[k] ? orient(t, l, u) > 0 : orient(u, l, t) > 0;
  }

  void cut(std::size_t k, std::size_t s) { d_.add_cut(order_[k], order_[s]); }

  const Polygon& p_;
  Decomposition& d_;
  std::vector<std::uint32_t> order_;
  std::vector<char> on_left_;
  std::vector<std::size_t> stack_;
  std::int64_t steps_ = 0;
};

}  // namespace

Decomposition triangulate_monotone_pieces(const Polygon& p, const std::vector<Cut>& diagonals, Counters& counters) {
  Decomposition d;
  d.cuts.reserve(p.size() - 3);
  d.cuts.assign(diagonals.begin(), diagonals.end());
  const Rotation rotation(p, diagonals);
  StackTriangulator triangulator(p, d);
  std::vector<char> walked(rotation.half_edges(), 0);
  std::vector<std::uint32_t> cycle;
  std::int64_t pieces = 0;
  // Every half-edge but v -> prev(v) has the interior on its left; each face is walked once.
  for (std::uint32_t v = 0; v < p.size(); ++v)
    for (std::uint32_t s = rotation.first(v); s < rotation.last(v); ++s) {
      if (walked[s]) continue;
      cycle.clear();
      std::uint32_t u = v, h = s;
      do {
        walked[h] = 1;
        cycle.push_back(u);
        u = rotation.target(h);
        h = rotation.next_in_face(h);
      } while (h != s);
      triangulator.triangulate(cycle);
      ++pieces;
    }
  counters["pieces"] = pieces;
  counters["stack_steps"] = triangulator.steps();
  return d;
}

Decomposition triangulate_monotone(const Polygon& p, Counters& counters) {
  return triangulate_monotone_pieces(p, y_monotone_diagonals(p, counters), counters);
}

}  // namespace pd
