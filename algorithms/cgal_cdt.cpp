// cgal-cdt: CGAL's constrained Delaunay triangulation of the polygon, faces inside only (peer).
//
// CGAL 5.5, Triangulation_2: Constrained_Delaunay_triangulation_2 with the polygon's edges as
// constraints, O(n log n) expected; the inside faces are found by a flood fill from the infinite face
// that flips parity at each constraint, so a hole's faces (two constraints crossed) are outside. Pre: a
// polygon, with holes or without (collinear vertices are fine): n + 2h - 2 triangles for h holes. The
// triangles are reported as CGAL returns them.
#include "core/registry.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <utility>
#include <vector>

namespace pd {
namespace {

using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;

// Depth of each face: 0 outside, 1 inside (one constraint crossed), by breadth-first search.
void mark_inside(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Face_handle> frontier{cdt.infinite_face()}, across;
  cdt.infinite_face()->info() = 0;
  for (int depth = 0; !frontier.empty(); ++depth, frontier.swap(across), across.clear()) {
    while (!frontier.empty()) {
      const Cdt::Face_handle f = frontier.back();
      frontier.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle g = f->neighbor(i);
        if (g->info() != -1) continue;
        if (cdt.is_constrained({f, i})) {
          across.push_back(g);
        } else {
          g->info() = depth;
          frontier.push_back(g);
        }
      }
    }
    for (const auto& g : across)
      if (g->info() == -1) g->info() = depth + 1;
  }
}

Decomposition cgal_cdt(const Polygon& p, Counters& counters) {
  std::vector<std::pair<Point, VertexId>> points;
  points.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) points.emplace_back(p[i], static_cast<VertexId>(i));
  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  std::vector<Cdt::Vertex_handle> handle(p.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
  for (std::size_t i = 0; i < p.size(); ++i) cdt.insert_constraint(handle[i], handle[p.next(i)]);
  mark_inside(cdt);
  Decomposition d;
  d.pieces.emplace();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      d.pieces->push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  counters["cdt_faces"] = static_cast<std::int64_t>(cdt.number_of_faces());
  return d;
}

}  // namespace

REGISTER_ALGORITHM({.name = "cgal-cdt", .kind = Kind::Triangulation, .time_bound = "n*log(n)",
                    .pieces_bound = "== n+2*h-2",
                    .source = "CGAL 5.5 Constrained_Delaunay_triangulation_2, inside faces",
                    .peer = "CGAL 5.5", .accepts = {.holes = true}, .run = cgal_cdt});

}  // namespace pd
