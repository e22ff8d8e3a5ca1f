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
#include <climits>
#include <cstdlib>
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
  using Place = boundary::SegmentSearch::Contact;

  LooseRays(const Polygon& p, const Patterns& patterns) : p_(p), count_(2 * static_cast<int>(patterns.notches().size())) {
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
  bool opens(int a, int b) const { return opens_[cell(a, b)] == kOpens; }
  // Whether the lines of a and b meet strictly inside both clipped rays: the two open segments cross.
  bool loose(int a, int b) const { return opens_[cell(a, b)] != kApart; }
  // The loose points on a, in order along it: the rays b whose lines meet a's strictly inside both.
  const std::vector<int>& along(int a) const { return along_[a]; }
  QPoint point(int a, int b) const {
    const Rational s = parameter(a, b);
    return origin_[a] + s * direction_[a];
  }
  // Where ray a's clipped segment starts (its notch) and ends on the boundary.
  const Place& start(int a) const { return start_[a]; }
  const Place& end(int a) const { return end_[a]; }
  // Which side of the directed line of ray a point y lies on: +1 left, -1 right, 0 on it.
  int line_side(int a, const QPoint& y) const {
    return CGAL::sign(CGAL::determinant(direction_[a], y - origin_[a]));
  }
  // Whether boundary place a comes before b in the order of the boundary from vertex 0 on.
  bool before(const Place& a, const Place& b) const {
    if (a.edge != b.edge) return a.edge < b.edge;
    if (a.at_vertex || b.at_vertex) return a.at_vertex && !b.at_vertex;
    const QPoint w = to_exact(p_[a.edge]);
    const Vec e = to_exact(p_[p_.next(a.edge)]) - w;
    return (a.point - w) * e < (b.point - w) * e;
  }
  std::int64_t stopped_at_vertices() const { return std::count(at_vertex_.begin(), at_vertex_.end(), 1); }
  std::int64_t loose_points() const { return loose_points_; }

 private:
  using Vec = ExactKernel::Vector_2;

  static int compare(int a, int b) { return a < b ? -1 : (a > b ? 1 : 0); }
  // opens_ per pair: not a loose point, a loose point, or a loose point where the notches turn
  // counter-clockwise.
  enum : std::int8_t { kApart, kLoose, kOpens };

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
      start_.push_back({v, true, z});
      end_.push_back({hit->vertex, hit->at_vertex, hit->at_vertex ? w : z + reach * u});
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
      opens_[cell(a, b)] = orient(x, origin_[a], origin_[b]) > 0 ? kOpens : kLoose;
      points.push_back(b);
      loose_points_ += a < b;
    }
    along_.push_back(std::move(points));
  }

  const Polygon& p_;
  int count_;
  std::vector<Place> start_, end_;
  std::vector<QPoint> origin_;
  std::vector<Vec> direction_;
  std::vector<Rational> reach_;
  std::vector<char> at_vertex_;
  std::vector<std::int8_t> cross_sign_, base_side_, meet_sign_, opens_;
  std::vector<int> key_;
  std::vector<std::vector<int>> along_;
  std::int64_t loose_points_ = 0;
};

// Two rays G and H apart (their clipped segments disjoint but for a shared end) are chords of P;
// between them lies the part P' of P bounded by G, H and two arcs of the boundary, each from an end of
// G to an end of H, one of them a single point where G and H share an end (header, (7)). The four ends
// in boundary order, and which end of H the stretch of H unseen from X through Y reaches.
class ArcsBetween {
 public:
  using Place = LooseRays::Place;

