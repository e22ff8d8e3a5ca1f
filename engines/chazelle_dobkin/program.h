// Algorithm CD, the dynamic program of Chazelle and Dobkin's optimal convex decomposition with Steiner
// points (B. Chazelle, Computational Geometry and Convexity, thesis, Yale 1980 (000), Sec. 2.3.6,
// Theorems 16-17), for chazelle-dobkin-n5 and chazelle-dobkin, which differ in STEP 3's X4 term.
//
// Method. An optimal decomposition has r + 1 - p pieces, p the most compatible X-patterns (Theorem 7),
// and every pattern can be taken to be a Y-pattern or an X4-pattern (Theorem 9). Patterns whose
// notches do not interleave round the boundary never cross (Sec. 2.3.6.1), so a dynamic program over
// intervals V(i, j) of consecutive notches finds p: S(i, j) is the most compatible patterns with notches
// in V(i, j) (STEP 3: a split, an X4-pattern or a Y-pattern joining z_i and z_j, plus the intervals
// between its notches); the Y-pattern joining z_i and z_j comes from patching the Y-subtrees kept in
// B(.,.) and F(.,.) (STEP 2: cases Y1-Y4 of <ARG>), and B(i, j), F(i, j) are the one candidate subtree
// hanging at z_i (resp. z_j) into V(i, j) (STEP 4: cases B1-B4, F1-F4 with the functions Y and Y').
// STEP 5 finishes the remaining notches with the naive decomposition searched through the boundary's
// convex chains (naive_complete_chains, engines/naive/naive.h; Theorem 4), and the cut graph is turned
// into pieces by the shared routine (Theorem 10). Pattern detection (Theorems 13-15, Corollary 14) is
// in chazelle_dobkin_patterns.h.
//
// Orientation: the thesis walks the boundary clockwise; our polygons are counter-clockwise and the
// notches z_0..z_{r-1} are taken in index order, so the thesis's R_i (the edge towards V(i, j)) is our
// forward edge (z_i, z_i + 1) and its L_i our backward edge. Because patterns do not interleave, the
// intervals need not wrap: S(0, r-1) is the answer.
//
// Reconstructions (the OCR text is garbled where the candidates are defined and the figures are lost):
// - A Y-subtree is kept in B(i, j) only when it is "free" (relation 3: the best patterns between its
//   notches number |S(i, j)|). A free subtree never resolves z_i by itself (it would then be a
//   pattern, one more than |S(i, j)|), so the angle it leaves at z_i is reflex, and a second branch
//   there must lie in the cone between the extension of its edge and that of L_i. That cone widens as
//   the edge turns towards L_i, so among the candidates the one whose edge turns furthest towards L_i
//   is kept: the thesis's "maximizes u = (t, L_i)" of STEP 4 (Sec. 2.3.6.1 says "minimizes (L_i, t)",
//   the same angle measured the other way). F mirrors B.
// - A subtree is represented here by how it was built (B1: the narrower B(i, k); B2: an edge to z_k
//   and B(k, j); B3: an edge to z_j and F(i+1, j); B4: a Steiner point joining z_i to z_k and z_j with
//   F(i+1, k) and F(k+1, j)), and its edge at z_i by the point it reaches; the patterns are laid out
//   from these records once the program is done.
// - An empty B(i, j) (the thesis's (R(v_i, R_i), 0)) leaves z_i a leaf of the pattern; the count of the
//   notches beside it then excludes z_i (S(i+1, j) rather than S(i, j)), which the thesis's formulas
//   leave implicit.
// - B4's Steiner point (Corollary 14.2) is the point of the feasible region turned furthest around
//   z_i, which lies on the region's boundary (an edge through a vertex of P, or along a range); it is
//   moved 1/64 of the way towards the region's average so that its edges are interior. A later patch
//   that needs the edge turned further than that point is missed: a compromise of exactness against
//   the thesis's extreme (a symbolic perturbation would remove it); no test has met such a case.
// - STEP 3's X4 term is left to the variant (x4_term).
// Deviation: superranges are replaced by trees of geodesics from each notch over a decomposition by
// vertical chords (chazelle_dobkin_patterns.h), in the same O(n + r^2 log n) preprocessing.
//
// Time, apart from x4_term: that preprocessing; the joint of each of the O(r^2) stored subtrees is
// built once; then O(r^3) pattern tests (STEPs 2 and 4: O(r) per interval), each O(1) (Theorems 13
// and 14, chazelle_dobkin_patterns.h); STEP 5's naive completion, O(n + r^2 log(n/r)). Space O(r^2)
// subproblems and subtree joints, plus O(n).
// Output: exactly r + 1 - S(0, r-1) convex pieces; Steiner points exact.
#pragma once

