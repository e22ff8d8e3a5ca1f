// chazelle-dobkin's program and its X4 tables (Sec. 2.4 of Chazelle's thesis): the loose rays with their
// sorted lists, the table entry (Witness) and the program whose STEP 3 fills and reads the rows E and W.
// The paper, the reconstructions with their proofs, the bounds, the preconditions and the deviations are
// in the header of algorithms/chazelle_dobkin_cubic.cpp, which registers the algorithm. The classes are
// here so that the tests can read the rows the program fills (entry(), S()) after its run.
#pragma once

#include "algorithms/chazelle_dobkin.h"
#include "algorithms/ray_shooting.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pd::cd {

// The loose rays of Definition 2.4 and, for every pair of them, where their lines meet (the thesis's
// points A_ik and its lists sorted along each ray). Ray a = 2 v + side is the extension beyond notch v of
// its forward edge (side 0, the thesis's r_v) or of its backward edge (side 1), clipped at its first
// contact with the boundary, a vertex included.
class LooseRays {
 public:
  LooseRays(const Polygon& p, const Patterns& patterns) : count_(2 * static_cast<int>(patterns.notches().size())) {
    shoot(p, patterns);
    const std::size_t cells = static_cast<std::size_t>(count_) * static_cast<std::size_t>(count_);
    cross_sign_.assign(cells, 0);
    base_side_.assign(cells, 0);
    meet_sign_.assign(cells, 0);
    key_.assign(cells, -1);
    opens_.assign(cells, 0);
    std::vector<Rational> meet(cells);
    for (int a = 0; a < count_; ++a)
      for (int b = 0; b < count_; ++b) relate(a, b, meet);
    for (int a = 0; a < count_; ++a) list_loose_points(a, sorted_along(a, meet), meet);
  }

  static int notch(int ray) { return ray / 2; }
  // sign(u_a x u_b): +1 when b's direction turns counter-clockwise from a's.
  int cross_sign(int a, int b) const { return cross_sign_[cell(a, b)]; }
  // Rank of the parameter on a's line where b's line meets it, among all such parameters on a's line
  // (equal parameters, equal ranks); -1 when they are parallel or of the same notch.
  int key(int a, int b) const { return key_[cell(a, b)]; }
  // The sign of that parameter (the notch is at 0).
  int meet_sign(int a, int b) const { return meet_sign_[cell(a, b)]; }
  // Which side of the directed line of a the point where b's line meets c's lies on: +1 left, -1 right,
  // 0 on it. O(1): a threshold on b's line, or a constant when a and b are parallel.
  int side(int a, int b, int c) const {
    const int s = cross_sign(a, b);
    return s == 0 ? base_side_[cell(a, b)] : s * compare(key(b, c), key(b, a));
  }
  // sign(u_a x (z_b - z_a)): which side of a's line b's notch lies on.
  int base_side(int a, int b) const { return base_side_[cell(a, b)]; }
  // Whether the lines of a and b meet strictly inside both clipped rays (a loose point, the thesis's
  // A_ik) and the notches of a and b, seen from it, turn counter-clockwise.
  bool opens(int a, int b) const { return opens_[cell(a, b)] != 0; }
  // The loose points on a, in order along it: the rays b whose lines meet a's strictly inside both.
  const std::vector<int>& along(int a) const { return along_[a]; }
  QPoint point(int a, int b) const {
    const Rational s = parameter(a, b);
    return origin_[a] + s * direction_[a];
  }
  std::int64_t stopped_at_vertices() const { return std::count(at_vertex_.begin(), at_vertex_.end(), 1); }
  std::int64_t loose_points() const { return loose_points_; }

 private:
  using Vec = ExactKernel::Vector_2;

  static int compare(int a, int b) { return a < b ? -1 : (a > b ? 1 : 0); }

  std::size_t cell(int a, int b) const { return static_cast<std::size_t>(a) * count_ + b; }

