// Exact validation of a decomposition, apart from the algorithms.
//
// A decomposition is valid when every piece is a simple counter-clockwise polygon of the required kind
// (a triangle; y-monotone; convex) and the pieces tile the polygon exactly. The tiling test is the
// boundary-chain argument: when every piece is simple and counter-clockwise, its winding number is 1
// inside and 0 outside, so if the sum of the pieces' directed edges equals the polygon's boundary
// (each boundary edge once, forwards: the outer ring counter-clockwise, every hole clockwise; every
// other edge as often forwards as backwards) the pieces' indicator functions add up to the polygon's,
// whose winding number is the outer ring's less the holes': no gap, no overlap, nothing outside, nothing
// in a hole. Areas are compared
// as well (exact rationals), as a second, independent line. All predicates are exact.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"

#include <string>
#include <vector>

namespace pd {

struct Validation {
  bool ok = true;
  std::string reason;  // empty when ok; otherwise names the piece, vertex or edge at fault
};

// Validates pieces (cycles of vertex ids into `points`, where points[0..n-1] are the polygon's vertices
// in counter-clockwise order) against the polygon. `allow_steiner`: whether points beyond n may be used.
Validation validate_pieces(const Polygon& p, const std::vector<QPoint>& points,
                           const std::vector<Piece>& pieces, Kind kind, bool allow_steiner);
// The same for the pieces of decomposition d (pieces_of(p, d)): without Steiner points the polygon's
// own vertices are checked, with no exact copy of them.
Validation validate_pieces(const Polygon& p, const Decomposition& d, const std::vector<Piece>& pieces, Kind kind,
                           bool allow_steiner);

// Turns d into pieces with the shared routine and validates them; a malformed cut graph is reported
// as invalid with its reason.
Validation validate(const Polygon& p, const Decomposition& d, Kind kind, bool allow_steiner);

}  // namespace pd