#include "engines/chazelle_dobkin/patterns.h"
#include "engines/naive/naive.h"

#include <array>
#include <deque>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>

namespace pd::cd {

// How a Y-subtree hanging at a notch was built (STEP 4's B1-B4, F1-F4).
enum class Hang : std::uint8_t { Bare, Narrower, ToNotch, ToEnd, ToSteiner };

struct Subtree {
  Hang how = Hang::Bare;
  int k = 0;   // Narrower: the narrower entry's other end; ToNotch: the notch reached; ToSteiner: the middle notch
  QPoint far;  // the other end of the subtree's edge at its notch
};

// An X4-pattern on z_i, z_k, z_l, z_j (k < l inside the interval) and the count it reaches.
struct X4Choice {
  int count;
  int k, l;
  bool wrapped;  // the first Steiner point joins z_k and z_l, the second z_j and z_i (else z_i, z_k; z_l, z_j)
  QPoint first, second;
};

// How S(i, j) was reached (STEP 3).
enum class Way : std::uint8_t { Empty, Split, X4, Y1, Y2, Y3, Y4 };

struct Best {
  int count = 0;
  Way way = Way::Empty;
  int k = 0, l = 0;            // Split, Y: k; X4: the inner notches k < l
  bool wrapped = false;        // X4: the first Steiner point joins z_k, z_l (else z_i, z_k)
  QPoint first{}, second{};    // Steiner points: Y3, Y4: first; X4: both
};

class Program {
 public:
  virtual ~Program() = default;
  explicit Program(const Polygon& p)
      : p_(p), patterns_(p), r_(static_cast<int>(patterns_.notches().size())),
        best_(static_cast<std::size_t>(r_) * r_), b_(best_.size()), f_(best_.size()), b_joint_(best_.size()),
        f_joint_(best_.size()) {}

  // STEPs 1-5. Throws std::logic_error if the patterns laid out do not add up to S(0, r-1).
  Decomposition run(Counters& counters) {
    for (int d = 1; d < r_; ++d)
      for (int i = 0; i + d < r_; ++i) {
        const int j = i + d;
        ++subproblems_;
        best_[at(i, j)] = step3(i, j);
        b_[at(i, j)] = step4_b(i, j);
        if (B(i, j).how != Hang::Bare) b_joint_[at(i, j)] = keep(patterns_.joint(with_b(i, j)));
        f_[at(i, j)] = step4_f(i, j);
        if (F(i, j).how != Hang::Bare) f_joint_[at(i, j)] = keep(patterns_.joint(with_f(i, j)));
      }
    Decomposition d;
    used_.assign(r_, 0);
    if (r_ > 0) emit_s(0, r_ - 1, d);
    if (r_ > 0 && emitted_patterns_ != S(0, r_ - 1))
      throw std::logic_error("chazelle-dobkin: laid out " + std::to_string(emitted_patterns_) + " patterns, counted " +
                             std::to_string(S(0, r_ - 1)));
    std::vector<VertexId> rest;
    for (int k = 0; k < r_; ++k)
      if (!used_[k]) rest.push_back(patterns_.notches()[k]);
    const std::size_t steiner = d.steiner.size();
    d = naive_complete_chains(p_, std::move(d), rest, counters);
    patterns_.report(counters);
    counters["subproblems"] = subproblems_;
    counters["y_found"] = y_found_;
    counters["patterns"] = emitted_patterns_;
    counters["pattern_steiner_points"] = static_cast<std::int64_t>(steiner);
    return d;
  }