  // Each ray's direction and reach (the parameter of its first contact): O(r log n) per ray.
  void shoot(const Polygon& p, const Patterns& patterns) {
    RayShooter shooter(p);
    for (int a = 0; a < count_; ++a) {
      const std::size_t v = patterns.notches()[static_cast<std::size_t>(notch(a))];
      const std::size_t away = a % 2 == 0 ? p.next(v) : p.prev(v);
      const QPoint z = to_exact(p[v]);
      const Vec u = z - to_exact(p[away]);
      const auto hit = shooter.shoot(v, away, false);
      if (!hit) throw std::logic_error("chazelle-dobkin: a notch's loose ray leaves the polygon");
      const QPoint w = to_exact(p[hit->vertex]);
      Rational reach;
      if (hit->at_vertex) {
        reach = ((w - z) * u) / (u * u);
      } else {
        const Vec e = to_exact(p[p.next(hit->vertex)]) - w;
        reach = CGAL::determinant(w - z, e) / CGAL::determinant(u, e);
      }
      origin_.push_back(z);
      direction_.push_back(u);
      reach_.push_back(reach);
      at_vertex_.push_back(hit->at_vertex ? 1 : 0);
    }
  }

  // Where b's line crosses a's, as a parameter along a (z_a + s u_a). Pre: not parallel.
  Rational parameter(int a, int b) const {
    const Vec& ub = direction_[b];
    return -CGAL::determinant(ub, origin_[a] - origin_[b]) / CGAL::determinant(ub, direction_[a]);
  }

  // The O(1) facts about a pair of rays, computed once: O(r^2) in all.
  void relate(int a, int b, std::vector<Rational>& meet) {
    const std::size_t c = cell(a, b);
    cross_sign_[c] = static_cast<std::int8_t>(CGAL::sign(CGAL::determinant(direction_[a], direction_[b])));
    base_side_[c] = static_cast<std::int8_t>(CGAL::sign(CGAL::determinant(direction_[a], origin_[b] - origin_[a])));
    if (notch(a) == notch(b) || cross_sign_[c] == 0) return;
    meet[c] = parameter(a, b);
    meet_sign_[c] = static_cast<std::int8_t>(CGAL::sign(meet[c]));
  }

  // The rays whose lines cross a's, in order along a, with their ranks: O(r log r).
  std::vector<int> sorted_along(int a, const std::vector<Rational>& meet) {
    std::vector<int> rays;
    for (int b = 0; b < count_; ++b)
      if (notch(a) != notch(b) && cross_sign(a, b) != 0) rays.push_back(b);
    std::sort(rays.begin(), rays.end(), [&](int x, int y) { return meet[cell(a, x)] < meet[cell(a, y)]; });
    int rank = -1;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      if (k == 0 || meet[cell(a, rays[k - 1])] < meet[cell(a, rays[k])]) ++rank;
      key_[cell(a, rays[k])] = rank;
    }
    return rays;
  }

  // The loose points on a, in order along it.
  void list_loose_points(int a, const std::vector<int>& sorted, const std::vector<Rational>& meet) {
    std::vector<int> points;
    for (int b : sorted) {
      const Rational &s = meet[cell(a, b)], &t = meet[cell(b, a)];
      if (s <= 0 || s >= reach_[a] || t <= 0 || t >= reach_[b]) continue;
      const QPoint x = origin_[a] + s * direction_[a];
      opens_[cell(a, b)] = orient(x, origin_[a], origin_[b]) > 0;
      points.push_back(b);
      loose_points_ += a < b;
    }
    along_.push_back(std::move(points));
  }

  int count_;
  std::vector<QPoint> origin_;
  std::vector<Vec> direction_;
  std::vector<Rational> reach_;
  std::vector<char> at_vertex_;
  std::vector<std::int8_t> cross_sign_, base_side_, meet_sign_, opens_;
  std::vector<int> key_;
  std::vector<std::vector<int>> along_;
  std::int64_t loose_points_ = 0;
};

// A table entry: the inner notch of an X4-pattern found for this outer notch, or -1, and the sides of
// the four loose rays it uses (bit 0: the outer notch's, 1: g's, 2: the inner notch's, 3: h's).
struct Witness {
  std::int16_t inner = -1;
  std::uint8_t sides = 0;
};

class ProgramCubic final : public Program {
 public:
  explicit ProgramCubic(const Polygon& p)
      : Program(p), notch_count_(checked(patterns().notches().size())), rays_(p, patterns()),
        rows_(static_cast<std::size_t>(notch_count_) * static_cast<std::size_t>(notch_count_)) {}

