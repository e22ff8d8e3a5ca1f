// An independent exact check of the minimum number of convex pieces with Steiner points, for small r:
// the judge of the optimal programs with Steiner points (`chazelle-dobkin-n5`, `chazelle-dobkin`).
// It shares no code with them (nothing from algorithms/): it is built from the definitions of
// Chazelle's thesis (papers 000, Sections 2.2.3 and 2.2.4), not from the dynamic program of 2.3.
//
// What it computes. Theorem 7: an optimal convex decomposition has exactly r + 1 - p pieces, p the
// largest number of compatible X-patterns (Definition 2.2: a tree in P whose degree-1 and degree-2
// vertices are notches, each notch's reflex angle resolved by its tree edges, every other vertex a
// Steiner point of degree 3 with no reflex angle around it; compatible: no two edges of distinct
// patterns meet). The checker searches the patterns of the kinds below from their definitions, finds
// the largest compatible set it can, and returns r + 1 - p with a witness decomposition: the patterns'
// edges, then each remaining notch resolved by a ray (the naive decomposition, Theorem 1, written here
// afresh) up to the first segment it meets. The witness is checked by the project's validator in the
// tests, so the returned count is always a proven upper bound on the optimum.
//
// Patterns searched (trees whose vertices are notches, plus at most one Steiner point, and X4):
//   - Steiner-free trees: any tree of diagonals between notches of the group (X2 is one diagonal; an
//     X3 path has its middle notch as an N2-node; larger paths and notch-hubs likewise);
//   - one-Steiner trees: a point S joined to three notches of the group (X3 with a Steiner point,
//     Theorem 14's configuration), the group's other notches joined by diagonals (Y4, Y5, Y6 with one
//     N3-node);
//   - X4-patterns with two adjacent Steiner points (Theorem 15's kind): S joined to two notches and to
//     T, T joined to the other two. All four notches are leaves, so S lies in the ranges of its two
//     notches and T in those of its two; each is taken from the sampled faces (below) of the
//     arrangement inside the intersection of its two ranges' cones, and every pair is tested exactly.
//     This is a sampling, not an exhaustive search: the angles at S depend on T, whose lines are not
//     in S's arrangement, so an X4 whose points must both sit in special positions could be missed.
// A Steiner-free tree may have a notch of degree 3 or more (a hub). Such a tree is not an X-pattern in
// the strict sense of Definition 2.2, but it saves one piece all the same (relation (1) in the proof of
// Theorem 6 counts only its contacts with the boundary), and Theorem 5's transformation turns it into
// an X-pattern with a Steiner point next to the hub; the witness is validated either way.
// Steiner points are found exactly: for three notches, every condition on S (the three segments lie
// in P, touching its boundary only at their ends; the angles at S and at the notches are not reflex;
// no crossing with a diagonal between notches) changes only across the polygon's edge lines and the
// lines through two notches, so the checker samples one exact point of every face (vertex, edge, cell)
// of the arrangement of those lines inside the triangle of the three notches (S must lie in that
// closed triangle for its three angles to be at most 180 degrees). Visibility from a notch t changes
// only where S crosses an edge line or a line from t through a reflex vertex (a notch): a segment from
// t passing a convex or flat vertex leaves P on both sides of it. Diagonals are tested exactly.
//
// When the count is the optimum. A tree with k notches has (number of leaves) - 2 Steiner points of
// degree 3, so a pattern of at most 3 notches has at most one; and p <= floor(r/2). Hence:
//   - r <= 3: exact (every pattern of at most 3 notches is searched exhaustively);
//   - r = 4, 5: exact when p = 2 is possible (two patterns of 2 and 2 or 2 and 3 notches; a Steiner
//     point compatible with a fixed diagonal is found exactly, the diagonal's lines being in the
//     arrangement); when p = 1, exact unless the only patterns have two or more Steiner points: an
//     X4 is searched by sampling (above), a Y5/X5 with two or three N3-nodes not at all;
//   - r = 6: exact for p = 3 (three diagonals); for p = 2, a diagonal with a 4-notch pattern with two
//     Steiner points is searched by sampling only, and for two one-Steiner patterns (two X3) each point
//     is taken from the sampled faces of its own arrangement, which does not hold the other pattern's
//     lines, so a compatible pair needing both points in special positions could be missed; p = 1 as
//     for r = 5, X6 with several N3-nodes not searched.
// Whenever the count reaches ceil(r/2) + 1 (Theorem 8's lower bound) it is proven optimal whatever the
// kinds (the result says `proven_optimal`). In short: never below the optimum (the witness), possibly
// above it only through patterns with two or more Steiner points or, at r = 6, two X3-patterns.
//
// Degeneracies: a pattern edge may not touch the boundary between its ends (a segment grazing a vertex
// is rejected; it would make the tree touch B(P) outside its notches); 180-degree angles are allowed.
// Bound: r <= 6 (more notches are refused with std::invalid_argument); the work grows with the
// number of notch subsets and with n^3 per triple of notches (the arrangement), meant for n up to
// about 40.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace pd::steiner_check {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using EPoint = EK::Point_2;
using EVector = EK::Vector_2;
using ESegment = EK::Segment_2;
using ELine = EK::Line_2;
static_assert(std::is_same_v<std::decay_t<decltype(CGAL::exact(EK::FT()))>, Rational>,
              "the witness converts the exact kernel's numbers to pd::Rational");