 protected:
  // STEP 3's B: the best X4-pattern joining z_i and z_j, with the patterns between its notches, if it
  // counts more than `to_beat`.
  virtual std::optional<X4Choice> x4_term(int i, int j, int to_beat) = 0;
  // Called on each X4-pattern laid out, the first Steiner point x joining notches[0] and notches[1],
  // the second y joining notches[2] and notches[3]; throws std::logic_error if it is not one. A
  // variant whose x4_term returns only tested patterns need not check again.
  virtual void check_x4(const std::array<int, 4>& /*notches*/, const QPoint& /*x*/, const QPoint& /*y*/) {}

  int S(int i, int j) const { return i >= j ? 0 : best_[at(i, j)].count; }
  Patterns& patterns() { return patterns_; }
  const Polygon& polygon() const { return p_; }

 private:
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(i) * r_ + j; }
  const Subtree& B(int i, int j) const { return b_[at(i, j)]; }
  const Subtree& F(int i, int j) const { return f_[at(i, j)]; }
  // The patterns beside a subtree: its free count, or without its notch when it is bare.
  int free_b(int i, int j) const { return B(i, j).how == Hang::Bare ? S(i + 1, j) : S(i, j); }
  int free_f(int i, int j) const { return F(i, j).how == Hang::Bare ? S(i, j - 1) : S(i, j); }
  const QPoint& z(int k) const { return patterns_.notch_point(k); }

  // The notch adapted to the subtree hanging at it (Corollary 14.1).
  AdaptedNotch with_b(int i, int j) const {
    AdaptedNotch a = patterns_.bare(i);
    if (i < j && B(i, j).how != Hang::Bare) a.forward = B(i, j).far;
    return a;
  }
  AdaptedNotch with_f(int i, int j) const {
    AdaptedNotch a = patterns_.bare(j);
    if (i < j && F(i, j).how != Hang::Bare) a.backward = F(i, j).far;
    return a;
  }
  // Their joints, computed once per subtree (the program asks for them O(r^3) times).
  const Joint& joint_b(int i, int j) const {
    return i < j && B(i, j).how != Hang::Bare ? joints_[b_joint_[at(i, j)]] : patterns_.bare_joint(i);
  }
  const Joint& joint_f(int i, int j) const {
    return i < j && F(i, j).how != Hang::Bare ? joints_[f_joint_[at(i, j)]] : patterns_.bare_joint(j);
  }
  std::size_t keep(Joint joint) {
    joints_.push_back(std::move(joint));
    return joints_.size() - 1;
  }

  // STEPs 2 and 3.
  Best step3(int i, int j) {
    Best best;
    auto offer = [&](int count, const Best& way) {
      if (count > best.count) best = way, best.count = count;
    };
    for (int k = i; k < j; ++k) offer(S(i, k) + S(k + 1, j), {0, Way::Split, k});
    for (int k = i + 1; k < j; ++k) {  // Y1: z_k an N2-node between F(i, k) and B(k, j)
      const Subtree &left = F(i, k), &right = B(k, j);
      if (left.how == Hang::Bare || right.how == Hang::Bare || S(i, k) + S(k, j) + 1 <= best.count) continue;
      if (orient(z(k), right.far, left.far) >= 0) ++y_found_, offer(S(i, k) + S(k, j) + 1, {0, Way::Y1, k});
    }
    for (int k = i + 1; k <= j; ++k) {  // Y2: the edge z_i z_j
      const int count = free_b(i, k - 1) + free_f(k, j) + 1;
      if (count > best.count && patterns_.x2(with_b(i, k - 1), with_f(k, j))) ++y_found_, offer(count, {0, Way::Y2, k});
    }
    for (int k = i + 1; k < j; ++k) {  // Y3: a Steiner point joining z_i, z_k (subtrees ahead) and z_j
      const int count = free_b(i, k - 1) + free_b(k, j - 1) + 1;
      if (count <= best.count) continue;
      const auto s = patterns_.x3(joint_b(i, k - 1), joint_b(k, j - 1),
                                  patterns_.bare_joint(j));
      if (s) ++y_found_, offer(count, {0, Way::Y3, k, 0, false, *s});
    }
    for (int k = i + 1; k < j; ++k) {  // Y4: a Steiner point joining z_i and z_k, z_j (subtrees behind)
      const int count = free_f(i + 1, k) + free_f(k + 1, j) + 1;
      if (count <= best.count) continue;
      const auto s = patterns_.x3(patterns_.bare_joint(i), joint_f(i + 1, k),
                                  joint_f(k + 1, j));
      if (s) ++y_found_, offer(count, {0, Way::Y4, k, 0, false, *s});
    }
    if (const auto x = x4_term(i, j, best.count)) offer(x->count, {0, Way::X4, x->k, x->l, x->wrapped, x->first, x->second});
    return best;
  }