  void report(Counters& counters) const {
    counters["x4_loose_points"] = rays_.loose_points();
    counters["x4_table_entries"] = table_entries_;
    counters["x4_table_witnesses"] = table_witnesses_;
    counters["x4_found"] += table_witnesses_;
    counters["x4_scan_steps"] = scan_steps_;
    counters["x4_p4_tests"] = p4_tests_;
    counters["x4_lookup_steps"] = lookup_steps_;
    counters["x4_chosen"] = chosen_;
    counters["x4_chosen_from_w"] = chosen_from_w_;
    counters["x4_rays_at_vertex"] = rays_.stopped_at_vertices();
  }

  // The row of interval (g, h) at outer notch q, as STEP 3 reads it: E(g, h)[q] for q < g, W(g, h)[q]
  // for q > h (no witness before (g, h) is filled, and never for h - g < 2 or q in [g, h]).
  Witness entry(int g, int h, int q) const {
    const Row& row = rows_[at(g, h)];
    return row.empty() ? Witness{} : row[static_cast<std::size_t>(q)];
  }
  // S(i, j) of Algorithm CD, the table whose tightness T selects the inner notches of the rows.
  using Program::S;

 private:
  using Segment = ExactKernel::Segment_2;

  static constexpr int kMaxNotches = INT16_MAX;
  // The notch count, refused before any table is built when a witness could not hold it.
  static int checked(std::size_t notches) {
    if (notches > static_cast<std::size_t>(kMaxNotches))
      throw std::invalid_argument("chazelle-dobkin: more than 32767 notches");
    return static_cast<int>(notches);
  }
  // The rows of interval (g, h): per outer notch q, E(g, h)[q] for q < g and W(g, h)[q] for q > h.
  using Row = std::vector<Witness>;

  // An X4-pattern on notches q, g, m, h in counter-clockwise cyclic order: X joins z_q and z_g, on g's
  // ray G, Y joins z_m and z_h, on h's ray H. E(k, j)[i] is (q, g, m, h) = (i, k, l, j); W(i, l)[j] is
  // (j, i, k, l).
  struct Query {
    int ray, along;  // Q, and X's rank along G
  };
  struct Insert {
    int ray, along, at;  // M, the rank along G where M's line crosses it, and Y's rank along H
  };

  // The Y inserted so far in one pass of a scan, in order along H (by rank, then by ray): a doubly
  // linked list over the pass's inserts. Where each insert goes is found beforehand, offline: its
  // neighbours at its insertion are its neighbours in the full list once every insert after it is
  // unlinked, so unlinking them all in reverse order of insertion finds every one of them in O(1).
  // A pass is then O(inserts) in all (an ordered set would be O(log r) per insert).
  class Inserted {
   public:
    // `by_at`: this pass's inserts (positions into the scan's inserts, at most `inserts`) in order
    // along H; `order`: the same positions in the order they will be inserted.
    Inserted(std::size_t inserts, const std::vector<int>& by_at, const std::vector<int>& order)
        : prev_(inserts + 2), next_(inserts + 2), left_(inserts), right_(inserts) {
      int last = head();
      for (int k : by_at) {
        link(last, k);
        last = k;
      }
      link(last, tail());
      for (auto k = order.rbegin(); k != order.rend(); ++k) {
        left_[*k] = prev_[*k];
        right_[*k] = next_[*k];
        link(prev_[*k], next_[*k]);
      }
    }
    void insert(int k) {
      link(left_[k], k);
      link(k, right_[k]);
    }
    bool empty() const { return next_[head()] == tail(); }
    int first() const { return next_[head()]; }
    int last() const { return prev_[tail()]; }
    int after(int k) const { return next_[k]; }
    int before(int k) const { return prev_[k]; }
    bool is_end(int k) const { return k >= head(); }

   private:
    int head() const { return static_cast<int>(left_.size()); }
    int tail() const { return head() + 1; }
    void link(int a, int b) { next_[a] = b, prev_[b] = a; }
    std::vector<int> prev_, next_, left_, right_;
  };

  std::size_t at(int a, int b) const { return static_cast<std::size_t>(a) * notch_count_ + b; }

  // Called once per interval, shortest first (STEP 3): answers from the rows of shorter intervals, then
  // fills this interval's row, which needs S only strictly inside it.
  std::optional<X4Choice> x4_term(int i, int j, int to_beat) override {
    std::optional<X4Choice> found;
    if (S(i + 1, j - 1) + 1 > to_beat) found = lookup(i, j);
    fill(i, j);
    return found;
  }

