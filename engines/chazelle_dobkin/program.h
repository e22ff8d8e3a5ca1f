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
// in engines/chazelle_dobkin/patterns.h.
//
// Orientation: the thesis walks the boundary clockwise; our polygons are counter-clockwise and the
// notches z_0..z_{r-1} are taken in index order, so the thesis's R_i (the edge towards V(i, j)) is our
// forward edge (z_i, z_i + 1) and its L_i our backward edge. Because patterns do not interleave, the
// intervals need not wrap: S(0, r-1) is the answer.
//
// Reconstructions where the OCR text is garbled and the figures are lost (which Y-subtree B(i, j)
// keeps, how a subtree is recorded, an empty B(i, j), B4's Steiner point and its 1/64 compromise):
// docs/algorithms/chazelle-dobkin-patterns.md, "The dynamic program". STEP 3's X4 term is left to
// the variant (x4_term).
// Deviation: superranges are replaced by trees of geodesics from each notch over a decomposition by
// vertical chords (engines/chazelle_dobkin/geodesics.h), in the same O(n + r^2 log n) preprocessing.
//
// Time, apart from x4_term: that preprocessing; the joint of each of the O(r^2) stored subtrees is
// built once; then O(r^3) pattern tests (STEPs 2 and 4: O(r) per interval), each O(1) (Theorems 13
// and 14, engines/chazelle_dobkin/patterns.h); STEP 5's naive completion, O(n + r^2 log(n/r)). Space O(r^2)
// subproblems and subtree joints, plus O(n).
// Output: exactly r + 1 - S(0, r-1) convex pieces; Steiner points exact.
#pragma once

#include "engines/chazelle_dobkin/patterns.h"
#include "engines/naive/naive.h"

#include <array>
#include <deque>
#include <initializer_list>
#include <optional>

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
  explicit Program(const Polygon& p);

  // STEPs 1-5. Throws std::logic_error if the patterns laid out do not add up to S(0, r-1).
  Decomposition run(Counters& counters);

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
  AdaptedNotch with_b(int i, int j) const;
  AdaptedNotch with_f(int i, int j) const;
  // Their joints, computed once per subtree (the program asks for them O(r^3) times).
  const Joint& joint_b(int i, int j) const;
  const Joint& joint_f(int i, int j) const;
  std::size_t keep(Joint joint);

  // STEPs 2 and 3.
  Best step3(int i, int j);

  // Whether an edge from notch v to `far` hangs forward and leaves v's angle on its other side reflex.
  bool hangs_forward(int v, const QPoint& far) const;
  bool hangs_backward(int v, const QPoint& far) const;

  // STEP 4, B(i, j): the free subtree at z_i in V(i, j) whose edge turns furthest towards L_i.
  Subtree step4_b(int i, int j);

  // STEP 4, F(i, j): the mirror image at z_j.
  Subtree step4_f(int i, int j);

  // ---- laying out the chosen patterns (Theorem 10's graph) ----

  VertexId vertex(int k);
  VertexId steiner(Decomposition& d, const QPoint& s);
  void star(Decomposition& d, const QPoint& s, std::initializer_list<int> notches);

  void emit_s(int i, int j, Decomposition& d);

  // A subtree with the patterns between its notches.
  void emit_b(int i, int j, Decomposition& d);
  void emit_f(int i, int j, Decomposition& d);

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