  // Whether an edge from notch v to `far` hangs forward and leaves v's angle on its other side reflex.
  bool hangs_forward(int v, const QPoint& far) const {
    const Joint& j = patterns_.forward_branch(v);
    return orient(z(v), j.lower, far) > 0 && orient(z(v), j.upper, far) < 0;
  }
  bool hangs_backward(int v, const QPoint& far) const {
    const Joint& j = patterns_.backward_branch(v);
    return orient(z(v), j.lower, far) > 0 && orient(z(v), j.upper, far) < 0;
  }

  // STEP 4, B(i, j): the free subtree at z_i in V(i, j) whose edge turns furthest towards L_i.
  Subtree step4_b(int i, int j) {
    const int c = S(i, j);
    Subtree best;
    auto offer = [&](const Subtree& t) {
      if (best.how == Hang::Bare || orient(z(i), best.far, t.far) > 0) best = t;
    };
    for (int k = i + 1; k < j; ++k)  // B1
      if (B(i, k).how != Hang::Bare && S(i, k) + S(k + 1, j) == c) offer({Hang::Narrower, k, B(i, k).far});
    for (int k = i + 1; k <= j; ++k) {  // B2 (k < j) and B3 (k = j): an edge z_i z_k
      const bool to_end = k == j;
      if ((to_end ? free_f(i + 1, j) : S(i + 1, k - 1) + free_b(k, j)) != c) continue;
      const AdaptedNotch there = to_end ? with_f(i + 1, j) : with_b(k, j);
      if (patterns_.diagonal(i, k) && patterns_.resolves(there, z(i)) && hangs_forward(i, z(k)))
        offer({to_end ? Hang::ToEnd : Hang::ToNotch, k, z(k)});
    }
    for (int k = i + 1; k < j; ++k) {  // B4
      if (free_f(i + 1, k) + free_f(k + 1, j) != c) continue;
      const auto s = patterns_.x3_extreme(patterns_.forward_branch(i), joint_f(i + 1, k),
                                          joint_f(k + 1, j), true);
      if (s) offer({Hang::ToSteiner, k, *s});
    }
    return best;
  }

  // STEP 4, F(i, j): the mirror image at z_j.
  Subtree step4_f(int i, int j) {
    const int c = S(i, j);
    Subtree best;
    auto offer = [&](const Subtree& t) {
      if (best.how == Hang::Bare || orient(z(j), best.far, t.far) < 0) best = t;
    };
    for (int k = i + 1; k < j; ++k)  // F1
      if (F(k, j).how != Hang::Bare && S(i, k - 1) + S(k, j) == c) offer({Hang::Narrower, k, F(k, j).far});
    for (int k = i; k < j; ++k) {  // F2 (k > i) and F3 (k = i): an edge z_j z_k
      const bool to_end = k == i;
      if ((to_end ? free_b(i, j - 1) : free_f(i, k) + S(k + 1, j - 1)) != c) continue;
      const AdaptedNotch there = to_end ? with_b(i, j - 1) : with_f(i, k);
      if (patterns_.diagonal(j, k) && patterns_.resolves(there, z(j)) && hangs_backward(j, z(k)))
        offer({to_end ? Hang::ToEnd : Hang::ToNotch, k, z(k)});
    }
    for (int k = i + 1; k < j; ++k) {  // F4
      if (free_b(i, k - 1) + free_b(k, j - 1) != c) continue;
      const auto s = patterns_.x3_extreme(patterns_.backward_branch(j), joint_b(i, k - 1),
                                          joint_b(k, j - 1), false);
      if (s) offer({Hang::ToSteiner, k, *s});
    }
    return best;
  }

  // ---- laying out the chosen patterns (Theorem 10's graph) ----

