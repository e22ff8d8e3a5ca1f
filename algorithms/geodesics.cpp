// Geodesic trees by the funnel walk; see geodesics.h.
#include "algorithms/geodesics.h"

#include <algorithm>
#include <stdexcept>

namespace pd {

// reached_from(i) for the edge F[i] F[i+1]: whether c's path leaves the funnel at vertex i or before it
// (towards the left end), i.e. c does not lie past the edge. On the left chain (before the apex) c lies
// past an edge when it lies strictly left of it, on the right chain when strictly right of it. On the
// edge's line, c is reached from the edge's vertex nearer to it: the outer one when c lies beyond it (a
// terminal inside an edge, on the window itself, can also lie on the edge between the two). The
// answers are false before the tangent vertex and true from it on.
std::size_t funnel_tangent(const std::vector<const FilteredPoint*>& F, std::size_t lo, std::size_t hi, std::size_t apex,
                           const FilteredPoint& c, std::optional<std::size_t> guess, std::int64_t& steps) {
  const auto reached_from = [&](std::size_t i) {
    ++steps;
    const int side = orient(*F[i], *F[i + 1], c);
    if (side != 0) return i < apex ? side <= 0 : side >= 0;
    const bool between = CGAL::collinear_are_strictly_ordered_along_line(F[i]->exact, c.exact, F[i + 1]->exact);
    return i < apex ? !between : between;
  };
  return guess ? first_holding(lo, hi, *guess, reached_from) : first_holding_from_ends(lo, hi, reached_from);
}

GeodesicTrees::GeodesicTrees(const Polygon& p, const VisibilityGraph& triangulation, const std::vector<Terminal>& terminals)
    : p_(p), triangulation_(triangulation), terminals_(terminals), terminals_on_edge_(p.size()),
      trees_by_root_(terminals.size()), built_(terminals.size(), 0), edge_root_id_(static_cast<std::uint32_t>(p.size())),
      funnel_(2 * funnel_middle() + 2, 0), funnel_points_(funnel_.size(), nullptr) {
  vertices_.reserve(p.size());
  for (const Point& v : p.vertices()) vertices_.emplace_back(to_exact(v));
  edge_points_.reserve(terminals.size());
  for (std::size_t t = 0; t < terminals.size(); ++t) {
    edge_points_.emplace_back(terminals[t].point);
    if (!terminals[t].at_vertex) terminals_on_edge_[terminals[t].edge].push_back(static_cast<std::uint32_t>(t));
  }
  mark_windows_towards_terminals();
}

// Triangles are numbered by a slot with the triangle on its left (a -> b, third vertex next after b
// around a); the triangle on the right of slot s is the one on the left of twin(s). A depth-first walk
// over the dual tree from triangle 0 counts the terminals in each subtree; beyond a slot lies the
// subtree of the triangle on its right, or all but the subtree of the triangle on its left.
void GeodesicTrees::mark_windows_towards_terminals() {
  const std::uint32_t slots = triangulation_.row_end(p_.size() - 1);
  std::vector<std::uint32_t> left_of(slots, kUnset), owner(slots, 0);
  std::uint32_t count = 0;
  for (std::uint32_t a = 0; a < p_.size(); ++a)
    for (std::uint32_t h = triangulation_.row_begin(a); h + 1 < triangulation_.row_end(a); ++h) {
      if (left_of[h] != kUnset) continue;
      for (std::uint32_t s : triangle_slots(h)) left_of[s] = count;
      owner[count++] = h;
    }
  std::vector<std::uint32_t> weight(count, 0), parent(count, kUnset), order;
  for (const Terminal& t : terminals_) weight[left_of[triangulation_.row_begin(t.edge)]] += 1;
  std::vector<std::uint32_t> pending{0};
  parent[0] = 0;
  while (!pending.empty()) {
    const std::uint32_t t = pending.back();
    pending.pop_back();
    order.push_back(t);
    for (std::uint32_t s : triangle_slots(owner[t])) {
      const std::uint32_t across = left_of[triangulation_.twin(s)];
      if (across != kUnset && parent[across] == kUnset) parent[across] = t, pending.push_back(across);
    }
  }
  std::vector<std::uint32_t> below(weight);
  for (std::size_t k = order.size(); k-- > 1;) below[parent[order[k]]] += below[order[k]];
  towards_terminal_.assign(slots, 0);
  for (std::uint32_t s = 0; s < slots; ++s) {
    const std::uint32_t here = left_of[s], there = left_of[triangulation_.twin(s)];
    if (there == kUnset)  // s is polygon edge a -> a + 1, the outside beyond it
      towards_terminal_[s] = !terminals_on_edge_[triangulation_.head(triangulation_.twin(s))].empty();
    else if (here == kUnset)  // s is a polygon edge backwards, the whole triangulation beyond it
      towards_terminal_[s] = below[0] > 0;
    else
      towards_terminal_[s] = (parent[there] == here ? below[there] : below[0] - below[here]) > 0;
  }
}

// The three slots with the triangle on the left of slot h (a -> b) on their left: a -> b, b -> c, c -> a.
std::array<std::uint32_t, 3> GeodesicTrees::triangle_slots(std::uint32_t h) const {
  const std::uint32_t b_to_c = triangulation_.twin(h) - 1;
  return {h, b_to_c, triangulation_.twin(b_to_c) - 1};
}

const FilteredPoint& GeodesicTrees::point(std::size_t terminal) const {
  const Terminal& t = terminals_[terminal];
  return t.at_vertex ? vertices_[t.edge] : edge_points_[terminal];
}

void GeodesicTrees::path(std::size_t from, std::size_t to, std::vector<const FilteredPoint*>& out) {
  out.clear();
  const FilteredPoint &start = point(from), &end = point(to);
  if (&start == &end || start.exact == end.exact) {
    out.push_back(&end);
    return;
  }
  out.push_back(&start);
  if (!built_[to]) build(to);
  const Tree& tree = trees_by_root_[to];
  const Terminal& source = terminals_[from];
  const std::uint32_t root = terminals_[to].at_vertex ? static_cast<std::uint32_t>(terminals_[to].edge) : edge_root_id_;
  std::uint32_t id = source.at_vertex ? tree.vertex_turn[source.edge] : tree.terminal_turn[from];
  while (id != root) {
    if (id == kUnset) throw std::logic_error("geodesics: a terminal not reached by the walk");
    out.push_back(&vertices_[id]);
    id = tree.vertex_turn[id];
  }
  out.push_back(&end);
}

void GeodesicTrees::build(std::size_t root) {
  ++trees_;
  built_[root] = 1;
  Tree& tree = trees_by_root_[root];
  tree.vertex_turn.assign(p_.size(), kUnset);
  tree.terminal_turn.assign(terminals_.size(), kUnset);
  root_point_ = &point(root);
  root_id_ = terminals_[root].at_vertex ? static_cast<std::uint32_t>(terminals_[root].edge) : edge_root_id_;
  if (terminals_[root].at_vertex) start_at_vertex(terminals_[root].edge, tree);
  else start_inside_edge(root, tree);
}

// From vertex v every neighbour in the triangulation, and every point of the two edges at v, is seen
// directly; the walk starts at the window opposite v in each triangle of v's fan.
void GeodesicTrees::start_at_vertex(std::size_t v, Tree& tree) {
  const std::uint32_t self = static_cast<std::uint32_t>(v);
  for (std::size_t edge : {v, p_.prev(v)})
    for (std::uint32_t t : terminals_on_edge_[edge]) tree.terminal_turn[t] = self;
  const std::uint32_t first = triangulation_.row_begin(v), last = triangulation_.row_end(v);
  for (std::uint32_t h = first; h < last; ++h) tree.vertex_turn[triangulation_.head(h)] = self;
  const std::uint32_t mid = funnel_middle();
  for (std::uint32_t h = first; h + 1 < last; ++h) {
    set_funnel_entry(mid - 1, triangulation_.head(h + 1));
    set_funnel_entry(mid, self);
    set_funnel_entry(mid + 1, triangulation_.head(h));
    const std::uint32_t opposite = triangulation_.twin(h) - 1;
    if (towards_terminal_[opposite]) walk({opposite, mid - 1, mid + 1, mid, mid, self}, tree);
  }
}

// A root inside edge (u, u+1) sees that edge and the triangle on it; the walk starts at that edge,
// looking into the triangle: u on the left, u+1 on the right.
void GeodesicTrees::start_inside_edge(std::size_t root, Tree& tree) {
  const std::size_t u = terminals_[root].edge, w = p_.next(u);
  for (std::uint32_t t : terminals_on_edge_[u]) tree.terminal_turn[t] = edge_root_id_;
  tree.vertex_turn[u] = tree.vertex_turn[w] = edge_root_id_;
  const std::uint32_t mid = funnel_middle();
  set_funnel_entry(mid - 1, static_cast<std::uint32_t>(u));
  set_funnel_entry(mid, edge_root_id_);
  set_funnel_entry(mid + 1, static_cast<std::uint32_t>(w));
  const std::uint32_t into_triangle = triangulation_.twin(triangulation_.row_begin(u));
  if (towards_terminal_[into_triangle]) walk({into_triangle, mid - 1, mid + 1, mid, mid, edge_root_id_}, tree);
}

// Depth first over the dual tree. A window's triangle has its third vertex c just before the left end in
// the right end's counter-clockwise row (VisibilityGraph::visible_from), unless the window is the polygon
// edge right -> right + 1.
void GeodesicTrees::walk(const Window& first, Tree& tree) {
  stack_.assign(1, first);
  while (!stack_.empty()) {
    const Window w = stack_.back();
    stack_.pop_back();
    if (w.slot == kRestore) {
      set_funnel_entry(w.write_at, w.id);
      continue;
    }
    stack_.push_back({kRestore, 0, 0, 0, w.write_at, funnel_[w.write_at]});
    set_funnel_entry(w.write_at, w.id);
    const std::uint32_t right = triangulation_.head(triangulation_.twin(w.slot));
    if (w.slot == triangulation_.row_begin(right)) {
      reach_edge(right, w, tree);
      continue;
    }
    ++triangles_;
    const std::uint32_t c = triangulation_.head(w.slot - 1);
    const std::uint32_t k = static_cast<std::uint32_t>(tangent(w, vertices_[c]));
    if (tree.vertex_turn[c] == kUnset) tree.vertex_turn[c] = last_turn(funnel_[k], vertices_[c], tree);
    const std::uint32_t towards_right = w.slot - 1, towards_left = triangulation_.twin(w.slot - 1) - 1;
    if (towards_terminal_[towards_right]) stack_.push_back({towards_right, k - 1, w.hi, std::max(w.apex, k), k - 1, c});
    if (towards_terminal_[towards_left]) stack_.push_back({towards_left, w.lo, k + 1, std::min(w.apex, k), k + 1, c});
  }
}

// The walk reaches polygon edge (edge, edge + 1) through window w: the last turns before the terminals
// inside it.
void GeodesicTrees::reach_edge(std::size_t edge, const Window& w, Tree& tree) {
  for (std::uint32_t t : terminals_on_edge_[edge])
    if (tree.terminal_turn[t] == kUnset) tree.terminal_turn[t] = last_turn(funnel_[tangent(w, edge_points_[t])], edge_points_[t], tree);
}

std::size_t GeodesicTrees::tangent(const Window& w, const FilteredPoint& c) {
  return funnel_tangent(funnel_points_, w.lo, w.hi, w.apex, c, std::nullopt, tangent_steps_);
}

// The geodesic reaches c straight from funnel vertex u: it turns at u unless u is the root or its last
// turn g, u and c lie on one line (the geodesic then runs straight from g through u to c).
std::uint32_t GeodesicTrees::last_turn(std::uint32_t u, const FilteredPoint& c, const Tree& tree) const {
  if (u == root_id_) return u;
  const std::uint32_t g = tree.vertex_turn[u];
  return orient(point_of(g), point_of(u), c) == 0 ? g : u;
}

// Sets funnel entry `at` to the vertex or root `id`.
void GeodesicTrees::set_funnel_entry(std::size_t at, std::uint32_t id) {
  funnel_[at] = id;
  funnel_points_[at] = &point_of(id);
}

}  // namespace pd
