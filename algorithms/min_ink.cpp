// min-ink: the convex decomposition without Steiner points of least total diagonal length ("minimum
// ink"), Keil & Snoeyink (001), Sec. 1: O(n^2 r^2), the bound of Greene's double dynamic program.
//
// Time O(n^2 r^2) comparisons (engines/convex/convex_chains.h), space O(n^2) for the link table plus O(n r)
// subproblems. Pre: a simple counter-clockwise polygon; collinear vertices allowed. Output: convex
// pieces whose diagonals have the least total length among all convex decompositions by diagonals (not
// necessarily the fewest pieces, so not registered as optimal in the piece-count sense).
//
// The engine is Greene's double program with lengths for weights: a side that is a diagonal weighs its
// length plus the least ink on its far side. Lengths are square roots and are never compared by
// accident: totals are compared by the exact rule of engines/convex/exact_ink.h (intervals, then cancellation of
// equal lengths, merging of radicals with rational ratios, and MPFR evaluation of what remains, which
// is then known not to be zero). The terms of a total are recovered from the chain and the stored
// pieces when the intervals overlap.
#include "core/registry.h"
#include "engines/convex/convex_chains.h"
#include "engines/convex/exact_ink.h"

namespace pd {
namespace {

class Ink {
 public:
  using Value = ink::Interval;
  Value zero() const { return {0.0, 0.0}; }
  Value infinite() const { return {kInf, kInf}; }
  bool finite(const Value& v) const { return v.lo != kInf; }
  Value plus(const Value& a, const Value& b) const { return finite(a) && finite(b) ? ink::add(a, b) : infinite(); }
  Value side(std::uint32_t segment, const Value& far_side) const { return plus(lengths_.enclosure(segment), far_side); }
  std::uint32_t add_segment(const Point& a, const Point& b) { return lengths_.add(a, b); }
  void freeze() { lengths_.freeze(); }

  // a < b, exactly: the enclosures when they are apart, otherwise the terms of both totals.
  template <class TermsA, class TermsB>
  bool less(const Value& a, const Value& b, TermsA&& terms_a, TermsB&& terms_b) {
    if (!finite(b)) return finite(a);
    if (!finite(a)) return false;
    if (a.hi < b.lo) return true;
    if (b.hi < a.lo) return false;
    lhs_.clear();
    rhs_.clear();
    terms_a(lhs_);
    terms_b(rhs_);
    return lengths_.compare(lhs_, rhs_) < 0;
  }

  void report(Counters& counters) const {
    counters["exact_comparisons"] = lengths_.exact_comparisons();
    counters["exact_ties_cancelled"] = lengths_.cancelled_ties();
    counters["exact_evaluations"] = lengths_.evaluated();
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  ink::SegmentLengths lengths_;
  std::vector<std::uint32_t> lhs_, rhs_;
};

Decomposition min_ink(const Polygon& p, Counters& counters) {
  Ink cost;
  return chains::Program<Ink>(p, cost).run(counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "min-ink", .kind = Kind::Convex, .time_bound = "n^2*r^2",
                    .pieces_bound = "min ink",
                    .source = "Keil & Snoeyink (001) Sec. 1 (minimum ink, Greene's double program)",
                    .size_ceiling = 400, .run = min_ink});

}  // namespace pd
