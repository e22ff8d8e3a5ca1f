// cutting-tri: triangulation by recursive polygon cutting. Chazelle, "How to Divide a Polygon Fairly",
// CMU 1982 (paper 004), Section 3.2, Theorem 8.
//
// Every vertex weighs 1. A part of 7 vertices or more is cut by the polygon-cutting theorem
// (polygon_cutting.h): each side then holds at most 2/3 of the part's vertices plus the diagonal's two
// ends, so the recursion is O(log n) deep. A part of at most 6 vertices is finished by ear clipping.
// Time O(n log n): the preprocessing (LH, LV) once, then O(m) per part of m vertices and O(n) per level
// of the recursion; the counters give the work (cut_visits) and the depth. Space O(n).
// Pre: a simple counter-clockwise polygon; collinear vertices allowed. Output: n-3 diagonals, n-2
// non-degenerate triangles, no Steiner points.
//
// Reconstruction: the paper omits how to finish ("it is straightforward to complete the
// triangulation. We omit the details"): a small part is ear-clipped, an ear being a strictly convex
// vertex whose closed triangle holds no other vertex of the part (one always exists). Parts are
// sub-cycles of the top polygon carrying LH and LV restricted to them, so no polygon is rebuilt or
// checked again.
#include "core/registry.h"
#include "engines/cutting/polygon_cutting.h"

#include <algorithm>

namespace pd {
namespace {

using cutting::Id;
using cutting::Part;

constexpr std::size_t kSmallPart = 7;  // parts with fewer vertices are ear-clipped

class TriangulationByCutting {
 public:
  explicit TriangulationByCutting(const Polygon& p) : p_(p), cutter_(p) {}

  Decomposition run(Counters& counters) {
    d_.cuts.reserve(p_.size() - 3);
    triangulate(cutter_.whole(), 0);
    counters["fair_cuts"] = cuts_;
    counters["cut_visits"] = work_.visits;
    counters["separator_levels"] = work_.levels;
    counters["max_depth"] = max_depth_;
    counters["ear_tests"] = ear_tests_;
    return std::move(d_);
  }

 private:
  void triangulate(const Part& part, std::int64_t depth) {
    max_depth_ = std::max(max_depth_, depth);
    if (part.cycle.size() < kSmallPart) {
      clip_ears(part.cycle);
      return;
    }
    const cutting::Diagonal cut = cutter_.fair_diagonal(part, std::vector<int>(part.cycle.size(), 1), work_);
    ++cuts_;
    d_.add_cut(part.cycle[cut.a], part.cycle[cut.b]);
    const auto [first, second] = cutter_.split(part, cut.a, cut.b);
    triangulate(first, depth + 1);
    triangulate(second, depth + 1);
  }

  void clip_ears(std::vector<Id> cycle) {
    while (cycle.size() > 3) {
      std::size_t tip = 0;
      while (tip < cycle.size() && !is_ear(cycle, tip)) ++tip;
      if (tip == cycle.size()) throw std::logic_error("cutting-tri: a small part has no ear");
      const std::size_t m = cycle.size();
      d_.add_cut(cycle[(tip + m - 1) % m], cycle[(tip + 1) % m]);
      cycle.erase(cycle.begin() + static_cast<std::ptrdiff_t>(tip));
    }
  }

  bool is_ear(const std::vector<Id>& cycle, std::size_t tip) {
    ++ear_tests_;
    const std::size_t m = cycle.size();
    const Point &a = p_[cycle[(tip + m - 1) % m]], &b = p_[cycle[tip]], &c = p_[cycle[(tip + 1) % m]];
    if (orient(a, b, c) <= 0) return false;
    for (std::size_t k = 0; k < m; ++k) {
      if (k == tip || k == (tip + 1) % m || k == (tip + m - 1) % m) continue;
      const Point& z = p_[cycle[k]];
      if (orient(a, b, z) >= 0 && orient(b, c, z) >= 0 && orient(c, a, z) >= 0) return false;
    }
    return true;
  }

  const Polygon& p_;
  cutting::Cutter cutter_;
  cutting::CutWork work_;
  Decomposition d_;
  std::int64_t cuts_ = 0, max_depth_ = 0, ear_tests_ = 0;
};

Decomposition cutting_tri(const Polygon& p, Counters& counters) { return TriangulationByCutting(p).run(counters); }

}  // namespace

REGISTER_ALGORITHM({.name = "cutting-tri", .kind = Kind::Triangulation, .time_bound = "n*log(n)",
                    .pieces_bound = "== n-2", .source = "Chazelle 1982 (004) Sec. 3.2, Thm 8",
                    .run = cutting_tri});

}  // namespace pd
