#include "core/polygon.h"

#include "core/ring_layout.h"
#include "core/sweep.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <utility>

namespace pd {
namespace {

// Names a vertex of a cycle being checked: its index in the input (the cycle may have lost merged
// vertices).
using NameOf = std::function<std::string(std::size_t)>;

std::string identity_name(std::size_t i) { return std::to_string(i); }

std::string edge_name(std::size_t i, std::size_t n, const NameOf& name) {
  return name(i) + "-" + name((i + 1) % n);
}

// Adjacent edges (a,b), (b,c) of a simple chain meet only at b: they fail when c folds back onto ab.
template <class P>
bool folds_back(const P& a, const P& b, const P& c) {
  return orient(a, b, c) == 0 && !CGAL::collinear_are_ordered_along_line(a, b, c);
}

// The cycle's vertex indices in lexicographic order of their points (equal points by index).
template <class P>
std::vector<std::uint32_t> lexicographic_order(const std::vector<P>& cycle) {
  std::vector<std::uint32_t> order(cycle.size());
  std::iota(order.begin(), order.end(), 0);
  // A merge sort: introsort's pivots meet the organ-pipe x order of a monotone polygon's vertices and
  // fall back to heapsort, twice as slow at 10^6.
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return cycle[i] < cycle[j]; });
  return order;
}

template <class P>
std::string duplicate_vertices(const std::vector<P>& cycle, const std::vector<std::uint32_t>& order, const NameOf& name) {
  for (std::size_t k = 1; k < order.size(); ++k)
    if (cycle[order[k - 1]] == cycle[order[k]])
      return "vertices " + name(order[k - 1]) + " and " + name(order[k]) + " coincide";
  return {};
}

template <class P>
std::string fold_back_fault(const std::vector<P>& cycle, const NameOf& name) {
  const std::size_t n = cycle.size();
  for (std::size_t i = 0; i < n; ++i)
    if (folds_back(cycle[i], cycle[(i + 1) % n], cycle[(i + 2) % n]))
      return "edges " + edge_name(i, n, name) + " and " + edge_name((i + 1) % n, n, name) + " overlap";
  return {};
}

// Distinct vertices, no fold-back, then the sweep of core/sweep.h, which names two edges that meet.
template <class P>
std::string simplicity_fault(const std::vector<P>& cycle, const NameOf& name) {
  if (cycle.size() < 3) return std::to_string(cycle.size()) + " vertices; a cycle needs at least 3";
  const std::vector<std::uint32_t> order = lexicographic_order(cycle);
  if (std::string dup = duplicate_vertices(cycle, order, name); !dup.empty()) return dup;
  if (std::string fold = fold_back_fault(cycle, name); !fold.empty()) return fold;
  const auto meeting = CycleSweep<P>(cycle, order).meeting();
  if (!meeting) return {};
  const std::size_t n = cycle.size();
  return "edge " + edge_name(meeting->first, n, name) + " crosses edge " + edge_name(meeting->second, n, name);
}

std::size_t lowest_vertex(const std::vector<Point>& v) {
  return static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
}

// One input ring made ready: the closing vertex dropped, each vertex that repeats its predecessor
// merged into it, the rest checked.
struct CleanRing {
  Ring kept;
  std::vector<std::uint32_t> file;                          // per kept vertex, its index in the ring's input
  std::vector<std::pair<std::size_t, std::size_t>> merged;  // (index, index of the vertex it repeats)
  std::size_t input_count = 0;
};

std::string ring_name(std::size_t k, std::size_t rings) {
  if (rings == 1) return "";
  return k == 0 ? "the outer ring" : "hole " + std::to_string(k);
}

// Names a cleaned ring's kept vertex by its index in the ring's input, as messages about the ring do.
NameOf input_names(const CleanRing& c) {
  return [&c](std::size_t i) { return std::to_string(c.file[i]); };
}

std::string not_simple(const std::string& why, std::size_t k, std::size_t rings) {
  return rings == 1 ? "not simple: " + why : ring_name(k, rings) + " is not simple: " + why;
}

