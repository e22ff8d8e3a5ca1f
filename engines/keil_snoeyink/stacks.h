// keil-snoeyink's program (algorithms/keil_snoeyink.cpp) as a function, for programs that run it on a
// polygon of their own making (the reduced polygon of keil-snoeyink-reduced).
#pragma once

#include "core/decomposition.h"

namespace pd {

// Minimum convex decomposition without Steiner points, Keil & Snoeyink (001) Algorithm 1: O(n r^2).
Decomposition keil_snoeyink(const Polygon& p, Counters& counters);

}  // namespace pd
