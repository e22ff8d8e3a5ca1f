// chazelle-dobkin: optimal convex decomposition with Steiner points, Algorithm CD with Section 2.4's
// organisation of STEP 3's X4 term (B. Chazelle, Computational Geometry and Convexity, thesis, Yale
// 1980 (000), Sec. 2.4, "An OCD Algorithm Cubic in the Number of Notches": Definition 2.4, Theorem 18,
// Lemma 9, the sets E(i, j) of Sec. 2.4.2). The dynamic program (STEPs 1-5), its orientation and its
// reconstructions are in algorithms/chazelle_dobkin.h; pattern detection, including the X4 test used
// here, in algorithms/chazelle_dobkin_patterns.h.
//
// What the thesis says (Sec. 2.4.1-2.4.2, as far as the OCR text goes). STEP 3 must not try the
// O(r^2) pairs of inner notches of every interval. E(i, j) is computed right after S(i, j) and holds,
// for each notch v_k outside V(i, j), "a single piece of data": whether some v_l inside can be patched
// with v_i, v_j and v_k into an X4-pattern, keeping only the v_l that "cause the same savings in
// V(i, j), that is, |S(i, j)|", so that STEP 3 decides the X4 term of an interval in O(r) lookups. The
// text stops while describing the scan that fills E(i, j) in O(r).
//
// Reconstructed here, with proofs (S is the table of Algorithm CD; S(a, b) = 0 when a >= b).
// (1) Only tight X4-patterns matter. S is monotone (S(a, b) >= S(a, b - 1), STEP 3's split at b - 1)
//     and superadditive over disjoint intervals (S(a, c) >= S(a, b) + S(b + 1, c), the split at b).
//     An X4-pattern on notches i < k < l < j counts c(k, l) = S(i+1, k-1) + S(k+1, l-1) + S(l+1, j-1) + 1,
//     and S(i+1, k-1) + S(k+1, l-1) <= S(i+1, l-1) (superadditive, then monotone), so
//     c(k, l) <= S(i+1, j-1) + 1. STEP 3's split term already reaches S(i, i) + S(i+1, j) >= S(i+1, j-1):
//     the X4 term changes S(i, j) only if some X4-pattern reaches exactly S(i+1, j-1) + 1.
// (2) Tightness factors. With a = S(i+1, k-1), b = S(k+1, l-1), c = S(l+1, j-1):
//     a + b + c <= a + S(k+1, j-1) <= S(i+1, j-1), so a + b + c = S(i+1, j-1) iff
//       T(i, j; k): S(i+1, k-1) + S(k+1, j-1) = S(i+1, j-1)  and
//       T(k, j; l): S(k+1, l-1) + S(l+1, j-1) = S(k+1, j-1),
//     and, splitting at l first (a + b <= S(i+1, l-1)), iff T(i, j; l) and T(i, l; k).
// (3) The two pairings (Figure 2.24-a, -b) give two tables.
//     E(k, j)[i], for i < k < j: some l in (k, j) with T(k, j; l) and an X4-pattern whose first Steiner
//       point joins z_i and z_k and whose second joins z_l and z_j. It needs S only strictly inside
//       V(k, j), so it is computed when the program reaches the interval (k, j) (the thesis's "E(i, j)
//       computed after S(i, j)"), for every outer notch i at once.
//     W(i, l)[j], for i < l < j: some k in (i, l) with T(i, l; k) and an X4-pattern whose first Steiner
//       point joins z_k and z_l and whose second joins z_j and z_i; computed at the interval (i, l).
//     STEP 3 on (i, j), when S(i+1, j-1) + 1 beats the other terms: the X4 term is S(i+1, j-1) + 1 iff
//     some k in (i, j) has T(i, j; k) and a witness in E(k, j)[i], or some l in (i, j) has T(i, j; l)
//     and a witness in W(i, l)[j] (by (1) and (2)); O(r) lookups per interval, O(r^3) in all. The
//     witness names the other inner notch, and the Steiner points are recomputed from it for the layout.
//     Every table entry an interval reads belongs to a shorter interval, so it is final.
//     Consequence, proven by induction over the intervals: S (and therefore B, F and the piece count)
//     is the same table as chazelle-dobkin-n5's, which takes the maximum of c(k, l) over all pairs
//     with the same X4 test; only the X4-pattern laid out may differ.
// Deviations.
// - The Steiner points are the tips of Q of Theorem 15 (chazelle_dobkin_patterns.h), the same as
//   chazelle-dobkin-n5's, not the thesis's loose points A_ik = r_i ∩ r_k of Theorem 18 (every notch
//   edge lined up with the extension of the notch's forward edge). So exactly the X4-patterns of
//   chazelle-dobkin-n5 are found, which the tests check count for count. A tip joining a and b (a
//   before b) whose edges are not clipped by a view or by the line ab has a's edge along the
//   extension of a's backward edge and b's along r_b: one of Definition 2.4's 16 loose configurations,
//   so the second Steiner points of E(k, j) lie on r_j and the first on r_k, as in the thesis; clipped
//   tips do not, and the thesis's sorted lists and two-way scan are not used. Theorem 18's proof
//   (Figure 2.31) and the scan are lost with the figures and the end of the OCR text; this file does
//   not reconstruct them.
// - E(k, j) and W(i, l) are filled by a loop: over the outer notches whose tip exists, over the tight
//   inner notches whose tip exists, stopping at the first X4-pattern. Each test is O(1) (tips cached,
//   half-planes, crossings) and only its survivors test the segment between the Steiner points against
//   the boundary's convex chains, O(r log(n/r)). A test pairs a first tip with a second tip, and each
//   such pair is tested at most once per table (the four notches name the entry and the candidate):
//   with t the number of tips that exist (counter "tips_found", t <= r^2), O(r^3 + t^2) tests, where
//   the thesis's scan takes O(r^3). Tips exist for few pairs of notches in the families measured.
// - Preprocessing and STEPs 2 and 4 are shared with chazelle-dobkin-n5 (chazelle_dobkin.h): visibility
//   in place of superranges, and Y-pattern tests that check segments against the boundary.
//
// Time: O(n log n + n r + r^2 log n) preprocessing; tips O(r^2) times O(r log(n/r)); STEPs 2 and 4
// O(r^4 log(n/r)) (chazelle_dobkin.h); STEP 3's X4 term O(r^3) lookups; the tables O(r^3 + t^2)
// tests, each O(1) or O(r log(n/r)). Worst case (t = r^2) O(n log n + n r + r^5 log(n/r)), as
// chazelle-dobkin-n5, which makes Theta(r^4) O(1) steps on every polygon where this makes O(r^3 + t^2).
// Space O(n + r^3) (the tables, one entry per outer notch and interval, only for intervals with a
// witness). Pre: a simple counter-clockwise polygon with fewer than 32768 notches. Output: an optimal
// convex decomposition (OPT = r + 1 - the most compatible patterns), Steiner points exact.
//
// Counters, besides the program's and the patterns': "x4_table_entries" (outer notches with a tip
// examined for E and W), "x4_table_witnesses" (entries that found a pattern), "x4_candidates" (pairs
// of Steiner-point candidates tested while filling the tables), "x4_scan_steps" (STEP 3's lookups),
// "x4_chosen" (intervals whose S was reached by an X4-pattern).
#include "algorithms/chazelle_dobkin.h"

