// chazelle-dobkin's program and its X4 tables (Sec. 2.4 of Chazelle's thesis): the loose rays with their
// sorted lists, the table entry (Witness) and the program whose STEP 3 fills and reads the rows E and W.
// The bounds and the preconditions are in the header of algorithms/chazelle_dobkin.cpp, which registers
// the algorithm; what the thesis says, the reconstructions with their proofs and the deviations in
// docs/algorithms/chazelle-dobkin.md. The classes are
// here so that the tests can read the rows the program fills (entry(), S()) after its run.
#pragma once

#include "engines/chazelle_dobkin/program.h"
#include "engines/chazelle_dobkin/geodesics.h"
#include "engines/search/ray_shooting.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
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

  LooseRays(const Polygon& p, const Patterns& patterns);

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
  int side(int a, int b, int c) const;
  // sign(u_a x (z_b - z_a)): which side of a's line b's notch lies on.
  int base_side(int a, int b) const { return base_side_[cell(a, b)]; }
  // Whether the lines of a and b meet strictly inside both clipped rays (a loose point, the thesis's
  // A_ik) and the notches of a and b, seen from it, turn counter-clockwise.
  bool opens(int a, int b) const { return opens_[cell(a, b)] == kOpens; }
  // Whether the lines of a and b meet strictly inside both clipped rays: the two open segments cross.
  bool loose(int a, int b) const { return opens_[cell(a, b)] != kApart; }
  // The loose points on a, in order along it: the rays b whose lines meet a's strictly inside both.
  const std::vector<int>& along(int a) const { return along_[a]; }
  QPoint point(int a, int b) const;
  // The loose point of a and b, made the first time it is asked for (an exact division; scans ask for
  // each many times).
  const FilteredPoint& loose_point(int a, int b);
  // The ray ends as terminals of geodesics (geodesics.h): 2a is ray a's notch, 2a + 1 its far end.
  std::vector<Place> terminals() const;
  // The terminal of ray a's notch (end 0, the same for both rays of a notch) or far end (end 1).
  static std::size_t terminal(int a, int end);
  // Whether an end of ray a is an end of ray b (neither comes before the other on the boundary).
  bool share_an_end(int a, int b) const;
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
  void shoot(const Polygon& p, const Patterns& patterns);

  // Where b's line crosses a's, as a parameter along a (z_a + s u_a). Pre: not parallel.
  Rational parameter(int a, int b) const;

  // The O(1) facts about a pair of rays, computed once: O(r^2) in all.
  void relate(int a, int b, std::vector<Rational>& meet);

  // The rays whose lines cross a's, in order along a, with their ranks: O(r log r).
  std::vector<int> sorted_along(int a, const std::vector<Rational>& meet);

  // The loose points on a, in order along it.
  void list_loose_points(int a, const std::vector<int>& sorted, const std::vector<Rational>& meet);

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
  std::vector<int> made_at_;                          // per pair of rays meeting at a loose point
  std::vector<std::optional<FilteredPoint>> made_;  // the loose points made so far
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
  // How a scan tests P4 (XY in P): from the places X sees, found with geodesics (the algorithm), or by a
  // walk testing every step in turn with the segment search until one passes (the reference the tests
  // hold the rows of the first against: both must find the same witness for every entry).
  enum class P4Test { kGeodesics, kSegmentSearch };

  explicit ProgramCubic(const Polygon& p, P4Test p4_test = P4Test::kGeodesics);

  void report(Counters& counters) const;

  // The row of interval (g, h) at outer notch q, as STEP 3 reads it: E(g, h)[q] for q < g, W(g, h)[q]
  // for q > h (no witness before (g, h) is filled, and never for h - g < 2 or q in [g, h]).
  Witness entry(int g, int h, int q) const;
  // S(i, j) of Algorithm CD, the table whose tightness T selects the inner notches of the rows.
  using Program::S;

 private:
  using Segment = ExactKernel::Segment_2;

  static constexpr int kMaxNotches = INT16_MAX;
  // The notch count, refused before any table is built when a witness could not hold it.
  static int checked(std::size_t notches);
  // The rows of interval (g, h): per outer notch q, E(g, h)[q] for q < g and W(g, h)[q] for q > h.
  using Row = std::vector<Witness>;

  // An X4-pattern on notches q, g, m, h in counter-clockwise cyclic order: X joins z_q and z_g, on g's
  // ray G, Y joins z_m and z_h, on h's ray H. E(k, j)[i] is (q, g, m, h) = (i, k, l, j); W(i, l)[j] is
  // (j, i, k, l).
  struct Query {
    int ray, along, index;  // Q, X's rank along G, and the query's position in the scan
  };
  struct Insert {
    int ray, along, at;  // M, the rank along G where M's line crosses it, and Y's rank along H
  };

  // A set of places in [0, size): a bitset under summary bitsets (a bit per nonempty word of the level
  // below) up to a single word. Inserting, and finding the nearest member on either side of a place,
  // take O(levels) word operations, levels = max(1, ceil(log_64 size)): at most 3 for the 65534 rays of
  // 32767 notches. (A linked list with offline insertion points would be O(1), but a query asks for the
  // nearest member of any place, where what it sees begins.)
  class PlaceSet {
   public:
    explicit PlaceSet(int size);
    void insert(int k);
    bool empty() const { return levels_.back()[0] == 0; }
    // The largest member at most k, or -1; k in [-1, size).
    int at_or_before(int k) const;
    // The smallest member at least k, or size; k in [0, size].
    int at_or_after(int k) const;

   private:
    static int highest(std::uint64_t word) { return 63 - __builtin_clzll(word); }
    static int lowest(std::uint64_t word) { return __builtin_ctzll(word); }
    // From member k of `level` down to the member of the bottom level that `pick` chooses in each word.
    int descend(std::size_t level, int k, int (*pick)(std::uint64_t)) const;
    int size_;
    std::vector<std::vector<std::uint64_t>> levels_;
  };

  // The funnel of the geodesics from G's two ends to a point e (docs/algorithms/chazelle-dobkin.md, (7)): from the end of G on its
  // left, seen from the apex (where the two geodesics meet), to the end on its right. For X on the open
  // G, the geodesic from X to e runs straight to a funnel vertex (funnel_tangent), on the ray that holds
  // the first point of the boundary it meets, and on along the funnel. When the apex is an end of G the
  // geodesic from the other end runs along G through it, and so does that of every X: the funnel is that
  // end alone.
  struct Funnel {
    std::vector<const FilteredPoint*> points;
    std::size_t apex = 0;
  };

  // One scan's inserts, the places of by_at (in order along H: Y's rank, then the ray, the order of the
  // walks), and what each query's X sees.
  struct Lists {
    Lists(int g_ray, int h_ray, std::vector<Insert> usable)
        : G(g_ray), H(h_ray), inserts(std::move(usable)), place(inserts.size()) {}
    int G, H;
    std::vector<Insert> inserts;
    std::vector<int> by_at;       // positions into inserts
    std::vector<int> place;       // by_at inverted: the place of each insert
    std::vector<int> below_rank;  // below_rank[v]: the places whose Y has a rank along H below v
    // kGeodesics: per end of H (0 its notch, 1 its far end), the funnel of the geodesics from G's ends
    // to it, once a query has needed them; per query the places its X sees, [lo, hi) (docs/algorithms/chazelle-dobkin.md, (7)),
    // once a pass has needed them; and where the last query's searches ended, in the funnels and along
    // H.
    std::array<Funnel, 2> funnels;
    std::vector<std::array<int, 2>> seen;
    std::array<std::size_t, 2> met_guess{0, 0}, place_guess{0, 0};

    const Insert& at_place(int k) const { return inserts[static_cast<std::size_t>(by_at[static_cast<std::size_t>(k)])]; }
  };

  // A walk's view of the places inserted in a pass: steps numbered from the end of the list the walk
  // starts at.
  class Walk {
   public:
    Walk(const PlaceSet& inserted, int size, bool down) : inserted_(inserted), size_(size), down_(down) {}
    int place(int step) const { return down_ ? size_ - 1 - step : step; }
    // The first inserted step at or after `step`, or size.
    int first_from(int step) const;

   private:
    const PlaceSet& inserted_;
    int size_;
    bool down_;
  };

  std::size_t at(int a, int b) const { return static_cast<std::size_t>(a) * notch_count_ + b; }

  // Called once per interval, shortest first (STEP 3): answers from the rows of shorter intervals, then
  // fills this interval's row, which needs S only strictly inside it.
  std::optional<X4Choice> x4_term(int i, int j, int to_beat) override;

  // T(a, b; m): splitting V(a+1, b-1) at m loses nothing.
  bool tight(int a, int b, int m) const { return S(a + 1, m - 1) + S(m + 1, b - 1) == S(a + 1, b - 1); }

  // STEP 3's X4 term: a tight X4-pattern from E(k, j)[i] or W(i, l)[j], with its Steiner points.
  std::optional<X4Choice> lookup(int i, int j);

  // The witness's Steiner points; Lemma 9 is checked on the patterns laid out (check_x4).
  X4Choice chosen(int count, const std::array<int, 4>& notches, std::uint8_t sides, bool wrapped);

  static int ray(int notch, std::uint8_t sides, int bit) { return 2 * notch + ((sides >> bit) & 1); }

  // Only the O(r) patterns laid out are checked, O(r log(n/r)) each: a witness that no layout uses
  // cannot make the output invalid (the program checks that the patterns laid out add up to
  // S(0, r-1)). A wrong one, which would be a bug of the scans, could still raise an S that STEP 4
  // compares with and so cost patterns elsewhere without a throw; the tests hold every row to walks
  // with segment searches and every count to chazelle-dobkin-n5's.
  void check_x4(const std::array<int, 4>& notches, const QPoint& x, const QPoint& y) override;

  // Lemma 9 on the loose pair, checked in full and independently of the scan: every angle at X and Y
  // below 180 degrees, each notch's edge in its closed range and in P, the edges meeting only at X and
  // Y, and XY in P.
  bool is_x4(const std::array<int, 4>& notches, const QPoint& x, const QPoint& y);

  bool joins(int notch, const QPoint& s);

  const QPoint& z(int notch) { return patterns().notch_point(static_cast<std::size_t>(notch)); }

  // The row of interval (g, h): the thesis's scan, once for each choice of the rays G and H.
  void fill(int g, int h);

  void scan(int g, int h, int G, int H, Row& row);

  // The outer notches q, in order along G, whose loose point X on G passes the conditions that do not
  // depend on the inner notch: X opens towards z_g (angle z_q X z_g), lies strictly right of the line
  // of H (angle at Y towards X), P1 is not a constant false, and z_q X cannot cross z_h Y.
  std::vector<Query> open_queries(int g, int h, int G, int H, const Row& row);

  // The tight inner notches m whose loose point Y on H passes the conditions that do not depend on the
  // outer notch: Y opens towards z_h, lies strictly right of the line of G, P2 is not a constant false,
  // and z_m Y cannot cross z_g X.
  std::vector<Insert> usable_inserts(int g, int h, int G, int H);

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
  bool crosses_before(int A, int B, int C) const;

  // P2 for inserts whose line crosses G with cross(u_m, u_g) > 0 asks X beyond the crossing: a prefix
  // along G. Queries are answered before the inserts of the same rank (strict inequality).
  void sweep_forward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g,
                     Row& row);

  void sweep_backward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g,
                      Row& row);

  // Inserts insert k into the pass when its line crosses G with the pass's sign.
  void admit(const Lists& lists, int k, int sign, PlaceSet& inserted);

  static bool has_witness(const Row& row, int q) { return !row.empty() && row[static_cast<std::size_t>(q)].inner >= 0; }

  // P1 bounds Y's rank along H on one side (or not at all when Q and H are parallel): a walk takes the
  // inserted Y from the far end of the list inwards while P1 holds, and the first that passes P4 (XY in
  // P) is the witness. Steps [0, end) are those where P1 holds: down from the top of H when Q's
  // direction does not turn clockwise from H's, else up from the bottom.
  int p1_end(const Query& query, const Lists& lists) const;

  // The witness of a query among the places inserted in a pass, if any: the first inserted step of its
  // walk where P1 holds and X sees Y. kGeodesics reads it from the places X sees (one lookup);
  // kSegmentSearch tests the steps in turn.
  void find_visible(const Query& query, Lists& lists, const PlaceSet& inserted, Row& row);

  const FilteredPoint& y_at(const Lists& lists, int place) { return rays_.loose_point(lists.H, lists.at_place(place).ray); }

  // How X on G sees Y on H: seen, or not with no seen point of H between Y and H's notch, or its far
  // end (docs/algorithms/chazelle-dobkin.md, (7)).
  enum class View { kSeen, kTowardsNotch, kTowardsFarEnd };

  // What X on G sees of H (docs/algorithms/chazelle-dobkin.md, (7)): f1 and f2, the first turns (or ends) of the geodesics from X to
  // H's notch and to its far end, and the orientation of X, f1, f2, 0 when X sees no point of H.
  struct Sight {
    std::array<const FilteredPoint*, 2> first_met{};
    int angle = 0;
  };

  // The places X sees, [lo, hi) in by_at order (docs/algorithms/chazelle-dobkin.md, (7)). Each search starts where the last
  // query's ended: along a pass the queries come in order along G, f1 and f2 move monotonically over
  // the funnels (F3), and the ends of what X sees along H monotonically too (M), so a scan costs
  // O(queries + inserts + funnels) orientations.
  std::array<int, 2> seen_places(const Query& query, Lists& lists);

  // f1, f2 and their angle for X, the scan's funnels built when its first query needs them.
  Sight sight_of(const FilteredPoint& x, Lists& lists);

  // The funnel of the geodesics from G's ends to terminal e: O(r), their length (they list their turns,
  // at notches, and their ends).
  Funnel funnel(int G, std::size_t e);

  // The first turn (or end) of the geodesic from X (on the open G) to the funnel's e (F3), searched from
  // `guess`, which becomes its index.
  const FilteredPoint& first_point_met(const Funnel& f, const FilteredPoint& x, std::size_t& guess);

  // F4: X sees exactly the points of the open H strictly inside the angle (less than 180 degrees)
  // between the rays from X through f1 and f2; nothing when that angle is empty. O(1).
  static View view_from(const FilteredPoint& x, const Sight& sight, const FilteredPoint& y);

  void record(Row& row, int q, int Q, int G, int M, int H);

  // The trees, over P's decomposition by vertical chords, built when a scan first needs a geodesic.
  GeodesicTrees& geodesics();

  int notch_count_;
  LooseRays rays_;
  std::vector<Row> rows_;  // at(g, h): the row of interval (g, h), empty when it has no witness
  P4Test p4_test_;
  std::optional<GeodesicTrees> geodesics_;
  std::vector<const FilteredPoint*> from_notch_, from_far_end_;  // the geodesics of funnel(), reused
  std::int64_t scans_sharing_an_end_ = 0, funnel_points_ = 0, funnel_steps_ = 0;
  std::int64_t table_entries_ = 0, table_witnesses_ = 0, scan_steps_ = 0, p4_tests_ = 0, lookup_steps_ = 0, chosen_ = 0,
               chosen_from_w_ = 0;
};

}  // namespace pd::cd