constexpr std::size_t kMaxReflex = 6;
// An edge end at the pattern's Steiner point k is -1 - k; notches are polygon vertex indices.
constexpr int steiner_end(std::size_t k) { return -1 - static_cast<int>(k); }
constexpr std::size_t steiner_index(int end) { return static_cast<std::size_t>(-1 - end); }

// A pattern: a tree whose ends are notches or its Steiner points.
struct Pattern {
  std::vector<std::pair<int, int>> edges;
  std::vector<EPoint> steiner;
  std::uint32_t notches = 0;  // bit k: the k-th notch (in counter-clockwise order) belongs to it
};

struct Result {
  std::size_t pieces = 0;         // r + 1 - (number of patterns)
  std::vector<Pattern> patterns;  // the compatible set found
  bool proven_optimal = false;    // pieces == ceil(r/2) + 1, Theorem 8's lower bound
  Decomposition witness;          // the patterns, then the remaining notches resolved by rays
};

class Checker {
 public:
  explicit Checker(const Polygon& p) : p_(p) {
    for (std::size_t i = 0; i < p.size(); ++i) points_.emplace_back(p[i].x(), p[i].y());
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_reflex(i)) notches_.push_back(static_cast<int>(i));
    if (notches_.size() > kMaxReflex) throw std::invalid_argument("steiner_check: r > 6");
    for (std::size_t a = 0; a < notches_.size(); ++a)
      for (std::size_t b = a + 1; b < notches_.size(); ++b)
        if (open_segment_inside(points_[notches_[a]], points_[notches_[b]])) diagonals_.push_back({a, b});
  }

  Result run() {
    const std::size_t r = notches_.size();
    Result result;
    for (std::size_t target = r / 2; target >= 1 && result.patterns.empty(); --target) {
      std::vector<Pattern> chosen;
      if (find_compatible(target, 0, 0, chosen)) result.patterns = chosen;
    }
    result.pieces = r + 1 - result.patterns.size();
    result.proven_optimal = result.pieces == (r + 1) / 2 + 1;
    result.witness = witness(result.patterns);
    return result;
  }

 private:
  struct NotchPair {
    std::size_t a, b;  // indices into notches_
  };

  const EPoint& at(const Pattern& t, int end) const { return end < 0 ? t.steiner[steiner_index(end)] : points_[end]; }

  // --- Exact primitives -------------------------------------------------------------------------

  // Whether q lies in P's interior (not on its boundary).
  bool strictly_inside(const EPoint& q) const {
    return CGAL::bounded_side_2(points_.begin(), points_.end(), q, EK()) == CGAL::ON_BOUNDED_SIDE;
  }

  // Whether segment ab lies in P and meets P's boundary at most at its ends a and b.
  bool open_segment_inside(const EPoint& a, const EPoint& b) const {
    if (a == b) return false;
    const ESegment ab(a, b);
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const ESegment edge(points_[i], points_[p_.next(i)]);
      if (!CGAL::do_intersect(ab, edge)) continue;
      const auto meet = CGAL::intersection(ab, edge);
      const EPoint* x = boost::get<EPoint>(&*meet);
      if (x == nullptr || (*x != a && *x != b)) return false;
    }
    return strictly_inside(CGAL::midpoint(a, b));
  }

  // The counter-clockwise angle from u to w is in (0, 180] degrees.
  static bool not_reflex(const EVector& u, const EVector& w) {
    const auto turn = CGAL::orientation(u, w);
    return turn == CGAL::LEFT_TURN || (turn == CGAL::COLLINEAR && u * w < 0);
  }

  // Directions sorted by counter-clockwise angle from ref, in [0, 360).
  static void sort_around(const EVector& ref, std::vector<EVector>& dirs) {
    const auto half = [&](const EVector& u) {
      const auto side = CGAL::orientation(ref, u);
      return side == CGAL::LEFT_TURN || (side == CGAL::COLLINEAR && ref * u > 0) ? 0 : 1;
    };
    std::sort(dirs.begin(), dirs.end(), [&](const EVector& u, const EVector& w) {
      const int hu = half(u), hw = half(w);
      return hu != hw ? hu < hw : CGAL::orientation(u, w) == CGAL::LEFT_TURN;
    });
  }

  // Whether the edges from notch v towards `ends` leave no reflex angle at v: from the boundary edge
  // to v's successor round to the edge to its predecessor, each angle in (0, 180].
  bool resolves_notch(int v, const std::vector<EPoint>& ends) const {
    const EPoint& o = points_[v];
    const EVector first = points_[p_.next(v)] - o, last = points_[p_.prev(v)] - o;
    std::vector<EVector> dirs;
    for (const EPoint& e : ends) dirs.push_back(e - o);
    sort_around(first, dirs);
    dirs.insert(dirs.begin(), first);
    dirs.push_back(last);
    for (std::size_t k = 0; k + 1 < dirs.size(); ++k)
      if (!not_reflex(dirs[k], dirs[k + 1])) return false;
    return true;
  }

  // Whether the three edges at a Steiner point s leave every angle around it in (0, 180].
  static bool steiner_angles_ok(const EPoint& s, const std::vector<EPoint>& ends) {
    std::vector<EVector> dirs;
    for (const EPoint& e : ends) dirs.push_back(e - s);
    const EVector first = dirs[0];
    sort_around(first, dirs);
    dirs.push_back(first);
    for (std::size_t k = 0; k + 1 < dirs.size(); ++k)
      if (!not_reflex(dirs[k], dirs[k + 1])) return false;
    return true;
  }

  // --- Patterns ----------------------------------------------------------------------------------

  // Whether the tree's edges meet only at shared ends (no crossing, no overlap).
  bool edges_apart(const Pattern& t) const {
    for (std::size_t i = 0; i < t.edges.size(); ++i)
      for (std::size_t j = i + 1; j < t.edges.size(); ++j) {
        const auto [a, b] = t.edges[i];
        const auto [c, d] = t.edges[j];
        const ESegment s(at(t, a), at(t, b)), u(at(t, c), at(t, d));
        if (!CGAL::do_intersect(s, u)) continue;
        if (a != c && a != d && b != c && b != d) return false;
        const int shared = (a == c || a == d) ? a : b;
        const auto meet = CGAL::intersection(s, u);
        const EPoint* x = boost::get<EPoint>(&*meet);
        if (x == nullptr || *x != at(t, shared)) return false;
      }
    return true;
  }

  // Every notch of the tree resolved by its edges, the Steiner point's angles not reflex.
  bool resolved(const Pattern& t) const {
    std::map<int, std::vector<EPoint>> ends;
    for (const auto& [a, b] : t.edges) {
      ends[a].push_back(at(t, b));
      ends[b].push_back(at(t, a));
    }
    for (const auto& [v, far] : ends) {
      if (v < 0 ? !steiner_angles_ok(at(t, v), far) : !resolves_notch(v, far)) return false;
    }
    return true;
  }

  bool is_pattern(const Pattern& t) const { return edges_apart(t) && resolved(t); }

  // Two patterns are compatible when no edge of one meets an edge of the other.
  bool compatible(const Pattern& s, const Pattern& t) const {
    for (const auto& [a, b] : s.edges)
      for (const auto& [c, d] : t.edges)
        if (CGAL::do_intersect(ESegment(at(s, a), at(s, b)), ESegment(at(t, c), at(t, d)))) return false;
    return true;
  }

  bool compatible_with(const std::vector<Pattern>& chosen, const Pattern& t) const {
    return std::all_of(chosen.begin(), chosen.end(), [&](const Pattern& c) { return compatible(c, t); });
  }

  // The diagonals between notches of `group`.
  std::vector<NotchPair> diagonals_in(std::uint32_t group) const {
    std::vector<NotchPair> out;
    for (const NotchPair& d : diagonals_)
      if ((group >> d.a & 1) && (group >> d.b & 1)) out.push_back(d);
    return out;
  }

  // Calls `each` with every subset of `count` of the diagonals that joins the components of `joined`
  // (union-find roots over notch indices) into one tree; stops when `each` returns true.
  static bool each_joining_subset(const std::vector<NotchPair>& pool, std::size_t count, std::vector<int> joined,
                                  const std::function<bool(const std::vector<NotchPair>&)>& each) {
    std::vector<NotchPair> picked;
    std::function<bool(std::size_t, std::vector<int>)> grow = [&](std::size_t from, std::vector<int> roots) {
      if (picked.size() == count) return each(picked);
      for (std::size_t k = from; k < pool.size(); ++k) {
        const int ra = roots[pool[k].a], rb = roots[pool[k].b];
        if (ra == rb) continue;
        std::vector<int> merged = roots;
        for (int& x : merged)
          if (x == rb) x = ra;
        picked.push_back(pool[k]);
        if (grow(k + 1, merged)) return true;
        picked.pop_back();
      }
      return false;
    };
    return grow(0, std::move(joined));
  }

  std::vector<int> singleton_roots() const {
    std::vector<int> roots(notches_.size());
    for (std::size_t k = 0; k < roots.size(); ++k) roots[k] = static_cast<int>(k);
    return roots;
  }

  Pattern tree_of(std::uint32_t group, const std::vector<NotchPair>& picked, const std::optional<EPoint>& s,
                  const std::vector<std::size_t>& star) const {
    Pattern t;
    t.notches = group;
    if (s) t.steiner.push_back(*s);
    for (const NotchPair& d : picked) t.edges.push_back({notches_[d.a], notches_[d.b]});
    for (std::size_t k : star) t.edges.push_back({steiner_end(0), notches_[k]});
    return t;
  }

  // Calls `each` with every pattern realising `group` (all its notches, nothing else); stops when
  // `each` returns true.
  bool each_pattern(std::uint32_t group, const std::function<bool(const Pattern&)>& each) {
    const std::vector<NotchPair> pool = diagonals_in(group);
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < notches_.size(); ++k)
      if (group >> k & 1) members.push_back(k);
    const std::size_t size = members.size();
    const bool steiner_free = each_joining_subset(pool, size - 1, singleton_roots(), [&](const auto& picked) {
      const Pattern t = tree_of(group, picked, std::nullopt, {});
      return is_pattern(t) && each(t);
    });
    if (steiner_free || size < 3) return steiner_free;
    if (size == 4 && each_two_steiner_pattern(group, members, each)) return true;
    for (std::size_t i = 0; i < size; ++i)
      for (std::size_t j = i + 1; j < size; ++j)
        for (std::size_t k = j + 1; k < size; ++k) {
          const std::vector<std::size_t> star{members[i], members[j], members[k]};
          std::vector<int> roots = singleton_roots();
          roots[star[1]] = roots[star[2]] = roots[star[0]];
          for (const EPoint& s : steiner_candidates(star)) {
            const bool stop = each_joining_subset(pool, size - 3, roots, [&](const auto& picked) {
              const Pattern t = tree_of(group, picked, s, star);
              return is_pattern(t) && each(t);
            });
            if (stop) return true;
          }
        }
    return false;
  }

  // X4-patterns with two adjacent Steiner points: S joined to notches a, b and to T, T joined to c, d.
  // Each notch is a leaf, so S lies in the ranges of a and b, T in those of c and d; both are taken
  // from the sampled faces of their regions (see steiner_candidates), every pair tested exactly.
  bool each_two_steiner_pattern(std::uint32_t group, const std::vector<std::size_t>& members,
                                const std::function<bool(const Pattern&)>& each) {
    for (std::size_t partner = 1; partner < 4; ++partner) {
      std::vector<std::size_t> other;
      for (std::size_t k = 1; k < 4; ++k)
        if (k != partner) other.push_back(members[k]);
      const std::vector<std::size_t> left{members[0], members[partner]};
      for (const EPoint& s : leaf_pair_candidates(left[0], left[1]))
        for (const EPoint& u : leaf_pair_candidates(other[0], other[1])) {
          if (!angles_can_close(s, left, u) || !angles_can_close(u, other, s)) continue;
          Pattern t;
          t.notches = group;
          t.steiner = {s, u};
          t.edges = {{steiner_end(0), notches_[left[0]]}, {steiner_end(0), notches_[left[1]]},
                     {steiner_end(0), steiner_end(1)}, {steiner_end(1), notches_[other[0]]},
                     {steiner_end(1), notches_[other[1]]}};
          if (open_segment_inside(s, u) && is_pattern(t) && each(t)) return true;
        }
    }
    return false;
  }

  // The angles at s towards the two notches and towards far are not reflex (tested before the
  // segments, which cost O(n) each).
  bool angles_can_close(const EPoint& s, const std::vector<std::size_t>& pair, const EPoint& far) const {
    return steiner_angles_ok(s, {points_[notches_[pair[0]]], points_[notches_[pair[1]]], far});
  }

  const std::vector<Pattern>& patterns_of(std::uint32_t group) {
    auto found = patterns_.find(group);
    if (found != patterns_.end()) return found->second;
    std::vector<Pattern> all;
    each_pattern(group, [&](const Pattern& t) {
      all.push_back(t);
      return false;
    });
    return patterns_[group] = std::move(all);
  }

  // Whether `target` compatible patterns exist on disjoint groups, the groups taken in increasing
  // order of their bit masks, all above `after`; on success `chosen` holds them.
  bool find_compatible(std::size_t target, std::uint32_t after, std::uint32_t used, std::vector<Pattern>& chosen) {
    if (chosen.size() == target) return true;
    const std::size_t r = notches_.size();
    const std::size_t free_notches = r - static_cast<std::size_t>(__builtin_popcount(used));
    const std::size_t still = target - chosen.size();
    if (free_notches < 2 * still) return false;
    for (std::uint32_t group = after + 1; group < (1u << r); ++group) {
      const std::size_t size = static_cast<std::size_t>(__builtin_popcount(group));
      if ((group & used) != 0 || size < 2 || size > free_notches - 2 * (still - 1)) continue;
      if (chosen.empty() && still == 1) {
        // One pattern alone: existence is enough, without listing every realisation.
        const bool found = each_pattern(group, [&](const Pattern& t) {
          chosen.push_back(t);
          return true;
        });
        if (found) return true;
        continue;
      }
      for (const Pattern& t : patterns_of(group)) {
        if (!compatible_with(chosen, t)) continue;
        chosen.push_back(t);
        if (find_compatible(target, group, used | group, chosen)) return true;
        chosen.pop_back();
      }
    }
    return false;
  }

  // --- Steiner points ----------------------------------------------------------------------------

  // One exact point in every face (vertex, edge, cell) of the arrangement of the polygon's edge lines
  // and the lines through two notches, inside the closed triangle of the three notches `star`, kept
  // when the three segments to the notches lie in P and the angles at the point are not reflex.
  std::vector<EPoint> steiner_candidates(const std::vector<std::size_t>& star) {
    const auto key = std::make_tuple(star[0], star[1], star[2]);
    auto cached = candidates_.find(key);
    if (cached != candidates_.end()) return cached->second;
    std::vector<EPoint> keep;
    const EPoint &a = points_[notches_[star[0]]], &b = points_[notches_[star[1]]], &c = points_[notches_[star[2]]];
    if (!CGAL::collinear(a, b, c)) {
      for (const EPoint& s : face_samples({a, b, c}, /*cells_only*/ false)) {
        if (!steiner_angles_ok(s, {a, b, c}) || !strictly_inside(s)) continue;
        if (open_segment_inside(s, a) && open_segment_inside(s, b) && open_segment_inside(s, c)) keep.push_back(s);
      }
    }
    return candidates_[key] = keep;
  }

  // One exact point in every cell (2-dimensional face) of the same arrangement inside the part of P's
  // bounding box where the segments to both notches resolve them (the intersection of their ranges'
  // cones), kept when the point is inside P and the two segments lie in P. Cells only: the X4 search
  // is a sampling anyway, and pairs of points cost the product of the two lists.
  std::vector<EPoint> leaf_pair_candidates(std::size_t i, std::size_t j) {
    const auto key = std::make_pair(i, j);
    auto cached = leaf_candidates_.find(key);
    if (cached != leaf_candidates_.end()) return cached->second;
    std::vector<EPoint> region = bounding_box();
    for (std::size_t k : {i, j}) {
      const int v = notches_[k];
      const EPoint& o = points_[v];
      region = clip_left(region, o, o + (o - points_[p_.prev(v)]));
      region = clip_left(region, o, points_[p_.next(v)]);
    }
    std::vector<EPoint> keep;
    const EPoint &a = points_[notches_[i]], &b = points_[notches_[j]];
    if (region.size() >= 3) {
      for (const EPoint& s : face_samples(region, /*cells_only*/ true)) {
        if (!strictly_inside(s) || !resolves_notch(notches_[i], {s}) || !resolves_notch(notches_[j], {s})) continue;
        if (open_segment_inside(s, a) && open_segment_inside(s, b)) keep.push_back(s);
      }
    }
    return leaf_candidates_[key] = keep;
  }

  std::vector<EPoint> bounding_box() const {
    EK::FT lo_x = points_[0].x(), hi_x = lo_x, lo_y = points_[0].y(), hi_y = lo_y;
    for (const EPoint& q : points_) {
      lo_x = CGAL::min(lo_x, q.x());
      hi_x = CGAL::max(hi_x, q.x());
      lo_y = CGAL::min(lo_y, q.y());
      hi_y = CGAL::max(hi_y, q.y());
    }
    return {EPoint(lo_x, lo_y), EPoint(hi_x, lo_y), EPoint(hi_x, hi_y), EPoint(lo_x, hi_y)};
  }

  // The convex polygon `region` (counter-clockwise) cut to the closed half-plane left of p -> q.
  static std::vector<EPoint> clip_left(const std::vector<EPoint>& region, const EPoint& p, const EPoint& q) {
    std::vector<EPoint> out;
    const ELine line(p, q);
    for (std::size_t k = 0; k < region.size(); ++k) {
      const EPoint &u = region[k], &w = region[(k + 1) % region.size()];
      const auto su = CGAL::orientation(p, q, u), sw = CGAL::orientation(p, q, w);
      if (su != CGAL::RIGHT_TURN) out.push_back(u);
      if (su != CGAL::COLLINEAR && sw != CGAL::COLLINEAR && su != sw) {
        const auto meet = CGAL::intersection(line, ESegment(u, w));
        out.push_back(boost::get<EPoint>(*meet));
      }
    }
    return out;
  }

  // The part of `line` inside the convex polygon `region`, when it is a segment.
  static std::optional<ESegment> chord(const ELine& line, const std::vector<EPoint>& region) {
    std::vector<EPoint> on;
    for (std::size_t k = 0; k < region.size(); ++k) {
      const ESegment side(region[k], region[(k + 1) % region.size()]);
      if (!CGAL::do_intersect(line, side)) continue;
      const auto meet = CGAL::intersection(line, side);
      if (const EPoint* x = boost::get<EPoint>(&*meet)) on.push_back(*x);
      else on.insert(on.end(), {side.source(), side.target()});
    }
    if (on.empty()) return std::nullopt;
    const auto [lo, hi] = std::minmax_element(on.begin(), on.end(), [](const EPoint& u, const EPoint& w) {
      return CGAL::compare_xy(u, w) < 0;
    });
    if (*lo == *hi) return std::nullopt;
    return ESegment(*lo, *hi);
  }

  std::vector<ELine> arrangement_lines() const {
    std::vector<ELine> lines;
    for (std::size_t i = 0; i < points_.size(); ++i) lines.emplace_back(points_[i], points_[p_.next(i)]);
    for (std::size_t a = 0; a < notches_.size(); ++a)
      for (std::size_t b = a + 1; b < notches_.size(); ++b)
        lines.emplace_back(points_[notches_[a]], points_[notches_[b]]);
    return lines;
  }

  // The faces of the arrangement of arrangement_lines() and the sides of the convex polygon `region`,
  // inside the region: its vertices, a point inside each of its edges, and, beside each edge's point,
  // a point of each of the two cells the edge separates (only those with `cells_only`).
  std::vector<EPoint> face_samples(const std::vector<EPoint>& region, bool cells_only) const {
    std::vector<ELine> lines = arrangement_lines();
    for (std::size_t k = 0; k < region.size(); ++k) lines.emplace_back(region[k], region[(k + 1) % region.size()]);
    std::vector<ESegment> chords;
    for (const ELine& line : lines)
      if (const auto c = chord(line, region)) chords.push_back(*c);
    std::vector<EPoint> samples;
    for (std::size_t i = 0; i < chords.size(); ++i) {
      std::vector<EPoint> on{chords[i].source(), chords[i].target()};
      for (std::size_t j = 0; j < chords.size(); ++j) {
        if (j == i || !CGAL::do_intersect(chords[i], chords[j])) continue;
        const auto meet = CGAL::intersection(chords[i], chords[j]);
        if (const EPoint* x = boost::get<EPoint>(&*meet)) on.push_back(*x);
      }
      std::sort(on.begin(), on.end(), [](const EPoint& u, const EPoint& w) { return CGAL::compare_xy(u, w) < 0; });
      on.erase(std::unique(on.begin(), on.end()), on.end());
      if (!cells_only) samples.insert(samples.end(), on.begin(), on.end());
      const EVector normal = chords[i].to_vector().perpendicular(CGAL::COUNTERCLOCKWISE);
      for (std::size_t k = 0; k + 1 < on.size(); ++k) {
        const EPoint m = CGAL::midpoint(on[k], on[k + 1]);
        if (!cells_only) samples.push_back(m);
        for (const EVector& side : {normal, -normal})
          if (const auto off = step_off(m, side, lines)) samples.push_back(*off);
      }
    }
    return samples;
  }

  // m + t/2 side, t the least positive parameter at which m + t side meets a line not through m.
  static std::optional<EPoint> step_off(const EPoint& m, const EVector& side, const std::vector<ELine>& lines) {
    std::optional<EK::FT> least;
    for (const ELine& line : lines) {
      const EK::FT along = line.a() * side.x() + line.b() * side.y();
      if (along == 0) continue;
      const EK::FT t = -(line.a() * m.x() + line.b() * m.y() + line.c()) / along;
      if (t > 0 && (!least || t < *least)) least = t;
    }
    if (!least) return std::nullopt;
    return m + side * (*least / 2);
  }

  // --- Witness -----------------------------------------------------------------------------------

  struct Drawn {
    EPoint a, b;
    VertexId ia, ib;
    std::int64_t boundary_edge;  // the polygon edge this piece of boundary lies on, or kInterior
  };

  VertexId add_point(Decomposition& d, const EPoint& x, std::int64_t boundary_edge) const {
    return static_cast<VertexId>(p_.size()) +
           d.add_steiner(QPoint(CGAL::exact(x.x()), CGAL::exact(x.y())), boundary_edge);
  }

  Decomposition witness(const std::vector<Pattern>& chosen) const {
    Decomposition d;
    std::vector<Drawn> drawn;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      drawn.push_back({points_[i], points_[p_.next(i)], static_cast<VertexId>(i), static_cast<VertexId>(p_.next(i)),
                       static_cast<std::int64_t>(i)});
    }
    std::uint32_t resolved = 0;
    for (const Pattern& t : chosen) {
      std::vector<VertexId> ids;
      for (const EPoint& s : t.steiner) ids.push_back(add_point(d, s, kInterior));
      const auto id = [&](int end) { return end < 0 ? ids[steiner_index(end)] : static_cast<VertexId>(end); };
      for (const auto& [a, b] : t.edges) drawn.push_back({at(t, a), at(t, b), id(a), id(b), kInterior});
      resolved |= t.notches;
    }
    for (std::size_t k = 0; k < notches_.size(); ++k)
      if (!(resolved >> k & 1)) shoot_from(notches_[k], d, drawn);
    for (const Drawn& s : drawn)
      if (s.boundary_edge == kInterior) d.add_cut(s.ia, s.ib);
    return d;
  }

  // Resolves notch v by a ray inside its range up to the first drawn segment, which it must meet
  // inside (not at an end); tries directions u1 + k u2 (u1, u2 the edges' extensions beyond v) until
  // one does.
  void shoot_from(int v, Decomposition& d, std::vector<Drawn>& drawn) const {
    const EPoint& o = points_[v];
    const EVector u1 = o - points_[p_.prev(v)], u2 = o - points_[p_.next(v)];
    for (int k = 1;; ++k) {
      const EK::FT weight = k % 2 == 0 ? EK::FT(k / 2 + 1) : EK::FT(1) / EK::FT(k / 2 + 1);
      const EK::Ray_2 ray(o, u1 + u2 * weight);
      std::optional<std::pair<EPoint, std::size_t>> nearest;
      bool clean = true;
      for (std::size_t s = 0; s < drawn.size() && clean; ++s) {
        const ESegment seg(drawn[s].a, drawn[s].b);
        if (seg.source() == o || seg.target() == o || !CGAL::do_intersect(ray, seg)) continue;
        const auto meet = CGAL::intersection(ray, seg);
        const EPoint* x = boost::get<EPoint>(&*meet);
        if (x == nullptr) {
          clean = false;
          continue;
        }
        if (!nearest || CGAL::has_smaller_distance_to_point(o, *x, nearest->first)) nearest = std::make_pair(*x, s);
      }
      if (!clean || !nearest) continue;
      const Drawn hit = drawn[nearest->second];
      if (nearest->first == hit.a || nearest->first == hit.b) continue;
      const VertexId x = add_point(d, nearest->first, hit.boundary_edge);
      drawn[nearest->second] = {hit.a, nearest->first, hit.ia, x, hit.boundary_edge};
      drawn.push_back({nearest->first, hit.b, x, hit.ib, hit.boundary_edge});
      drawn.push_back({o, nearest->first, static_cast<VertexId>(v), x, kInterior});
      return;
    }
  }

  const Polygon& p_;
  std::vector<EPoint> points_;
  std::vector<int> notches_;
  std::vector<NotchPair> diagonals_;
  std::map<std::uint32_t, std::vector<Pattern>> patterns_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::vector<EPoint>> candidates_;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<EPoint>> leaf_candidates_;
};

// The minimum number of convex pieces with Steiner points as far as the checker can tell (see above),
// with its witness.
inline Result check(const Polygon& p) { return Checker(p).run(); }

}  // namespace pd::steiner_check