#include <cstdint>
#include <stdexcept>

namespace pd {
namespace {

class ProgramCubic final : public cd::Program {
 public:
  explicit ProgramCubic(const Polygon& p)
      : cd::Program(p), notch_count_(static_cast<int>(patterns().notches().size())), e_(cells()), w_(cells()) {
    if (notch_count_ > kMaxNotches) throw std::invalid_argument("chazelle-dobkin: more than 32767 notches");
  }

  void report(Counters& counters) const {
    counters["x4_table_entries"] = table_entries_;
    counters["x4_table_witnesses"] = table_witnesses_;
    counters["x4_candidates"] = candidates_;
    counters["x4_scan_steps"] = scan_steps_;
    counters["x4_chosen"] = chosen_;
  }

 private:
  static constexpr int kMaxNotches = INT16_MAX;
  // A table row: per outer notch, the witness (the other inner notch) or -1; empty when none has one.
  using Row = std::vector<std::int16_t>;

  std::size_t cells() const { return static_cast<std::size_t>(notch_count_) * static_cast<std::size_t>(notch_count_); }
  std::size_t at(int a, int b) const { return static_cast<std::size_t>(a) * notch_count_ + b; }

  // Called once per interval, shortest first (STEP 3): answers from the tables of shorter intervals,
  // then fills this interval's own rows, which need S only strictly inside it.
  std::optional<cd::X4Choice> x4_term(int i, int j, int to_beat) override {
    std::optional<cd::X4Choice> found;
    if (S(i + 1, j - 1) + 1 > to_beat) found = lookup(i, j);
    fill_e(i, j);
    fill_w(i, j);
    return found;
  }

  // T(a, b; m): splitting V(a+1, b-1) at m loses nothing.
  bool tight(int a, int b, int m) const { return S(a + 1, m - 1) + S(m + 1, b - 1) == S(a + 1, b - 1); }