  // T(a, b; m): splitting V(a+1, b-1) at m loses nothing.
  bool tight(int a, int b, int m) const { return S(a + 1, m - 1) + S(m + 1, b - 1) == S(a + 1, b - 1); }

  // STEP 3's X4 term: a tight X4-pattern from E(k, j)[i] or W(i, l)[j], with its Steiner points.
  std::optional<X4Choice> lookup(int i, int j) {
    const int count = S(i + 1, j - 1) + 1;
    for (int k = i + 1; k < j; ++k) {
      ++lookup_steps_;
      const Witness w = tight(i, j, k) ? entry(k, j, i) : Witness{};
      if (w.inner >= 0) return chosen(count, {i, k, w.inner, j}, w.sides, false);
    }
    for (int l = i + 1; l < j; ++l) {
      ++lookup_steps_;
      const Witness w = tight(i, j, l) ? entry(i, l, j) : Witness{};
      if (w.inner >= 0) return chosen(count, {j, i, w.inner, l}, w.sides, true);
    }
    return std::nullopt;
  }

  X4Choice chosen(int count, const std::array<int, 4>& notches, std::uint8_t sides, bool wrapped) {
    const auto [q, g, m, h] = notches;
    const QPoint x = rays_.point(ray(g, sides, 1), ray(q, sides, 0));
    const QPoint y = rays_.point(ray(h, sides, 3), ray(m, sides, 2));
    if (!is_x4(notches, x, y)) throw std::logic_error("chazelle-dobkin: an X4 witness fails Lemma 9");
    ++chosen_;
    chosen_from_w_ += wrapped;
    if (wrapped) return X4Choice{count, m, h, true, y, x};
    return X4Choice{count, g, m, false, x, y};
  }

  static int ray(int notch, std::uint8_t sides, int bit) { return 2 * notch + ((sides >> bit) & 1); }

  // Lemma 9 on the loose pair, checked in full and independently of the scan: every angle at X and Y
  // below 180 degrees, each notch's edge in its closed range and in P, the edges meeting only at X and
  // Y, and XY in P.
  bool is_x4(const std::array<int, 4>& notches, const QPoint& x, const QPoint& y) {
    const auto [q, g, m, h] = notches;
    const QPoint &zq = z(q), &zg = z(g), &zm = z(m), &zh = z(h);
    if (orient(x, zq, zg) <= 0 || orient(x, zg, y) <= 0 || orient(x, y, zq) <= 0) return false;
    if (orient(y, zm, zh) <= 0 || orient(y, zh, x) <= 0 || orient(y, x, zm) <= 0) return false;
    for (int a : {q, g})
      if (!joins(a, x)) return false;
    for (int b : {m, h})
      if (!joins(b, y)) return false;
    for (int a : {q, g})
      for (int b : {m, h})
        if (CGAL::do_intersect(Segment(z(a), x), Segment(z(b), y))) return false;
    return patterns().inside(x, y);
  }

  bool joins(int notch, const QPoint& s) {
    return patterns().resolves(patterns().bare(static_cast<std::size_t>(notch)), s) &&
           patterns().sees(patterns().notches()[static_cast<std::size_t>(notch)], s);
  }

  const QPoint& z(int notch) { return patterns().notch_point(static_cast<std::size_t>(notch)); }

  // The row of interval (g, h): the thesis's scan, once for each choice of the rays G and H.
  void fill(int g, int h) {
    if (h - g < 2) return;
    Row row;
    for (int sides = 0; sides < 4; ++sides) scan(g, h, 2 * g + (sides & 1), 2 * h + (sides >> 1), row);
    if (!row.empty()) rows_[at(g, h)] = std::move(row);
  }

