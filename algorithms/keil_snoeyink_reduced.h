// keil-snoeyink-reduced's reduction step on its own, so that the tests can check it on polygons too
// small for the registered program to choose it.
#pragma once

#include "core/registry.h"

namespace pd {

// Shoots the rays, builds the reduced polygon and runs Algorithm 1 on it, whatever the sizes.
// Pre: a simple counter-clockwise polygon with at least one reflex vertex.
Decomposition solve_on_reduced_polygon(const Polygon& p, Counters& counters);

}  // namespace pd