  bool has_tip(int a, int b) { return patterns().has_tip(static_cast<std::size_t>(a), static_cast<std::size_t>(b)); }

  static int witness(const Row& row, int index) { return row.empty() ? -1 : row[static_cast<std::size_t>(index)]; }

  // STEP 3's X4 term: a tight X4-pattern from E(k, j)[i] or W(i, l)[j], with its Steiner points.
  std::optional<cd::X4Choice> lookup(int i, int j) {
    const int count = S(i + 1, j - 1) + 1;
    for (int k = i + 1; k < j; ++k) {
      ++scan_steps_;
      const int l = tight(i, j, k) ? witness(e_[at(k, j)], i) : -1;
      if (l >= 0) return chosen(count, k, l, false, patterns().x4(i, k, l, j));
    }
    for (int l = i + 1; l < j; ++l) {
      ++scan_steps_;
      const int k = tight(i, j, l) ? witness(w_[at(i, l)], j - l - 1) : -1;
      if (k >= 0) return chosen(count, k, l, true, patterns().x4(k, l, j, i));
    }
    return std::nullopt;
  }

  cd::X4Choice chosen(int count, int k, int l, bool wrapped, const std::optional<std::pair<QPoint, QPoint>>& points) {
    if (!points) throw std::logic_error("chazelle-dobkin: an X4 witness no longer tests as a pattern");
    ++chosen_;
    return cd::X4Choice{count, k, l, wrapped, points->first, points->second};
  }

  // E(k, j): for each outer notch i < k, a tight l in (k, j) with an X4-pattern joining (z_i, z_k) and
  // (z_l, z_j).
  void fill_e(int k, int j) {
    std::vector<int> seconds;
    for (int l = k + 1; l < j; ++l)
      if (tight(k, j, l) && has_tip(l, j)) seconds.push_back(l);
    if (seconds.empty()) return;
    Row row(static_cast<std::size_t>(k), -1);
    bool any = false;
    for (int i = 0; i < k; ++i) {
      if (!has_tip(i, k)) continue;
      const int l = first_pattern(seconds, [&](int m) { return patterns().x4(i, k, m, j).has_value(); });
      row[static_cast<std::size_t>(i)] = static_cast<std::int16_t>(l);
      any = any || l >= 0;
    }
    if (any) e_[at(k, j)] = std::move(row);
  }

  // W(i, l): for each outer notch j > l, a tight k in (i, l) with an X4-pattern joining (z_k, z_l) and
  // (z_j, z_i).
  void fill_w(int i, int l) {
    std::vector<int> firsts;
    for (int k = i + 1; k < l; ++k)
      if (tight(i, l, k) && has_tip(k, l)) firsts.push_back(k);
    if (firsts.empty()) return;
    Row row(static_cast<std::size_t>(notch_count_ - l - 1), -1);
    bool any = false;
    for (int j = l + 1; j < notch_count_; ++j) {
      if (!has_tip(j, i)) continue;
      const int k = first_pattern(firsts, [&](int m) { return patterns().x4(m, l, j, i).has_value(); });
      row[static_cast<std::size_t>(j - l - 1)] = static_cast<std::int16_t>(k);
      any = any || k >= 0;
    }
    if (any) w_[at(i, l)] = std::move(row);
  }

  // The first candidate inner notch that makes an X4-pattern, or -1; one table entry.
  template <class IsPattern>
  int first_pattern(const std::vector<int>& candidates, IsPattern is_pattern) {
    ++table_entries_;
    for (int m : candidates) {
      ++candidates_;
      if (is_pattern(m)) return ++table_witnesses_, m;
    }
    return -1;
  }

  int notch_count_;
  std::vector<Row> e_, w_;  // E(k, j) at at(k, j), indexed by i; W(i, l) at at(i, l), indexed by j - l - 1
  std::int64_t table_entries_ = 0, table_witnesses_ = 0, candidates_ = 0, scan_steps_ = 0, chosen_ = 0;
};

Decomposition chazelle_dobkin(const Polygon& p, Counters& counters) {
  ProgramCubic program(p);
  Decomposition d = program.run(counters);
  program.report(counters);
  return d;
}

}  // namespace

REGISTER_ALGORITHM(Algorithm{"chazelle-dobkin", Kind::Convex, true, true, "n*log(n)+n*r+r^5*log(n/r)", "== OPT",
                             "Chazelle thesis (000) Sec. 2.4, Def. 2.4, Thm 18, Lemma 9", 20000, chazelle_dobkin});

}  // namespace pd