  // Ends 0 and 1 are G's notch and far end, 2 and 3 H's. Two disjoint chords do not interleave on the
  // boundary: G's ends are neighbours in boundary order, and so are H's. A shared end (a ray stopping
  // at the other's notch, or both at one point) is listed twice, in the order that keeps them so.
  ArcsBetween(const LooseRays& rays, int G, int H)
      : rays_(rays), G_(G), ends_{&rays.start(G), &rays.end(G), &rays.start(H), &rays.end(H)} {
    for (const bool g_first : {true, false}) {
      order_ = {0, 1, 2, 3};
      std::sort(order_.begin(), order_.end(), [&](int a, int b) {
        if (rays_.before(*ends_[a], *ends_[b])) return true;
        if (rays_.before(*ends_[b], *ends_[a]) || (a < 2) == (b < 2)) return false;
        return (a < 2) == g_first;
      });
      int g_at[2] = {0, 0};
      for (int k = 0; k < 4; ++k)
        if (order_[k] < 2) g_at[order_[k]] = k;
      const int apart = std::abs(g_at[0] - g_at[1]);
      if (apart == 1 || apart == 3) return;
    }
    throw std::logic_error("chazelle-dobkin: two rays apart interleave on the boundary");
  }

  // Whether an end of G is an end of H (neither comes before the other on the boundary).
  bool share_an_end() const {
    for (int a : {0, 1})
      for (int b : {2, 3})
        if (!rays_.before(*ends_[a], *ends_[b]) && !rays_.before(*ends_[b], *ends_[a])) return true;
    return false;
  }

  // For Y on H not seen from X on G, with c the first point of the boundary on XY from X: an end of H
  // (0 its notch, 1 its far end) such that X sees no point of H between Y and it (header, (7)). When c
  // lies on an arc of P', the end that arc reaches; when it lies on the boundary beyond G, XY left X
  // away from P', so every point of H on Y's side of G's line is unseen: the end on that side.
  int end_of_h_reached(const Place& c, const QPoint& y) const {
    int k = 0;
    while (k < 4 && rays_.before(*ends_[k_th(k)], c)) ++k;
    const int a = k_th(k + 3), b = k_th(k);
    if ((k < 4 && !rays_.before(c, *ends_[b])) || (a >= 2 && b >= 2))
      throw std::logic_error("chazelle-dobkin: XY first meets the boundary at an end of G or H, or beyond H");
    if ((a < 2) != (b < 2)) return std::max(a, b) - 2;
    const int y_side = rays_.line_side(G_, y);
    return rays_.line_side(G_, ends_[2]->point) != -y_side ? 0 : 1;
  }

 private:
  int k_th(int k) const { return order_[static_cast<std::size_t>(k % 4)]; }

  const LooseRays& rays_;
  int G_;
  std::array<const Place*, 4> ends_;
  std::array<int, 4> order_{};
};

// A table entry: the inner notch of an X4-pattern found for this outer notch, or -1, and the sides of
// the four loose rays it uses (bit 0: the outer notch's, 1: g's, 2: the inner notch's, 3: h's).
struct Witness {
  std::int16_t inner = -1;
  std::uint8_t sides = 0;
};

class ProgramCubic final : public Program {
 public:
  // How a scan's walks go: carrying what earlier walks of a pass proved over to the later ones (the
  // algorithm), or each walk testing every step in turn until one passes (the reference the tests hold
  // the rows of the first against: both must find the same witness for every entry).
  enum class Walks { kCarryOver, kEachAlone };

  explicit ProgramCubic(const Polygon& p, Walks walks = Walks::kCarryOver)
      : Program(p), notch_count_(checked(patterns().notches().size())), rays_(p, patterns()),
        rows_(static_cast<std::size_t>(notch_count_) * static_cast<std::size_t>(notch_count_)), walks_(walks) {}

