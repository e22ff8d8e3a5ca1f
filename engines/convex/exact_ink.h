// Exact comparison of total lengths ("ink"), for min-ink.
//
// A length is the square root of a rational (the squared distance between two double points is an
// exact rational), so a total is a sum of square roots, and two totals are compared by the rule:
//  1. Intervals first. Each length is enclosed in [lo, hi] (MPFR, rounded down and up to doubles),
//     sums are widened by one ulp per addition; disjoint intervals decide.
//  2. Otherwise exactly. Lengths equal as rationals cancel (most ties: equal diagonals in symmetric
//     polygons). The rest is sum_i c_i sqrt(q_i) with c_i = +-1; terms whose radicands differ by a
//     rational square factor are merged (sqrt(q) = rho sqrt(q') with rho rational exactly when q q'
//     is a rational square), leaving sum_j C_j sqrt(m_j) over pairwise non-equivalent m_j. Square
//     roots of integers with distinct square-free parts are linearly independent over Q, so the sum is
//     0 exactly when every C_j is 0. Otherwise it is not 0, and MPFR interval evaluation at doubling
//     precision finds its sign (it terminates because the value is not 0).
// No tolerance is involved anywhere: equal totals compare equal, unequal ones in the right order.
#pragma once

#include "core/geometry.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace pd::ink {

// sign(sum_i c_i sqrt(q_i)) for rationals c_i and q_i >= 0, exactly. `precision_bits`, if given,
// receives the MPFR precision that decided (0 when decided without evaluation).
int sign_of_root_sum(const std::vector<std::pair<Rational, Rational>>& terms, long* precision_bits = nullptr);

// An enclosure of a total length.
struct Interval {
  double lo, hi;
};
Interval add(const Interval& a, const Interval& b);

// The lengths of a fixed set of segments, for comparing totals that are sums of them.
class SegmentLengths {
 public:
  // Returns the segment's id (ids count from 0).
  std::uint32_t add(const Point& a, const Point& b);
  // Call once after the last add: groups equal lengths.
  void freeze();

  const Interval& enclosure(std::uint32_t id) const { return enclosure_[id]; }
  // sign(sum of lengths of `lhs` - sum of lengths of `rhs`), exactly; ids may repeat.
  int compare(const std::vector<std::uint32_t>& lhs, const std::vector<std::uint32_t>& rhs);

  std::int64_t exact_comparisons() const { return exact_; }
  std::int64_t cancelled_ties() const { return cancelled_; }
  std::int64_t evaluated() const { return evaluated_; }

 private:
  std::vector<Rational> squared_;
  std::vector<Interval> enclosure_;
  std::vector<std::uint32_t> class_of_;  // equal squared lengths share a class
  std::int64_t exact_ = 0, cancelled_ = 0, evaluated_ = 0;
};

}  // namespace pd::ink
