// Geodesic trees by the funnel walk over a decomposition by vertical chords; see geodesics.h.
#include "engines/chazelle_dobkin/geodesics.h"

#include "engines/search/ray_shooting.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace pd {

// reached_from(i) for the edge F[i] F[i+1]: whether c's path leaves the funnel at vertex i or before it
// (towards the left end), i.e. c does not lie past the edge. On the left chain (before the apex) c lies
// past an edge when it lies strictly left of it, on the right chain when strictly right of it. On the
// edge's line, c is reached from the edge's vertex nearer to it: the outer one when c lies beyond it (a
// point X on chazelle-dobkin's ray G, tables.h, can also lie on the edge between the two). The answers
// are false before the tangent vertex and true from it on.
std::size_t funnel_tangent(const std::vector<const FilteredPoint*>& F, std::size_t lo, std::size_t hi, std::size_t apex,
                           const FilteredPoint& c, std::size_t guess, std::int64_t& steps) {
  const auto reached_from = [&](std::size_t i) {
    ++steps;
    const int side = orient(*F[i], *F[i + 1], c);
    if (side != 0) return i < apex ? side <= 0 : side >= 0;
    const bool between = CGAL::collinear_are_strictly_ordered_along_line(F[i]->exact, c.exact, F[i + 1]->exact);
    return i < apex ? !between : between;
  };
  return first_holding(lo, hi, guess, reached_from);
}

GeodesicTrees::GeodesicTrees(const Polygon& p, const std::vector<Terminal>& terminals) : p_(p) {
  for (const Terminal& t : terminals) {
    site_of_terminal_.push_back(static_cast<std::uint32_t>(sites_.size()));
    sites_.push_back({t, FilteredPoint(t.point)});
  }
  add_chords(p);
  sort_sites();
  build_faces();
  trees_by_root_.resize(sites_.size());
  funnel_.assign(2 * faces_.size() + 8, 0);
  funnel_points_.assign(funnel_.size(), nullptr);
}

// From every notch, the vertical rays that start into P's interior: up when an edge at the notch runs
// to the right (its cross product with (0, 1) is positive), down when one runs to the left.
void GeodesicTrees::add_chords(const Polygon& p) {
  RayShooter shooter(p);
  const Point origin(0, 0);
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (!p.is_reflex(v)) continue;
    const double in = p[v].x() - p[p.prev(v)].x(), out = p[p.next(v)].x() - p[v].x();
    for (const int up : {1, -1}) {
      if (!(up * in > 0 || up * out > 0)) continue;
      const Point along(0, up);
      const std::optional<RayShooter::Hit> hit = shooter.shoot_along(v, origin, along);
      if (!hit) throw std::logic_error("geodesics: a vertical ray into P meets no boundary");
      const std::uint32_t from = static_cast<std::uint32_t>(sites_.size());
      const QPoint z = to_exact(p[v]);
      const ExactKernel::Vector_2 u(0, up);
      const QPoint end = z + hit_parameter(p, z, u, *hit) * u;
      sites_.push_back({{v, true, z}, FilteredPoint(z)});
      sites_.push_back({{hit->vertex, hit->at_vertex, end}, FilteredPoint(end)});
      chords_.push_back({from, from + 1});
    }
  }
}

// Sorts the sites along the boundary, merges those at one point and renumbers the chords' ends and the
// terminals' sites; drops a chord found twice (from both its ends).
void GeodesicTrees::sort_sites() {
  const auto before = [&](const Site& a, const Site& b) { return Terminal::before(p_, a.place, b.place); };
  std::vector<std::uint32_t> order(sites_.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return before(sites_[a], sites_[b]); });
  std::vector<std::uint32_t> renamed(sites_.size());
  std::vector<Site> distinct;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Site& s = sites_[order[k]];
    if (distinct.empty() || before(distinct.back(), s)) distinct.push_back(s);
    renamed[order[k]] = static_cast<std::uint32_t>(distinct.size() - 1);
  }
  sites_ = std::move(distinct);
  for (std::uint32_t& s : site_of_terminal_) s = renamed[s];
  for (auto& [a, b] : chords_) {
    a = renamed[a], b = renamed[b];
    if (a > b) std::swap(a, b);
  }
  std::sort(chords_.begin(), chords_.end());
  chords_.erase(std::unique(chords_.begin(), chords_.end()), chords_.end());
}

// The chords join sites on a circle without crossing: face 0 runs along the whole boundary, jumping
// over each outermost chord; the face inside chord (i, j) runs from i to j the same way and back along
// the chord. Each step along the boundary and each side of a chord is in one face, each found by a
// binary search among the chords: O((s + chords) log r).
void GeodesicTrees::build_faces() {
  sides_.assign(chords_.size(), ChordSides{});
  faces_.push_back(inner_face(0, static_cast<std::uint32_t>(sites_.size()), -1));
  for (std::size_t c = 0; c < chords_.size(); ++c)
    faces_.push_back(inner_face(chords_[c][0], chords_[c][1], static_cast<std::int32_t>(c)));
  faces_at_site_.assign(sites_.size(), {});
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    for (std::uint32_t k = 0; k < faces_[f].size(); ++k) {
      const Step& step = faces_[f][k];
      faces_at_site_[step.from].push_back(f);
      if (step.chord < 0) continue;
      ChordSides& sides = sides_[static_cast<std::size_t>(step.chord)];
      const std::size_t side = step.from < step.to ? 1 : 0;  // 1: the face outside the chord
      sides.faces[side] = f, sides.steps[side] = k;
    }
}