  void report(Counters& counters) const {
    counters["x4_loose_points"] = rays_.loose_points();
    counters["x4_table_entries"] = table_entries_;
    counters["x4_table_witnesses"] = table_witnesses_;
    counters["x4_found"] += table_witnesses_;
    counters["x4_scan_steps"] = scan_steps_;
    counters["x4_p4_tests"] = p4_tests_;
    counters["x4_p4_sides"] = p4_sides_;
    counters["x4_scans_sharing_an_end"] = scans_sharing_an_end_;
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

  // A set of places in [0, size): a bitset under summary bitsets (a bit per nonempty word of the level
  // below) up to a single word. Inserting, and finding the nearest member on either side of a place,
  // take O(levels) word operations, levels = max(1, ceil(log_64 size)): at most 3 for the 65534 rays of
  // 32767 notches. (A linked list with offline insertion points would be O(1), but walks resume from places
  // that earlier walks left, which needs the nearest member of any place.)
  class PlaceSet {
   public:
    explicit PlaceSet(int size) : size_(size) {
      std::size_t count = static_cast<std::size_t>(std::max(size, 1));
      do {
        count = (count + 63) / 64;
        levels_.emplace_back(count, 0);
      } while (count > 1);
    }
    void insert(int k) {
      for (auto& level : levels_) {
        level[static_cast<std::size_t>(k >> 6)] |= std::uint64_t{1} << (k & 63);
        k >>= 6;
      }
    }
    bool empty() const { return levels_.back()[0] == 0; }
    // The largest member at most k, or -1; k in [-1, size).
    int at_or_before(int k) const {
      for (std::size_t level = 0; level < levels_.size() && k >= 0; ++level, k = (k >> 6) - 1) {
        const std::uint64_t word = levels_[level][static_cast<std::size_t>(k >> 6)] & (~std::uint64_t{0} >> (63 - (k & 63)));
        if (word != 0) return descend(level, (k & ~63) | highest(word), highest);
      }
      return -1;
    }
    // The smallest member at least k, or size; k in [0, size].
    int at_or_after(int k) const {
      for (std::size_t level = 0; level < levels_.size() && static_cast<std::size_t>(k >> 6) < levels_[level].size();
           ++level, k = (k >> 6) + 1) {
        const std::uint64_t word = levels_[level][static_cast<std::size_t>(k >> 6)] & (~std::uint64_t{0} << (k & 63));
        if (word != 0) return descend(level, (k & ~63) | lowest(word), lowest);
      }
      return size_;
    }

   private:
    static int highest(std::uint64_t word) { return 63 - __builtin_clzll(word); }
    static int lowest(std::uint64_t word) { return __builtin_ctzll(word); }
    // From member k of `level` down to the member of the bottom level that `pick` chooses in each word.
    int descend(std::size_t level, int k, int (*pick)(std::uint64_t)) const {
      while (level-- > 0) k = k * 64 + pick(levels_[level][static_cast<std::size_t>(k)]);
      return k;
    }
    int size_;
    std::vector<std::vector<std::uint64_t>> levels_;
  };

  // One scan's inserts, the places of by_at (in order along H: Y's rank, then the ray, the order of the
  // walks), where G and H cross when their clipped rays do, and the Y already made (a Y is tested by
  // the walks of many queries, and making it is an exact division).
  struct Lists {
    Lists(int g_ray, int h_ray, std::vector<Insert> usable)
        : G(g_ray), H(h_ray), inserts(std::move(usable)), place(inserts.size()), y_at_place(inserts.size()) {}
    int G, H;
    std::vector<Insert> inserts;
    std::vector<int> by_at;       // positions into inserts
    std::vector<int> place;       // by_at inverted: the place of each insert
    std::vector<int> below_rank;  // below_rank[v]: the places whose Y has a rank along H below v
    bool crossing = false;
    int crossing_on_g = -1, crossing_on_h = -1;  // the ranks of G ∩ H along G and along H
    std::vector<std::optional<QPoint>> y_at_place;  // Y of each place, once a walk has needed it
    std::optional<ArcsBetween> arcs;                // G and H apart: the arcs between them

    const Insert& at_place(int k) const { return inserts[static_cast<std::size_t>(by_at[static_cast<std::size_t>(k)])]; }
  };

  // What the walks of one pass in one direction proved for its later walks, in that direction's steps
  // (find_visible; each field is used by one kind of walk).
  struct Memory {
    int seen_from = INT_MAX;     // crossing, X approaching c: every near step from here on is seen
    int blocked_to = -1;         // no step up to here is seen (crossing with X receding, or apart)
    int reach = -1;              // apart: the furthest step seen so far
    int blocked_from = INT_MAX;  // apart: no step from here on is seen
    int seen_nearest = INT_MAX;  // apart: the nearest step seen so far
  };

  // One pass of a scan: the places of the Y inserted so far and, per direction of walk, its Memory.
  struct Pass {
    Pass(int size, bool forward) : inserted(size), forward(forward) {}
    PlaceSet inserted;
    bool forward;  // queries come in increasing rank along G
    std::array<Memory, 2> memory;  // walks down (from the top rank along H), walks up
  };

  // A walk's view of a pass: steps numbered from the end of the list the walk starts at.
  class Walk {
   public:
    Walk(const PlaceSet& inserted, int size, bool down) : inserted_(inserted), size_(size), down_(down) {}
    int place(int step) const { return down_ ? size_ - 1 - step : step; }
    // The first inserted step at or after `step`, or size.
    int first_from(int step) const {
      if (!down_) return inserted_.at_or_after(step);
      const int k = inserted_.at_or_before(size_ - 1 - step);
      return k < 0 ? size_ : size_ - 1 - k;
    }
    // The last inserted step before `step`, or -1.
    int last_before(int step) const {
      if (!down_) return inserted_.at_or_before(step - 1);
      const int k = inserted_.at_or_after(size_ - step);
      return k == size_ ? -1 : size_ - 1 - k;
    }

   private:
    const PlaceSet& inserted_;
    int size_;
    bool down_;
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

  // The inserts' orders are counting sorts, O(r) per scan: by_at along H (Y's rank, then the ray),
  // along_g by the rank along G where their lines cross it (-1, parallel, first).
  void scan(int g, int h, int G, int H, Row& row) {
    const std::vector<Query> queries = open_queries(g, h, G, H, row);
    if (queries.empty()) return;
    Lists lists(G, H, usable_inserts(g, h, G, H));
    if (lists.inserts.empty()) return;
    const auto item = [&](int k) -> const Insert& { return lists.inserts[static_cast<std::size_t>(k)]; };
    const int size = static_cast<int>(lists.inserts.size());
    std::vector<int> positions(lists.inserts.size());
    for (int k = 0; k < size; ++k) positions[static_cast<std::size_t>(k)] = k;
    const std::size_t range = 2 * static_cast<std::size_t>(notch_count_) + 1;
    const std::vector<int> by_ray = stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).ray); });
    const auto at = [&](int k) { return static_cast<std::size_t>(item(k).at); };
    lists.by_at = stably_ordered(by_ray, range, at);
    lists.below_rank = counts_below(positions, range, at);
    const std::vector<int> along_g =
        stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).along + 1); });
    for (int k = 0; k < size; ++k) lists.place[static_cast<std::size_t>(lists.by_at[static_cast<std::size_t>(k)])] = k;
    if (rays_.loose(G, H)) {
      lists.crossing = true, lists.crossing_on_g = rays_.key(G, H), lists.crossing_on_h = rays_.key(H, G);
    } else {
      lists.arcs.emplace(rays_, G, H);  // not collinear: the queries' X lie strictly right of H's line
      scans_sharing_an_end_ += lists.arcs->share_an_end();
    }
    sweep_forward(queries, lists, along_g, row);
    sweep_backward(queries, lists, along_g, row);
    Pass parallel(size, true);
    for (int k = 0; k < size; ++k)
      if (rays_.cross_sign(lists.at_place(k).ray, G) == 0) parallel.inserted.insert(k);
    for (const Query& q : queries) find_visible(q, lists, parallel, row);
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

  // counts[v]: how many of `positions` have a key (an integer in [0, range)) below v, for v in
  // [0, range]. O(positions + range).
  template <class Key>
  static std::vector<int> counts_below(const std::vector<int>& positions, std::size_t range, Key key) {
    std::vector<int> counts(range + 1, 0);
    for (int k : positions) ++counts[key(k) + 1];
    for (std::size_t v = 1; v <= range; ++v) counts[v] += counts[v - 1];
    return counts;
  }

  // `positions` ordered by key (an integer in [0, range)), stably: a counting sort, O(positions + range).
  template <class Key>
  static std::vector<int> stably_ordered(const std::vector<int>& positions, std::size_t range, Key key) {
    std::vector<int> first = counts_below(positions, range, key);
    std::vector<int> out(positions.size());
    for (int k : positions) out[static_cast<std::size_t>(first[key(k)]++)] = k;
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
  void sweep_forward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g, Row& row) {
    Pass pass(static_cast<int>(lists.inserts.size()), true);
    std::size_t next = 0;
    for (const Query& q : queries) {
      for (; next < along_g.size() && lists.inserts[static_cast<std::size_t>(along_g[next])].along < q.along; ++next)
        admit(lists, along_g[next], 1, pass);
      find_visible(q, lists, pass, row);
    }
  }

  void sweep_backward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g, Row& row) {
    Pass pass(static_cast<int>(lists.inserts.size()), false);
    std::size_t next = along_g.size();
    for (auto q = queries.rbegin(); q != queries.rend(); ++q) {
      for (; next > 0 && lists.inserts[static_cast<std::size_t>(along_g[next - 1])].along > q->along; --next)
        admit(lists, along_g[next - 1], -1, pass);
      find_visible(*q, lists, pass, row);
    }
  }

  // Inserts insert k into the pass when its line crosses G with the pass's sign.
  void admit(const Lists& lists, int k, int sign, Pass& pass) {
    ++scan_steps_;
    if (rays_.cross_sign(lists.inserts[static_cast<std::size_t>(k)].ray, lists.G) == sign)
      pass.inserted.insert(lists.place[static_cast<std::size_t>(k)]);
  }

  // P1 bounds Y's rank along H on one side (or not at all when Q and H are parallel): a walk takes the
  // inserted Y from the far end of the list inwards while P1 holds, and the first that passes P4 (XY in
  // P) is the witness. Steps [0, end) are those where P1 holds.
  void find_visible(const Query& query, Lists& lists, Pass& pass, Row& row) {
    const int q = LooseRays::notch(query.ray);
    if (pass.inserted.empty() || (!row.empty() && row[static_cast<std::size_t>(q)].inner >= 0)) return;
    const int turn = rays_.cross_sign(query.ray, lists.H);
    const int size = static_cast<int>(lists.inserts.size());
    const int bound = rays_.key(lists.H, query.ray);
    const auto places_below = [&](int rank) { return lists.below_rank[static_cast<std::size_t>(rank)]; };
    const int end = turn == 0 ? size : (turn > 0 ? size - places_below(bound + 1) : places_below(bound));
    const Walk walk(pass.inserted, size, turn >= 0);
    std::optional<QPoint> x;
    const auto y_at = [&](int step) -> const QPoint& {
      std::optional<QPoint>& y = lists.y_at_place[static_cast<std::size_t>(walk.place(step))];
      if (!y) y = rays_.point(lists.H, lists.at_place(walk.place(step)).ray);
      return *y;
    };
    const auto visible = [&](int step) {
      ++scan_steps_;
      ++p4_tests_;
      if (!x) x = rays_.point(lists.G, query.ray);
      return patterns().inside(*x, y_at(step));
    };
    // Rays apart: where XY first meets the boundary tells on which side of what X sees Y lies (header,
    // (7)). The walk starts at H's far end when it walks down.
    const auto side_unseen = [&](int step) {
      ++p4_sides_;
      const QPoint& y = y_at(step);
      const auto contact = patterns().first_contact(*x, y);
      if (!contact) throw std::logic_error("chazelle-dobkin: an unseen XY meets no boundary");
      return lists.arcs->end_of_h_reached(*contact, y) == (turn >= 0 ? 1 : 0) ? Side::kStartSide : Side::kFarSide;
    };
    Memory& memory = pass.memory[turn >= 0 ? 0 : 1];
    int found = -1;
    if (walks_ == Walks::kEachAlone) {
      found = walk_alone(walk, end, visible);
    } else if (lists.crossing) {
      const int c = lists.crossing_on_h;
      const int near_end = turn >= 0 ? size - places_below(c) : places_below(c + 1);
      const bool approaching = pass.forward ? query.along <= lists.crossing_on_g : query.along >= lists.crossing_on_g;
      found = approaching ? walk_approaching(walk, near_end, end, memory, visible) : walk_receding(walk, near_end, end, memory, visible);
      if (found < 0) found = walk_beyond_crossing(walk, near_end, end, visible);
    } else {
      // Apart, what X sees moves up along H as X moves up along G (header, (6)); a walk starts at the
      // bottom when turn < 0.
      const bool moving_away = pass.forward == (turn < 0);
      found = moving_away ? search_apart_moving_away(walk, end, memory, visible, side_unseen, unseen_)
                          : search_apart_moving_back(walk, end, memory, visible, side_unseen, unseen_);
    }
    if (found >= 0) record(row, q, query.ray, lists.G, lists.at_place(walk.place(found)).ray, lists.H);
  }

  // Each inserted step in turn, until one is seen: the first seen, or -1.
  template <class Visible>
  static int walk_alone(const Walk& walk, int end, const Visible& visible) {
    for (int step = walk.first_from(0); step < end; step = walk.first_from(step + 1))
      if (visible(step)) return step;
    return -1;
  }

  // The walks of crossing rays (header, (6)). The near steps [0, near_end), on the walk's side of c (c
  // included), that X sees are those from a threshold t(X) on; of the steps beyond c, those up to one.
  // Along a pass t(X) only falls while X moves towards c, and only rises while X moves away from it.
  //
  // X moving towards c: every near step from `seen_from` on is seen (an earlier X saw it). The walk
  // tests the inserted steps before it, one by one back towards its start, while they are seen.
  template <class Visible>
  static int walk_approaching(const Walk& walk, int near_end, int end, Memory& memory, const Visible& visible) {
    int& seen_from = memory.seen_from;
    seen_from = std::min(seen_from, near_end);
    for (int step = walk.last_before(std::min(seen_from, end)); step >= 0 && visible(step); step = walk.last_before(step))
      seen_from = step;
    const int first = walk.first_from(seen_from);
    return first < std::min(near_end, end) ? first : -1;
  }

  // X moving away from c: no step up to `blocked_to` is seen (not seen by an earlier X).
  template <class Visible>
  static int walk_receding(const Walk& walk, int near_end, int end, Memory& memory, const Visible& visible) {
    for (int step = walk.first_from(memory.blocked_to + 1); step < std::min(near_end, end); step = walk.first_from(step + 1)) {
      if (visible(step)) return step;
      memory.blocked_to = step;
    }
    return -1;
  }

  // No near step is a witness: of the steps beyond c only the first can be.
  template <class Visible>
  static int walk_beyond_crossing(const Walk& walk, int near_end, int end, const Visible& visible) {
    const int first = walk.first_from(near_end);
    return first < end && visible(first) ? first : -1;
  }

  // The searches of rays apart (header, (7)). Along a walk, the steps X does not see before those it
  // sees are on the start side, those after on the far side; kUnseen is a step not seen whose side was
  // not asked for.
  enum class Side { kSeen, kStartSide, kFarSide, kUnseen };

  // Most walks end within their first steps, and a side costs a second search: the first kPlainSteps
  // steps are tested in turn, as the walks of (6) do, asking no side that (6) does not already give.
  static constexpr int kPlainSteps = 2;

  // The first inserted step in [from, limit) that X sees, or limit when there is none: kPlainSteps
  // steps in turn, then the first step not on the start side, found by galloping and bisecting with
  // O(log(limit - from)) probes (its side tells whether X sees it). probe(step, ask) gives a step's
  // side, asking for it (a first contact) only when `ask` and (6) does not give it. The steps probed
  // that X does not see go to `unseen`.
  template <class Probe>
  static int first_seen(const Walk& walk, int from, int limit, const Probe& probe, std::vector<int>& unseen) {
    int a = from, b = limit;
    for (int k = 0; k < kPlainSteps; ++k) {
      const int step = walk.first_from(a);
      if (step >= b) return b;
      const Side side = probe(step, false);
      if (side == Side::kSeen) return step;
      unseen.push_back(step);
      if (side == Side::kFarSide) return limit;
      a = step + 1;
    }
    int found = limit;
    const auto look = [&](int step) {
      const Side side = probe(step, true);
      if (side != Side::kSeen) unseen.push_back(step);
      if (side == Side::kStartSide) {
        a = step + 1;
      } else {
        b = step;
        found = side == Side::kSeen ? step : limit;
      }
    };
    for (int gap = 1; a < b; gap *= 2) {
      const int at = std::min(b, a + gap - 1), step = walk.first_from(at);
      if (step >= b) {
        b = at;
        break;
      }
      look(step);
      if (b == step) break;
    }
    while (a < b) {
      const int mid = a + (b - a) / 2, step = walk.first_from(mid);
      if (step >= b) b = mid;
      else look(step);
    }
    return found;
  }

  // What X sees moves away from the walk's start along the pass: the search starts after the steps no
  // later X sees, and records what (6) allows of the steps X did not see.
  template <class Visible, class SideUnseen>
  static int search_apart_moving_away(const Walk& walk, int end, Memory& memory, const Visible& visible,
                                      const SideUnseen& side_unseen, std::vector<int>& unseen) {
    // A step up to the furthest seen by an earlier X, not seen by X, is on the start side (6).
    const auto probe = [&](int step, bool ask) {
      if (visible(step)) return Side::kSeen;
      if (step <= memory.reach) return Side::kStartSide;
      return ask ? side_unseen(step) : Side::kUnseen;
    };
    unseen.clear();
    const int found = first_seen(walk, memory.blocked_to + 1, end, probe, unseen);
    if (found < end) memory.reach = std::max(memory.reach, found);
    for (const int step : unseen)
      if (step <= memory.reach) memory.blocked_to = std::max(memory.blocked_to, step);
    return found < end ? found : -1;
  }

  // ... and back towards it: the search stops before the steps no later X sees.
  template <class Visible, class SideUnseen>
  static int search_apart_moving_back(const Walk& walk, int end, Memory& memory, const Visible& visible,
                                      const SideUnseen& side_unseen, std::vector<int>& unseen) {
    // A step at or after the nearest seen by an earlier X, not seen by X, is on the far side (6).
    const auto probe = [&](int step, bool ask) {
      if (visible(step)) return Side::kSeen;
      if (step >= memory.seen_nearest) return Side::kFarSide;
      return ask ? side_unseen(step) : Side::kUnseen;
    };
    unseen.clear();
    const int limit = std::min(end, memory.blocked_from);
    const int found = first_seen(walk, 0, limit, probe, unseen);
    if (found < limit) memory.seen_nearest = std::min(memory.seen_nearest, found);
    for (const int step : unseen)
      if (step >= memory.seen_nearest) memory.blocked_from = std::min(memory.blocked_from, step);
    return found < limit ? found : -1;
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
  Walks walks_;
  std::vector<int> unseen_;  // the steps a search of rays apart probed and X did not see
  std::int64_t p4_sides_ = 0, scans_sharing_an_end_ = 0;
  std::int64_t table_entries_ = 0, table_witnesses_ = 0, scan_steps_ = 0, p4_tests_ = 0, lookup_steps_ = 0, chosen_ = 0,
               chosen_from_w_ = 0;
};

}  // namespace pd::cd
