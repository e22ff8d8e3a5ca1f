// greene-dp: D. H. Greene, "The decomposition of polygons into convex parts" (1983), as cited by Keil &
// Snoeyink (001, Sec. 1) and listed in the slides (003, "Greene (1983): O(n^4) time with dynamic
// programming"): the double dynamic program for the minimum convex decomposition without Steiner
// points.
//
// The fewest convex pieces cut by diagonals. Time O(n^2 r^2) (Greene's bound, the slides' O(n^4)
// when r = Theta(n)), space O(n^2) for the link table plus O(n r) subproblems. Pre: a simple
// counter-clockwise polygon; collinear vertices allowed. Pieces: == OPT.
//
// The outer program runs over the diagonals with a reflex endpoint; the inner one builds the piece on
// each diagonal as a convex chain of sides (engines/convex/convex_chains.h). This is the O(n^2 r^2) form; the slides
// give only the bound, so the inner program's details (a pointer and a running minimum per vertex, one
// chain program per first side at a reflex end) are a reconstruction.
#include "core/registry.h"
#include "engines/convex/convex_chains.h"

namespace pd {
namespace {

// A decomposition weighs its number of diagonals; a side that is a diagonal weighs 1 plus the
// decomposition on its far side.
class PieceCount {
 public:
  using Value = std::int32_t;
  Value zero() const { return 0; }
  Value infinite() const { return std::numeric_limits<Value>::max(); }
  bool finite(Value v) const { return v != infinite(); }
  Value plus(Value a, Value b) const { return finite(a) && finite(b) ? a + b : infinite(); }
  Value side(std::uint32_t, Value far_side) const { return plus(far_side, 1); }
  std::uint32_t add_segment(const Point&, const Point&) { return 0; }
  void freeze() {}
  template <class TermsA, class TermsB>
  bool less(Value a, Value b, TermsA&&, TermsB&&) const {
    return a < b;
  }
  void report(Counters&) const {}
};

Decomposition greene_dp(const Polygon& p, Counters& counters) {
  PieceCount cost;
  return chains::Program<PieceCount>(p, cost).run(counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "greene-dp", .kind = Kind::Convex, .optimal = true, .time_bound = "n^2*r^2",
                    .pieces_bound = "== OPT",
                    .source = "Greene 1983 double dynamic program, as cited in 001 Sec. 1 and slides 003",
                    .size_ceiling = 400, .run = greene_dp});

}  // namespace pd