// The face inside chord `chord` = (i, j) (or the whole boundary, i = 0 and j = the number of sites):
// from each site the longest chord forward that stays within (i, j), else the boundary to the next site.
std::vector<GeodesicTrees::Step> GeodesicTrees::inner_face(std::uint32_t i, std::uint32_t j, std::int32_t chord) {
  const std::uint32_t count = static_cast<std::uint32_t>(sites_.size());
  std::vector<Step> steps;
  for (std::uint32_t k = i; k != j;) {
    // chords_ is sorted: the chords from k are a range, the longest last.
    auto at = std::upper_bound(chords_.begin(), chords_.end(), std::array<std::uint32_t, 2>{k, UINT32_MAX});
    std::int32_t jump = -1;
    while (at != chords_.begin() && (*(at - 1))[0] == k) {
      --at;
      const std::uint32_t end = (*at)[1];
      if (end < j || (end == j && k != i)) {
        jump = static_cast<std::int32_t>(at - chords_.begin());
        break;
      }
    }
    const std::uint32_t next = jump >= 0 ? chords_[static_cast<std::size_t>(jump)][1] : k + 1;
    steps.push_back({k, next % count, jump});
    k = next;
  }
  if (chord >= 0) steps.push_back({j, i, chord});
  return steps;
}

void GeodesicTrees::path(std::size_t from, std::size_t to, std::vector<const FilteredPoint*>& out) {
  out.clear();
  const std::uint32_t source = site_of_terminal_[from], root = site_of_terminal_[to];
  out.push_back(&sites_[source].point);
  if (source == root) return;
  const std::vector<std::uint32_t>& turn = tree(root).turn;
  for (std::uint32_t id = turn[source]; id != root; id = turn[id]) {
    if (id == kUnset) throw std::logic_error("geodesics: a site not reached by the walk");
    out.push_back(&sites_[id].point);
  }
  out.push_back(&sites_[root].point);
}

GeodesicTrees::Start GeodesicTrees::start(std::size_t from, std::size_t to) {
  const std::uint32_t root = site_of_terminal_[from], target = site_of_terminal_[to];
  if (root == target) return {sites_[root].place, false};
  const Tree& t = tree(root);
  if (t.first[target] == kUnset) throw std::logic_error("geodesics: a site not reached by the walk");
  return {sites_[t.first[target]].place, t.turn[target] == root && t.clear[target] != 0};
}

const GeodesicTrees::Tree& GeodesicTrees::tree(std::uint32_t root) {
  Tree& t = trees_by_root_[root];
  if (t.turn.empty()) build(root, t);
  return t;
}

// From the root every site of each face at it is seen directly; the walk enters every other face
// through a chord of those, with the funnel (left end, root, right end).
void GeodesicTrees::build(std::uint32_t root, Tree& tree) {
  ++trees_;
  root_ = root;
  tree.turn.assign(sites_.size(), kUnset);
  tree.first.assign(sites_.size(), kUnset);
  tree.clear.assign(sites_.size(), 1);
  for (std::uint32_t f : faces_at_site_[root]) mark_seen_directly(f, tree);
  const std::uint32_t mid = static_cast<std::uint32_t>(faces_.size() + 3);
  set_funnel_entry(mid, root_);
  for (std::uint32_t f : faces_at_site_[root]) {
    for (const Step& step : faces_[f]) {
      if (step.chord < 0 || step.from == root_ || step.to == root_) continue;
      const ChordSides& sides = sides_[static_cast<std::size_t>(step.chord)];
      const std::size_t beyond = sides.faces[0] == f ? 1 : 0;
      set_funnel_entry(mid - 1, step.to);
      set_funnel_entry(mid + 1, step.from);
      enter({sides.faces[beyond], sides.steps[beyond], mid - 1, mid + 1, mid, false, false, false}, tree);
    }
  }
}

// Whether the boundary of P from site a forwards to site b (the next site) runs straight: it holds no
// vertex strictly between them, or its first such vertex lies on the segment ab (the face on its left
// is convex, so the rest do too).
bool GeodesicTrees::straight_arc(std::uint32_t a, std::uint32_t b) const {
  const Terminal &from = sites_[a].place, &to = sites_[b].place;
  const std::size_t w = p_.next(from.edge);
  const bool vertex_between = !(to.edge == from.edge && !to.at_vertex) && !(to.at_vertex && to.edge == w);
  if (!vertex_between) return true;
  const FilteredPoint first(to_exact(p_[w]));
  const FilteredPoint &fa = sites_[a].point, &fb = sites_[b].point;
  return orient(fa, first, fb) == 0 && CGAL::collinear_are_strictly_ordered_along_line(fa.exact, first.exact, fb.exact);
}

