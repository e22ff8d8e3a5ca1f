// Whether two decompositions are the same segments: equal Steiner points (exact, on the same boundary
// edge), in order, and equal cuts, in order. For tests that hold two searches or two runs to each other.
#pragma once

#include "core/decomposition.h"

#include <gtest/gtest.h>

#include <string>

namespace pd {

inline ::testing::AssertionResult same_decomposition(const Decomposition& a, const Decomposition& b) {
  if (a.steiner.size() != b.steiner.size() || a.cuts.size() != b.cuts.size())
    return ::testing::AssertionFailure() << a.steiner.size() << " and " << b.steiner.size() << " Steiner points, "
                                         << a.cuts.size() << " and " << b.cuts.size() << " cuts";
  for (std::size_t k = 0; k < a.steiner.size(); ++k)
    if (!(a.steiner[k].point == b.steiner[k].point) || a.steiner[k].boundary_edge != b.steiner[k].boundary_edge)
      return ::testing::AssertionFailure() << "Steiner point " << k << " differs";
  for (std::size_t k = 0; k < a.cuts.size(); ++k)
    if (a.cuts[k].a != b.cuts[k].a || a.cuts[k].b != b.cuts[k].b)
      return ::testing::AssertionFailure() << "cut " << k << " differs";
  return ::testing::AssertionSuccess();
}

}  // namespace pd