// Every check of one input ring but its simplicity, which `check_simple` adds.
CleanRing clean_ring(Ring ring, std::size_t k, std::size_t rings, bool check_simple) {
  const std::string of = rings == 1 ? "" : " of " + ring_name(k, rings);
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (!std::isfinite(ring[i].x()) || !std::isfinite(ring[i].y()))
      throw PolygonError("vertex " + std::to_string(i) + of + " has a coordinate that is not finite");
  if (ring.size() >= 2 && ring.front() == ring.back()) ring.pop_back();
  CleanRing c;
  c.input_count = ring.size();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (i > 0 && ring[i] == c.kept.back()) {
      c.merged.push_back({i, c.file.back()});
      continue;
    }
    c.kept.push_back(ring[i]);
    c.file.push_back(static_cast<std::uint32_t>(i));
  }
  while (c.kept.size() > 1 && c.kept.back() == c.kept.front()) {
    c.merged.push_back({c.file.back(), 0});
    c.kept.pop_back();
    c.file.pop_back();
  }
  std::sort(c.merged.begin(), c.merged.end());
  if (c.kept.size() < 3) {
    const std::string count = std::to_string(c.kept.size()) + (c.kept.size() == 1 ? " vertex" : " vertices");
    const std::string after = c.merged.empty() ? "" : " once repeated vertices are merged";
    throw PolygonError(rings == 1 ? count + after + "; a polygon needs at least 3"
                                  : ring_name(k, rings) + " has " + count + after + "; a ring needs at least 3");
  }
  if (!check_simple) return c;
  if (std::string why = simplicity_fault(c.kept, input_names(c)); !why.empty())
    throw PolygonError(not_simple(why, k, rings));
  return c;
}

// Whether ring v must be turned round (keeping its first vertex first) to have the wanted orientation.
bool needs_turning(const Ring& v, bool counter_clockwise) {
  // The lowest-leftmost vertex of a simple ring is strictly convex, so its turn gives the orientation.
  const std::size_t n = v.size(), m = lowest_vertex(v);
  const bool is_ccw = orient(v[(m + n - 1) % n], v[m], v[(m + 1) % n]) > 0;
  return is_ccw != counter_clockwise;
}

// The first of the rings cleaned so far (of `rings` in all) that is not simple, as its error.
void throw_first_ring_fault(const std::vector<CleanRing>& clean, std::size_t rings) {
  for (std::size_t k = 0; k < clean.size(); ++k)
    if (std::string why = simplicity_fault(clean[k].kept, input_names(clean[k])); !why.empty())
      throw PolygonError(not_simple(why, k, rings));
}

// The rings of a polygon with holes, each cleaned but not yet checked for simplicity: one sweep checks
// the rings and their layout together; only when it fails do the rings' own checks and then the layout
// check run apart, in that order, to name the first fault as each would (ring by ring, then the
// layout).
void check_rings_and_layout(const Polygon& p, const std::vector<CleanRing>& clean) {
  bool folds = false;
  for (const CleanRing& c : clean) folds = folds || !fold_back_fault(c.kept, input_names(c)).empty();
  if (!folds && rings_and_layout_pass(p)) return;
  throw_first_ring_fault(clean, clean.size());
  if (std::string fault = layout_fault({&p}); !fault.empty()) throw PolygonError(fault);
}

}  // namespace

Rational twice_signed_area(const std::vector<Point>& cycle) {
  Rational sum = 0;
  for (std::size_t i = 0, n = cycle.size(); i < n; ++i) {
    const Point& a = cycle[i];
    const Point& b = cycle[(i + 1) % n];
    sum += Rational(a.x()) * Rational(b.y()) - Rational(b.x()) * Rational(a.y());
  }
  return sum;
}

template <class P>
bool simple_cycle(const std::vector<P>& cycle, std::string* why) {
  std::string fault = simplicity_fault(cycle, identity_name);
  if (why) *why = fault;
  return fault.empty();
}

bool is_simple_cycle(const std::vector<Point>& cycle, std::string* why) {
  return simple_cycle(cycle, why);
}
bool is_simple_cycle(const std::vector<QPoint>& cycle, std::string* why) {
  return simple_cycle(cycle, why);
}

