// chazelle-dobkin-n5: optimal convex decomposition with Steiner points, Algorithm CD with Theorem 15's
// X4 detection (B. Chazelle, Computational Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.3,
// Theorems 13-17). The dynamic program (STEPs 1-5), its orientation and its reconstructions are in
// engines/chazelle_dobkin/program.h; pattern detection in engines/chazelle_dobkin/patterns.h.
//
// STEP 3's B: X4-patterns are tried for every pair of inner notches of the interval, in both pairings
// (Figure 2.24-a, -b: the first Steiner point joins z_i and z_k, or z_k and z_l), with the Steiner
// points at the tips of Q (Theorem 15): O(r^2) tests per interval, O(r^4) in all, the r^5 of Theorem 17
// with Theorem 15's O(r log(n/r)) test. A candidate is tried only when its count would beat the best so
// far, so the tests actually made are often far fewer. Past its O(1) angle tests, a candidate's
// segments are tested against the boundary's convex chains, O(r log(n/r)) (Theorem 15).
// Deviation: superranges are replaced by trees of geodesics from each notch over a decomposition by
// vertical chords (engines/chazelle_dobkin/patterns.h), in the same O(n + r^2 log n) preprocessing.
//
// Time: O(n + r^2 log n) preprocessing, O(r^4) pattern tests: the X3 tests of STEPs 2 and 4 O(r^3),
// O(1) each (engines/chazelle_dobkin/program.h); the X4 tests O(r^4), each O(1) or, past the constant-time tests,
// O(r log(n/r)); STEP 5 O(n + r^2 log(n/r)): O(n + r^5 log(n/r)) (Theorem 17). Space O(r^2 + n). Pre: a
// simple counter-clockwise polygon. Output: an optimal convex decomposition (OPT = r + 1 - the most
// compatible patterns), Steiner points exact.
#include "core/registry.h"
#include "engines/chazelle_dobkin/program.h"

namespace pd {
namespace {

class ProgramN5 final : public cd::Program {
 public:
  using cd::Program::Program;

 private:
  std::optional<cd::X4Choice> x4_term(int i, int j, int to_beat) override {
    std::optional<cd::X4Choice> best;
    for (int k = i + 1; k < j; ++k)
      for (int l = k + 1; l < j; ++l) {
        const int count = S(i + 1, k - 1) + S(k + 1, l - 1) + S(l + 1, j - 1) + 1;
        if (count <= (best ? best->count : to_beat)) continue;
        if (const auto x = patterns().x4(i, k, l, j)) best = cd::X4Choice{count, k, l, false, x->first, x->second};
        else if (const auto y = patterns().x4(k, l, j, i)) best = cd::X4Choice{count, k, l, true, y->first, y->second};
      }
    return best;
  }
};

Decomposition chazelle_dobkin_n5(const Polygon& p, Counters& counters) { return ProgramN5(p).run(counters); }

}  // namespace

REGISTER_ALGORITHM({.name = "chazelle-dobkin-n5", .kind = Kind::Convex, .steiner = true, .optimal = true,
                    .time_bound = "n+r^5*log(n/r)", .pieces_bound = "== OPT",
                    .source = "Chazelle thesis (000) Sec. 2.3, Thms 13-17", .size_ceiling = 20000,
                    .run = chazelle_dobkin_n5});

}  // namespace pd
