// Algorithm CD, the dynamic program of Chazelle and Dobkin: see program.h for the method, the
// reconstructions of the thesis's garbled definitions and the bounds.
#include "engines/chazelle_dobkin/program.h"

#include <array>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace pd::cd {

Program::Program(const Polygon& p)
    : p_(p), patterns_(p), r_(static_cast<int>(patterns_.notches().size())),
      best_(static_cast<std::size_t>(r_) * r_), b_(best_.size()), f_(best_.size()), b_joint_(best_.size()),
      f_joint_(best_.size()) {}

Decomposition Program::run(Counters& counters) {
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

AdaptedNotch Program::with_b(int i, int j) const {
  AdaptedNotch a = patterns_.bare(i);
  if (i < j && B(i, j).how != Hang::Bare) a.forward = B(i, j).far;
  return a;
}

AdaptedNotch Program::with_f(int i, int j) const {
  AdaptedNotch a = patterns_.bare(j);
  if (i < j && F(i, j).how != Hang::Bare) a.backward = F(i, j).far;
  return a;
}

const Joint& Program::joint_b(int i, int j) const {
  return i < j && B(i, j).how != Hang::Bare ? joints_[b_joint_[at(i, j)]] : patterns_.bare_joint(i);
}

const Joint& Program::joint_f(int i, int j) const {
  return i < j && F(i, j).how != Hang::Bare ? joints_[f_joint_[at(i, j)]] : patterns_.bare_joint(j);
}

std::size_t Program::keep(Joint joint) {
  joints_.push_back(std::move(joint));
  return joints_.size() - 1;
}

Best Program::step3(int i, int j) {
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

bool Program::hangs_forward(int v, const QPoint& far) const {
  const Joint& j = patterns_.forward_branch(v);
  return orient(z(v), j.lower, far) > 0 && orient(z(v), j.upper, far) < 0;
}

bool Program::hangs_backward(int v, const QPoint& far) const {
  const Joint& j = patterns_.backward_branch(v);
  return orient(z(v), j.lower, far) > 0 && orient(z(v), j.upper, far) < 0;
}

Subtree Program::step4_b(int i, int j) {
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

Subtree Program::step4_f(int i, int j) {
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

VertexId Program::vertex(int k) {
  used_[k] = 1;
  return patterns_.notches()[k];
}

VertexId Program::steiner(Decomposition& d, const QPoint& s) {
  return static_cast<VertexId>(p_.size() + d.add_steiner(s));
}

void Program::star(Decomposition& d, const QPoint& s, std::initializer_list<int> notches) {
  const VertexId id = steiner(d, s);
  for (int k : notches) d.add_cut(vertex(k), id);
}

void Program::emit_s(int i, int j, Decomposition& d) {
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

void Program::emit_b(int i, int j, Decomposition& d) {
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

void Program::emit_f(int i, int j, Decomposition& d) {
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

}  // namespace pd::cd