// The root sees every site of a face at it in a straight line. The face is convex, so the segment
// from the root to a site touches the face's boundary between them only when the two lie on one of its
// sides, which starts at the root one way round or the other: where the boundary from the root to its
// neighbour that way runs straight, the sites after the neighbour on that line lie beyond a point of
// P's boundary, and the neighbour itself too when the side runs along P's boundary, not a chord.
void GeodesicTrees::mark_seen_directly(std::uint32_t face, Tree& tree) const {
  const std::vector<Step>& steps = faces_[face];
  const std::size_t size = steps.size();
  std::size_t at = 0;
  while (steps[at].from != root_) ++at;
  for (std::size_t k = 1; k < size; ++k) {
    const std::uint32_t site = steps[(at + k) % size].from;
    tree.turn[site] = root_;
    tree.first[site] = site;
  }
  for (const bool forward : {true, false}) {
    const Step& side = steps[forward ? at : (at + size - 1) % size];
    const std::uint32_t neighbour = forward ? side.to : side.from;
    if (side.chord < 0) {
      if (!straight_arc(side.from, side.to)) continue;  // the root and the neighbour are not on a side
      tree.clear[neighbour] = 0;
    }
    std::uint32_t last = neighbour;
    for (std::size_t k = 1; k + 1 < size; ++k) {
      const Step& next = steps[forward ? (at + k) % size : (at + 2 * size - 1 - k) % size];
      const std::uint32_t beyond = forward ? next.to : next.from;
      const FilteredPoint &o = sites_[root_].point, &l = sites_[last].point, &b = sites_[beyond].point;
      if (orient(o, l, b) != 0 || !CGAL::collinear_are_strictly_ordered_along_line(o.exact, l.exact, b.exact)) break;
      tree.clear[beyond] = 0;
      last = beyond;
    }
  }
}

// Depth first over the dual tree from window `first`. Within a face entered through its step p (from
// the window's left end x to its right end y, counter-clockwise), the other sites follow clockwise from
// x to y: their funnel vertices run from lo to hi.
void GeodesicTrees::enter(const Window& first, Tree& tree) {
  stack_.assign(1, first);
  while (!stack_.empty()) {
    const Window w = stack_.back();
    stack_.pop_back();
    if (w.restore) {
      set_funnel_entry(w.lo, w.hi);
      continue;
    }
    const std::vector<Step>& face = faces_[w.face];
    const std::uint32_t x = face[w.step].from, y = face[w.step].to;
    for (const auto& [write, at, site] : {std::tuple{w.write_lo, w.lo, x}, std::tuple{w.write_hi, w.hi, y}}) {
      if (!write) continue;
      stack_.push_back({0, 0, at, funnel_[at], 0, false, false, true});
      set_funnel_entry(at, site);
    }
    ++faces_entered_;
    const std::size_t size = face.size();
    std::uint32_t previous = w.lo;  // the funnel vertex of the site before, clockwise
    for (std::size_t back = 1; back < size; ++back) {
      const Step& step = face[(w.step + size - back) % size];
      const std::uint32_t site = step.from;
      std::uint32_t reached = w.hi;
      if (site != y) {
        reached = static_cast<std::uint32_t>(
            funnel_tangent(funnel_points_, w.lo, w.hi, w.apex, sites_[site].point, previous, tangent_steps_));
        if (tree.turn[site] == kUnset) reach(site, funnel_[reached], tree);
      }
      if (reached < previous) throw std::logic_error("geodesics: funnel vertices out of order around a face");
      if (step.chord >= 0) {
        // The chord from step.to (its left end) to site (its right end), seen from the root.
        const ChordSides& sides = sides_[static_cast<std::size_t>(step.chord)];
        const std::size_t beyond = sides.faces[0] == w.face ? 1 : 0;
        const bool new_lo = step.to != x, new_hi = site != y;
        stack_.push_back({sides.faces[beyond], sides.steps[beyond], new_lo ? previous - 1 : w.lo,
                          new_hi ? reached + 1 : w.hi, std::clamp(w.apex, previous, reached), new_lo, new_hi, false});
      }
      previous = reached;
    }
  }
}

// The geodesic reaches `site` straight from funnel vertex u: it turns at u unless u is the root or its
// last turn g, u and the site lie on one line (the geodesic then runs straight from g through u, a
// point of the boundary, to the site).
void GeodesicTrees::reach(std::uint32_t site, std::uint32_t u, Tree& tree) const {
  std::uint32_t turn = u;
  if (u != root_ && orient(sites_[tree.turn[u]].point, sites_[u].point, sites_[site].point) == 0) turn = tree.turn[u];
  tree.turn[site] = turn;
  tree.first[site] = turn == root_ ? site : tree.first[turn];
  tree.clear[site] = turn == root_ && u == root_;
}

void GeodesicTrees::set_funnel_entry(std::size_t at, std::uint32_t site) {
  funnel_[at] = site;
  funnel_points_[at] = &sites_[site].point;
}

}  // namespace pd