  // The inserts are passed as positions into `inserts`: by_at in order along H (Y's rank, then the
  // ray, the order of the walks), along_g in order of the rank along G where their lines cross it
  // (-1, parallel, first). Both are counting sorts, O(r) per scan.
  void scan(int g, int h, int G, int H, Row& row) {
    const std::vector<Query> queries = open_queries(g, h, G, H, row);
    if (queries.empty()) return;
    const std::vector<Insert> inserts = usable_inserts(g, h, G, H);
    if (inserts.empty()) return;
    const auto item = [&](int k) -> const Insert& { return inserts[static_cast<std::size_t>(k)]; };
    std::vector<int> positions(inserts.size());
    for (std::size_t k = 0; k < inserts.size(); ++k) positions[k] = static_cast<int>(k);
    const std::size_t range = 2 * static_cast<std::size_t>(notch_count_) + 1;
    const std::vector<int> by_ray = stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).ray); });
    const std::vector<int> by_at = stably_ordered(by_ray, range, [&](int k) { return static_cast<std::size_t>(item(k).at); });
    const std::vector<int> along_g =
        stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).along + 1); });
    sweep_forward(queries, inserts, by_at, along_g, G, H, row);
    sweep_backward(queries, inserts, by_at, along_g, G, H, row);
    const std::vector<int> parallel_to_g = with_cross_sign(inserts, by_at, 0, G);
    Inserted parallel(inserts.size(), parallel_to_g, parallel_to_g);
    for (int k : parallel_to_g) parallel.insert(k);
    for (const Query& q : queries) find_visible(q, inserts, parallel, G, H, row);
  }

  // The outer notches q, in order along G, whose loose point X on G passes the conditions that do not
  // depend on the inner notch: X opens towards z_g (angle z_q X z_g), lies strictly right of the line
  // of H (angle at Y towards X), P1 is not a constant false, and z_q X cannot cross z_h Y.
  std::vector<Query> open_queries(int g, int h, int G, int H, const Row& row) {
    std::vector<Query> out;
    for (int Q : rays_.along(G)) {
      ++scan_steps_;
      const int q = LooseRays::notch(Q);
      if ((q >= g && q <= h) || (!row.empty() && row[static_cast<std::size_t>(q)].inner >= 0)) continue;
      if (!rays_.opens(Q, G) || rays_.side(H, G, Q) >= 0) continue;
      const int turn = rays_.cross_sign(Q, H);
      if (turn == 0 && rays_.base_side(Q, H) <= 0) continue;
      if (turn > 0 && crosses_before(Q, H, G)) continue;
      ++table_entries_;
      out.push_back({Q, rays_.key(G, Q)});
    }
    return out;
  }

  // The tight inner notches m whose loose point Y on H passes the conditions that do not depend on the
  // outer notch: Y opens towards z_h, lies strictly right of the line of G, P2 is not a constant false,
  // and z_m Y cannot cross z_g X.
  std::vector<Insert> usable_inserts(int g, int h, int G, int H) {
    std::vector<Insert> out;
    for (int M : rays_.along(H)) {
      ++scan_steps_;
      const int m = LooseRays::notch(M);
      if (m <= g || m >= h || !tight(g, h, m)) continue;
      if (!rays_.opens(M, H) || rays_.side(G, H, M) >= 0) continue;
      const int turn = rays_.cross_sign(M, G);
      if (turn == 0 && rays_.base_side(M, G) <= 0) continue;
      if (turn > 0 && crosses_before(M, G, H)) continue;
      out.push_back({M, rays_.key(G, M), rays_.key(H, M)});
    }
    return out;
  }

  // `positions` ordered by key (an integer in [0, range)), stably: a counting sort, O(positions + range).
  template <class Key>
  static std::vector<int> stably_ordered(const std::vector<int>& positions, std::size_t range, Key key) {
    std::vector<int> first(range + 1, 0);
    for (int k : positions) ++first[key(k) + 1];
    for (std::size_t v = 1; v <= range; ++v) first[v] += first[v - 1];
    std::vector<int> out(positions.size());
    for (int k : positions) out[static_cast<std::size_t>(first[key(k)]++)] = k;
    return out;
  }

  // Those of `positions` whose insert's line crosses G with the given sign, in the same order.
  std::vector<int> with_cross_sign(const std::vector<Insert>& inserts, const std::vector<int>& positions, int sign,
                                   int G) const {
    std::vector<int> out;
    for (int k : positions)
      if (rays_.cross_sign(inserts[static_cast<std::size_t>(k)].ray, G) == sign) out.push_back(k);
    return out;
  }

  // Whether the segment of ray A up to its loose point with C meets ray B's segment from its notch to
  // the crossing of the two lines (with B's segment reaching past the crossing, which P1 or P2 ensures
  // in the class where this is asked).
  bool crosses_before(int A, int B, int C) const {
    return rays_.meet_sign(B, A) >= 0 && rays_.meet_sign(A, B) >= 0 && rays_.key(A, B) <= rays_.key(A, C);
  }

  // P2 for inserts whose line crosses G with cross(u_m, u_g) > 0 asks X beyond the crossing: a prefix
  // along G. Queries are answered before the inserts of the same rank (strict inequality).
  void sweep_forward(const std::vector<Query>& queries, const std::vector<Insert>& inserts,
                     const std::vector<int>& by_at, const std::vector<int>& along_g, int G, int H, Row& row) {
    Inserted set(inserts.size(), with_cross_sign(inserts, by_at, 1, G), with_cross_sign(inserts, along_g, 1, G));
    std::size_t next = 0;
    for (const Query& q : queries) {
      for (; next < along_g.size() && inserts[static_cast<std::size_t>(along_g[next])].along < q.along; ++next) {
        ++scan_steps_;
        if (rays_.cross_sign(inserts[static_cast<std::size_t>(along_g[next])].ray, G) > 0) set.insert(along_g[next]);
      }
      find_visible(q, inserts, set, G, H, row);
    }
  }

  void sweep_backward(const std::vector<Query>& queries, const std::vector<Insert>& inserts,
                      const std::vector<int>& by_at, const std::vector<int>& along_g, int G, int H, Row& row) {
    std::vector<int> order = with_cross_sign(inserts, along_g, -1, G);
    std::reverse(order.begin(), order.end());
    Inserted set(inserts.size(), with_cross_sign(inserts, by_at, -1, G), order);
    std::size_t next = along_g.size();
    for (auto q = queries.rbegin(); q != queries.rend(); ++q) {
      for (; next > 0 && inserts[static_cast<std::size_t>(along_g[next - 1])].along > q->along; --next) {
        ++scan_steps_;
        if (rays_.cross_sign(inserts[static_cast<std::size_t>(along_g[next - 1])].ray, G) < 0) set.insert(along_g[next - 1]);
      }
      find_visible(*q, inserts, set, G, H, row);
    }
  }

  // P1 bounds Y's rank along H on one side (or not at all when Q and H are parallel): walk the inserted
  // Y from the extreme inwards while P1 holds, and test P4 (XY in P) on each until one passes.
  void find_visible(const Query& query, const std::vector<Insert>& inserts, const Inserted& set, int G, int H, Row& row) {
    const int q = LooseRays::notch(query.ray);
    if (set.empty() || (!row.empty() && row[static_cast<std::size_t>(q)].inner >= 0)) return;
    const int turn = rays_.cross_sign(query.ray, H);
    const int bound = turn == 0 ? 0 : rays_.key(H, query.ray);
    const QPoint x = rays_.point(G, query.ray);
    auto visible = [&](const Insert& y) {
      ++scan_steps_;
      ++p4_tests_;
      if (!patterns().inside(x, rays_.point(H, y.ray))) return false;
      record(row, q, query.ray, G, y.ray, H);
      return true;
    };
    const auto y = [&](int k) -> const Insert& { return inserts[static_cast<std::size_t>(k)]; };
    if (turn >= 0) {
      for (int k = set.last(); !set.is_end(k) && (turn == 0 || y(k).at > bound); k = set.before(k))
        if (visible(y(k))) return;
    } else {
      for (int k = set.first(); !set.is_end(k) && y(k).at < bound; k = set.after(k))
        if (visible(y(k))) return;
    }
  }

  void record(Row& row, int q, int Q, int G, int M, int H) {
    if (row.empty()) row.assign(static_cast<std::size_t>(notch_count_), Witness{});
    const auto bit = [](int ray, int shift) { return static_cast<std::uint8_t>((ray & 1) << shift); };
    row[static_cast<std::size_t>(q)] = {static_cast<std::int16_t>(LooseRays::notch(M)),
                                        static_cast<std::uint8_t>(bit(Q, 0) | bit(G, 1) | bit(M, 2) | bit(H, 3))};
    ++table_witnesses_;
  }

  int notch_count_;
  LooseRays rays_;
  std::vector<Row> rows_;  // at(g, h): the row of interval (g, h), empty when it has no witness
  std::int64_t table_entries_ = 0, table_witnesses_ = 0, scan_steps_ = 0, p4_tests_ = 0, lookup_steps_ = 0, chosen_ = 0,
               chosen_from_w_ = 0;
};

}  // namespace pd::cd