std::size_t Polygon::reflex_count() const {
  std::size_t r = 0;
  for (std::size_t i = 0; i < v_.size(); ++i) r += is_reflex(i);
  return r;
}

std::size_t Polygon::first_reflex() const {
  for (std::size_t i = 0; i < v_.size(); ++i)
    if (is_reflex(i)) return i;
  return v_.size();
}

std::size_t Polygon::input_index(std::size_t i) const {
  const std::size_t k = ring_of(i), s = ring_start_[k], m = ring_start_[k + 1] - s;
  const std::size_t d = ring_reversed_[k] && i != s ? s + m - (i - s) : i;
  return file_of_.empty() ? d : file_of_[d];
}

Rings Polygon::rings() const {
  Rings out;
  for (std::size_t k = 0; k < ring_count(); ++k)
    out.emplace_back(v_.begin() + static_cast<std::ptrdiff_t>(ring_begin(k)), v_.begin() + static_cast<std::ptrdiff_t>(ring_end(k)));
  return out;
}

std::vector<Point> Polygon::input_points() const {
  std::vector<Point> points(input_size());
  for (std::size_t i = 0; i < v_.size(); ++i) points[input_index(i)] = v_[i];
  for (const auto& [index, repeats] : merged_) points[index] = points[repeats];
  return points;
}

Polygon Polygon::make(Ring outer) {
  Rings rings;
  rings.push_back(std::move(outer));
  return make_with_holes(std::move(rings));
}

Polygon Polygon::make_with_holes(Rings rings) {
  if (rings.empty()) throw PolygonError("the polygon is empty");
  const std::size_t count = rings.size();
  Polygon p;
  p.ring_start_.push_back(0);
  std::size_t file_offset = 0;
  bool any_merged = false;
  std::vector<CleanRing> clean;
  clean.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    try {
      clean.push_back(clean_ring(std::move(rings[k]), k, count, count == 1));
    } catch (const PolygonError&) {
      throw_first_ring_fault(clean, count);  // an earlier ring's own fault comes first
      throw;
    }
    any_merged = any_merged || !clean.back().merged.empty();
  }
  for (std::size_t k = 0; k < count; ++k) {
    const CleanRing& c = clean[k];
    p.ring_reversed_.push_back(needs_turning(c.kept, k == 0));
    if (any_merged)
      for (const std::uint32_t f : c.file) p.file_of_.push_back(static_cast<std::uint32_t>(file_offset + f));
    for (const auto& [index, repeats] : c.merged) p.merged_.push_back({file_offset + index, file_offset + repeats});
    p.v_.insert(p.v_.end(), c.kept.begin(), c.kept.end());
    if (p.ring_reversed_.back()) std::reverse(p.v_.end() - static_cast<std::ptrdiff_t>(c.kept.size()) + 1, p.v_.end());
    p.ring_start_.push_back(p.v_.size());
    file_offset += c.input_count;
  }
  if (count > 1) {
    p.ring_of_.resize(p.v_.size());
    for (std::size_t k = 0; k < count; ++k)
      std::fill(p.ring_of_.begin() + p.ring_start_[k], p.ring_of_.begin() + p.ring_start_[k + 1],
                static_cast<std::uint32_t>(k));
    check_rings_and_layout(p, clean);
  }
  return p;
}

std::vector<Polygon> make_parts(std::vector<Rings> parts) {
  if (parts.empty()) throw PolygonError("the polygon is empty");
  std::vector<Polygon> polygons;
  polygons.reserve(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    try {
      polygons.push_back(Polygon::make_with_holes(std::move(parts[k])));
    } catch (const PolygonError& e) {
      if (parts.size() == 1) throw;
      throw PolygonError("part " + std::to_string(k) + ": " + e.what());
    }
  }
  if (polygons.size() > 1) {
    std::vector<const Polygon*> all;
    for (const Polygon& p : polygons) all.push_back(&p);
    if (std::string fault = layout_fault(all); !fault.empty()) throw PolygonError(fault);
  }
  return polygons;
}

}  // namespace pd
