// Shared by the CGAL peers: turning the pieces a peer returns into a Decomposition as returned.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"

#include <vector>

namespace pd {

// A peer's piece may skip collinear polygon vertices that lie on one of its boundary edges; the
// contract lists every decomposition vertex on a piece's boundary, so they are put back. Nothing else
// is changed: a wrong piece stays wrong and is reported invalid.
inline Piece with_collinear_boundary_vertices(const Polygon& p, const Piece& piece) {
  Piece out;
  out.reserve(piece.size());
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const VertexId a = piece[i], b = piece[(i + 1) % piece.size()];
    out.push_back(a);
    for (std::size_t v = p.next(a); v != b && orient(p[a], p[b], p[v]) == 0 &&
                                    CGAL::collinear_are_strictly_ordered_along_line(p[a], p[v], p[b]);
         v = p.next(v))
      out.push_back(static_cast<VertexId>(v));
  }
  return out;
}

}  // namespace pd
