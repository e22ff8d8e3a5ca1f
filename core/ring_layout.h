// How the rings of a polygon with holes, or of a multipolygon's parts, lie relative to one another:
// the check behind Polygon::make_with_holes and make_parts.
#pragma once

#include "core/polygon.h"

#include <string>
#include <vector>

namespace pd {

// The first fault in the layout of the parts' rings, or "" when there is none: two rings that share a
// point (touch) or cross, a hole outside its outer ring or inside another hole, a part inside another
// part. Every ring must be simple and normally oriented (each Polygon is). A Shamos-Hoey sweep over
// every edge: O(n log n) for n vertices in all, with exact predicates.
std::string layout_fault(const std::vector<const Polygon*>& parts);

// Whether the rings of `p` are simple (no fold-backs, checked by the caller, aside) and lie as they
// should, in one sweep: layout_fault's sweep testing the edges of one ring against one another too.
// Says only yes or no (its faults are not named as the separate checks name them); O(n log n).
bool rings_and_layout_pass(const Polygon& p);

}  // namespace pd
