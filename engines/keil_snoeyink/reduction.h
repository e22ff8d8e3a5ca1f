// keil-snoeyink-reduced (algorithms/keil_snoeyink_reduced.cpp), and its reduction step on its own, so
// that the tests can check it on polygons too small for the program to choose it.
#pragma once

#include "core/decomposition.h"

namespace pd {

// The reduced polygon when it pays (r^2 + 2r < n and the rays cost less than Algorithm 1 on the
// input), else Algorithm 1 on the input. Pre: a simple counter-clockwise polygon.
Decomposition keil_snoeyink_reduced(const Polygon& p, Counters& counters);

// Shoots the rays, builds the reduced polygon and runs Algorithm 1 on it, whatever the sizes.
// Pre: a simple counter-clockwise polygon with at least one reflex vertex.
Decomposition solve_on_reduced_polygon(const Polygon& p, Counters& counters);

}  // namespace pd