  VertexId vertex(int k) {
    used_[k] = 1;
    return patterns_.notches()[k];
  }
  VertexId steiner(Decomposition& d, const QPoint& s) { return static_cast<VertexId>(p_.size() + d.add_steiner(s)); }
  void star(Decomposition& d, const QPoint& s, std::initializer_list<int> notches) {
    const VertexId id = steiner(d, s);
    for (int k : notches) d.add_cut(vertex(k), id);
  }

  void emit_s(int i, int j, Decomposition& d) {
    if (i >= j) return;
    const Best& b = best_[at(i, j)];
    const int k = b.k, l = b.l;
    if (b.way != Way::Empty && b.way != Way::Split) ++emitted_patterns_;
    switch (b.way) {
      case Way::Empty: return;
      case Way::Split: emit_s(i, k, d), emit_s(k + 1, j, d); return;
      case Way::Y1: emit_f(i, k, d), emit_b(k, j, d); return;
      case Way::Y2: d.add_cut(vertex(i), vertex(j)), emit_b(i, k - 1, d), emit_f(k, j, d); return;
      case Way::Y3: star(d, b.first, {i, k, j}), emit_b(i, k - 1, d), emit_b(k, j - 1, d); return;
      case Way::Y4: star(d, b.first, {i, k, j}), emit_f(i + 1, k, d), emit_f(k + 1, j, d); return;
      case Way::X4: {
        const VertexId a = steiner(d, b.first), c = steiner(d, b.second);
        const std::array<int, 2> at_first = b.wrapped ? std::array<int, 2>{k, l} : std::array<int, 2>{i, k};
        const std::array<int, 2> at_second = b.wrapped ? std::array<int, 2>{j, i} : std::array<int, 2>{l, j};
        check_x4({at_first[0], at_first[1], at_second[0], at_second[1]}, b.first, b.second);
        for (int n : at_first) d.add_cut(vertex(n), a);
        for (int n : at_second) d.add_cut(vertex(n), c);
        d.add_cut(a, c);
        emit_s(i + 1, k - 1, d), emit_s(k + 1, l - 1, d), emit_s(l + 1, j - 1, d);
        return;
      }
    }
  }

  // A subtree with the patterns between its notches.
  void emit_b(int i, int j, Decomposition& d) {
    const Subtree& t = i < j ? B(i, j) : Subtree{};
    const int k = t.k;
    switch (t.how) {
      case Hang::Bare: vertex(i), emit_s(i + 1, j, d); return;
      case Hang::Narrower: emit_b(i, k, d), emit_s(k + 1, j, d); return;
      case Hang::ToNotch: d.add_cut(vertex(i), vertex(k)), emit_s(i + 1, k - 1, d), emit_b(k, j, d); return;
      case Hang::ToEnd: d.add_cut(vertex(i), vertex(j)), emit_f(i + 1, j, d); return;
      case Hang::ToSteiner: star(d, t.far, {i, k, j}), emit_f(i + 1, k, d), emit_f(k + 1, j, d); return;
    }
  }
  void emit_f(int i, int j, Decomposition& d) {
    const Subtree& t = i < j ? F(i, j) : Subtree{};
    const int k = t.k;
    switch (t.how) {
      case Hang::Bare: vertex(j), emit_s(i, j - 1, d); return;
      case Hang::Narrower: emit_f(k, j, d), emit_s(i, k - 1, d); return;
      case Hang::ToNotch: d.add_cut(vertex(j), vertex(k)), emit_s(k + 1, j - 1, d), emit_f(i, k, d); return;
      case Hang::ToEnd: d.add_cut(vertex(j), vertex(i)), emit_b(i, j - 1, d); return;
      case Hang::ToSteiner: star(d, t.far, {j, i, k}), emit_b(i, k - 1, d), emit_b(k, j - 1, d); return;
    }
  }

  const Polygon& p_;
  Patterns patterns_;
  int r_;
  std::vector<Best> best_;
  std::vector<Subtree> b_, f_;
  // The joints at the notches adapted to the non-bare subtrees, and where each interval's are.
  std::deque<Joint> joints_;
  std::vector<std::size_t> b_joint_, f_joint_;
  std::vector<char> used_;
  std::int64_t subproblems_ = 0, y_found_ = 0, emitted_patterns_ = 0;
};

}  // namespace pd::cd
