// seidel: Seidel's randomized triangulation (R. Seidel, "A simple and fast incremental randomized
// algorithm for computing trapezoidal decompositions and for triangulating polygons", Computational
// Geometry: Theory and Applications 1(1), 1991; listed in Rosen's slides 003, "Towards linear-time
// triangulation").
//
// Expected time O(n log* n) over the algorithm's own random choices (for every input), space O(n).
// Pre: a polygon, with h >= 0 holes (the trapezoidal decomposition is of any non-crossing segments,
// and the pending edges are walked ring by ring; with holes Seidel's bound is O(n log n)); collinear
// (180-degree) vertices and horizontal edges allowed. Output: n+3h-3 diagonals, n+2h-2
// non-degenerate triangles, no Steiner points.
//
// 1. The trapezoidal decomposition of the edges, inserted in a random order, with its search DAG
//    (point nodes, segment nodes, trapezoid leaves): locate the endpoints, split their trapezoids,
//    thread the edge down through the trapezoids it crosses, merge what the edge now separates.
// 2. The log* phases: after each phase (about n / log^(h) n edges) the pending edges are traced
//    through the decomposition, so that each one's search later starts where its endpoints lie.
// 3. In every inside trapezoid whose top and bottom vertices are not joined by a side, the diagonal
//    between them: monotone pieces, which triangulate_monotone_pieces (monotone.h) triangulates.
//
// Deviation from the paper: the insertion order is a biased randomized insertion order (BRIO,
// Amenta, Choi and Rote, SoCG 2003: rounds of Bernoulli samples, each round in polygon order), so
// that consecutive insertions work near one another in memory; docs/algorithms/seidel.md proves the
// expected bound stays O(n log* n) (Clarkson and Shor's counting). Unlike the classic C code
// (Narkhede and Manocha, tolerance 1e-7), every test is exact: orient() or a coordinate comparison,
// with ties broken by an infinitesimal shear (the sweep order `above`, monotone.h) and by the other
// endpoint of the edge being inserted. The random order comes from the project's own generator with a
// fixed seed, so the output is the same on every machine.
//
// Hot loop: point location and threading in the DAG. The cells (trapezoids and the nodes that replace
// them) are 32 bytes aligned to 32, one cache line each; the next kLookahead insertions' searches are
// advanced one step per insertion with prefetches (exact: a search node never changes), and tracing
// interleaves kTracers runs so that their cache misses overlap. The layout and the experiments
// behind it (and those not kept) are in docs/algorithms/seidel.md.
#include "core/registry.h"
#include "engines/triangulation/monotone.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace pd {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
using Pair = std::array<std::uint32_t, 2>;  // up to two neighbours, left to right, kNone-padded

Pair pair_of(std::uint32_t a, std::uint32_t b) { return a == kNone ? Pair{b, kNone} : Pair{a, b}; }
bool has_two(const Pair& a) { return a[1] != kNone; }
std::uint32_t other(const Pair& a, std::uint32_t x) { return a[0] == x ? a[1] : a[0]; }
void replace(Pair& a, std::uint32_t from, std::uint32_t to) {
  for (std::uint32_t& x : a)
    if (x == from) x = to;
}

// A trapezoid of the decomposition: between the horizontal cuts through vertices hi and lo and
// between segments left and right (segment s is polygon edge s -> s+1); kNone is unbounded.
struct Trapezoid {
  std::uint32_t hi, lo, left, right;
  Pair up, down;  // neighbours across the cuts at hi and at lo
};

// A search-structure node: a point node holds its point; a segment node holds its segment's upper
// endpoint and the vertex id of its lower one. The node's kind is folded into the child fields: the
// left (or above) child carries kNodeTag, which tells a node from a trapezoid (whose first field is a
// vertex id below 2^31, or kNone), and a segment node's right child carries kSegmentNode.
constexpr std::uint32_t kNodeTag = 0x80000000u, kSegmentNode = 0x80000000u;

struct Node {
  std::uint32_t first;   // point node: above | kNodeTag; segment node: left | kNodeTag
  std::uint32_t second;  // point node: below; segment node: right | kSegmentNode
  std::uint32_t bottom;  // segment node: its lower endpoint
  double x, y;           // point node: its point; segment node: its upper endpoint
};

// One record is both a trapezoid and, once the trapezoid is destroyed, the search-structure node that
// replaced it, so that a search ends on the trapezoid itself and the nodes pointing at a destroyed
// trapezoid need no update. The search reads one cell per step at a random address, so a cell is 32
// bytes aligned to 32: every cell lies in one cache line. A segment node therefore keeps only its
// upper endpoint and reads the lower one from the polygon. Tags in the child ids limit a
// decomposition to 2^31 - 1 cells: with room for 8n of them reserved, n < 2.6*10^8.
union alignas(32) Cell {
  Trapezoid z;
  Node node;

  // Trapezoid and Node begin with the same fields, which either member may read.
  bool is_leaf() const { return z.hi == kNone || z.hi < kNodeTag; }
  bool is_segment_node() const { return node.second & kSegmentNode; }
  std::uint32_t left_child() const { return node.first & ~kNodeTag; }
  std::uint32_t right_child() const { return node.second & ~kSegmentNode; }
};
static_assert(sizeof(Cell) == 32, "a cell is one trapezoid, half a cache line");

// Segment s (polygon edge s -> s+1) with its endpoints in the sweep order.
struct Segment {
  Point top, bottom;
  std::uint32_t upper, lower;
  std::uint32_t start[2];  // where the searches for the ends at vertex s and at vertex s+1 start
};

// Per edge, in a byte of its own so that the scans over all edges stay in the cache.
enum EdgeFlag : std::uint8_t { kDescends = 1, kInserted = 2 };

// SplitMix64 (Steele, Lea, Flood 2014): a fixed, portable source for the random insertion order.
class SplitMix {
 public:
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_ = 0x5e1de1;
};

class Trapezoidation {
 public:
  explicit Trapezoidation(const Polygon& p)
      : p_(p), n_(static_cast<std::uint32_t>(p.size())), segs_(n_), flags_(n_, 0), point_phase_(n_, 0),
        point_node_(n_, 0) {
    for (std::uint32_t s = 0; s < n_; ++s) {
      const std::uint32_t t = next(s);
      const bool down = above(p_[s], p_[t]);
      segs_[s] = down ? Segment{p_[s], p_[t], s, t, {0, 0}} : Segment{p_[t], p_[s], t, s, {0, 0}};
      if (down) flags_[s] = kDescends;
    }
    // Between 4n and 6.5n cells are made on the families measured; growing would copy them all, and
    // capacity never used costs no memory (its pages are never touched).
    const std::size_t capacity = 8 * std::size_t{n_} + 16;
    if (capacity >= kNodeTag - 1) throw std::length_error("seidel: too many vertices for 31-bit cell ids");
    cells_.reserve(capacity);
    allocate({kNone, kNone, kNone, kNone, {kNone, kNone}, {kNone, kNone}});  // the plane; cell 0 is the root
  }

  // Inserts every edge in the BRIO order (docs/algorithms/seidel.md, "Deviation from the paper"),
  // phase by phase, tracing the rest after each phase.
  void build() {
    const InsertionOrder order = brio_order();
    std::uint32_t done = 0;
    for (std::uint32_t end : phase_ends(order.round_ends)) {
      insert_phase(order.edges, done, end);
      done = end;
      if (done < n_) trace_pending();
      ++phases_;
    }
  }

  // Step 3: the top-bottom diagonal of every inside trapezoid whose sides do not join them, ordered by
  // top vertex (the trapezoids were made in insertion order; triangulate_monotone_pieces files each
  // diagonal under both its vertices, which in vertex order reads and writes its arrays with far fewer
  // cache misses). The counting sort is O(n).
  std::vector<Cut> monotone_diagonals() const {
    std::vector<Cut> made;
    for (const Cell& c : cells_)
      if (is_diagonal(c)) made.push_back({c.z.hi, c.z.lo});
    std::vector<std::uint32_t> first(std::size_t{n_} + 1, 0);
    for (const Cut& d : made) ++first[d.a + 1];
    for (std::uint32_t v = 0; v < n_; ++v) first[v + 1] += first[v];
    std::vector<Cut> diagonals(made.size());
    for (const Cut& d : made) diagonals[first[d.a]++] = d;
    return diagonals;
  }

  void count(Counters& counters) const {
    counters["trapezoids"] = made_;
    counters["search_steps"] = search_steps_;
    counters["trace_steps"] = trace_steps_;
    counters["phases"] = phases_;
  }

 private:
  // The polygon's next and previous vertex in v's ring (the edge s runs from s to next(s)).
  std::uint32_t next(std::uint32_t v) const { return static_cast<std::uint32_t>(p_.next(v)); }
  std::uint32_t prev(std::uint32_t v) const { return static_cast<std::uint32_t>(p_.prev(v)); }
  const Point& at(std::uint32_t v) const { return p_[v]; }
  Trapezoid& z(std::uint32_t t) { return cells_[t].z; }
  std::uint32_t upper(std::uint32_t s) const { return segs_[s].upper; }
  std::uint32_t lower(std::uint32_t s) const { return segs_[s].lower; }
  // Which of segment s's two search starts belongs to its endpoint v.
  std::uint32_t& start_of(std::uint32_t s, std::uint32_t v) { return segs_[s].start[v == s ? 0 : 1]; }
  // orient(upper, lower, q) > 0: q is right of the downward segment s.
  bool right_of(std::uint32_t s, std::uint32_t q) const { return orient(segs_[s].top, segs_[s].bottom, at(q)) > 0; }

  bool inserted(std::uint32_t s) const { return flags_[s] & kInserted; }
  bool has_point(std::uint32_t v) const { return point_phase_[v] != 0; }
  void mark_point(std::uint32_t v, std::uint32_t node) {
    point_phase_[v] = static_cast<std::uint8_t>(phases_ + 1);
    point_node_[v] = node;
  }
  // The polygon lies right of its downward edges (counter-clockwise order).
  bool inside(const Trapezoid& t) const { return t.left != kNone && (flags_[t.left] & kDescends); }
  // Whether cell c is a trapezoid inside the polygon whose top and bottom vertices no side joins.
  bool is_diagonal(const Cell& c) const {
    return c.is_leaf() && inside(c.z) && !joins(c.z.left, c.z) && !joins(c.z.right, c.z);
  }
  // Side s (edge s -> s+1) runs from the trapezoid's top vertex to its bottom vertex.
  bool joins(std::uint32_t s, const Trapezoid& t) const {
    return s != kNone && ((s == t.hi && next(s) == t.lo) || (s == t.lo && next(s) == t.hi));
  }

  // The edges round by round, each round in polygon order, and where each round ends in that order.
  struct InsertionOrder {
    std::vector<std::uint32_t> edges, round_ends;
  };

  // Each edge draws its round: the last, ceil(log2 n), with probability 1/2, the one before with 1/4,
  // and so on; round 0 takes the remaining 2^-ceil(log2 n). A counting sort by round keeps polygon
  // order within a round.
  InsertionOrder brio_order() const {
    std::uint32_t last = 0;
    while ((std::uint64_t{1} << last) < n_) ++last;
    std::vector<std::uint8_t> round(n_);
    SplitMix rng;
    for (std::uint32_t s = 0; s < n_; ++s) {
      // Trailing zeros of a random word: z or more with probability 2^-z (bit 63 keeps the word nonzero).
      const auto zeros = static_cast<std::uint32_t>(__builtin_ctzll(rng.next() | (std::uint64_t{1} << 63)));
      round[s] = static_cast<std::uint8_t>(last - std::min(zeros, last));
    }
    InsertionOrder order{std::vector<std::uint32_t>(n_), std::vector<std::uint32_t>(last + 1, 0)};
    for (std::uint32_t s = 0; s < n_; ++s) ++order.round_ends[round[s]];
    for (std::uint32_t k = 1; k <= last; ++k) order.round_ends[k] += order.round_ends[k - 1];
    std::vector<std::uint32_t> next_slot(last + 1, 0);
    for (std::uint32_t k = 1; k <= last; ++k) next_slot[k] = order.round_ends[k - 1];
    for (std::uint32_t s = 0; s < n_; ++s) order.edges[next_slot[round[s]]++] = s;
    return order;
  }

  // Phase h ends with the first round after which every edge has been inserted with probability at
  // least 1 / log^(h) n (so after about N(h) = n / log^(h) n edges), while log^(h) n > 1; the last
  // phase ends with all n. Phases that would end at the same place are one.
  std::vector<std::uint32_t> phase_ends(const std::vector<std::uint32_t>& round_ends) const {
    const auto last = static_cast<std::uint32_t>(round_ends.size() - 1);
    std::vector<std::uint32_t> ends;
    for (double v = std::log2(double(n_)); v > 1; v = std::log2(v)) {
      const auto rounds_left = static_cast<std::uint32_t>(std::floor(std::log2(v)));
      const std::uint32_t end = round_ends[last - std::min(rounds_left, last)];
      if (end > 0 && end < n_ && (ends.empty() || ends.back() < end)) ends.push_back(end);
    }
    ends.push_back(n_);
    return ends;
  }

  std::uint32_t allocate(const Trapezoid& t) {
    Cell c;
    c.z = t;
    cells_.push_back(c);
    ++made_;
    return static_cast<std::uint32_t>(cells_.size() - 1);
  }

  void make_point_node(std::uint32_t cell, const Point& q, std::uint32_t above_it, std::uint32_t below_it) {
    Node& c = cells_[cell].node;
    c.first = above_it | kNodeTag;
    c.second = below_it;
    c.x = q.x();
    c.y = q.y();
  }

  void make_segment_node(std::uint32_t cell, std::uint32_t s, std::uint32_t left, std::uint32_t right) {
    Node& c = cells_[cell].node;
    c.first = left | kNodeTag;
    c.second = right | kSegmentNode;
    c.bottom = lower(s);
    c.x = segs_[s].top.x();
    c.y = segs_[s].top.y();
  }

  // The child of search node c on the side of point q moved a little towards point toward. q lies on
  // a node's segment only as one of its endpoints.
  std::uint32_t child_toward(const Cell& c, const Point& q, const Point& toward) const {
    const Point x(c.node.x, c.node.y);
    if (!c.is_segment_node()) return above(x == q ? toward : q, x) ? c.left_child() : c.node.second;
    const Point& bottom = at(c.node.bottom);
    const Point& probe = (q == x || q == bottom) ? toward : q;
    return orient(x, bottom, probe) > 0 ? c.right_child() : c.left_child();
  }

  // The trapezoid holding point q moved a little towards point toward, searching from cell `from`.
  std::uint32_t locate(const Point& q, const Point& toward, std::uint32_t from) {
    std::uint32_t cell = from;
    for (; !cells_[cell].is_leaf(); ++search_steps_) cell = child_toward(cells_[cell], q, toward);
    return cell;
  }

  // Inserts order[begin, end) with the lookahead of the header's hot-loop note: slot k % kLookahead
  // holds the lookahead of insertion k.
  void insert_phase(const std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end) {
    std::array<Lookahead, kLookahead> ahead;
    for (std::uint32_t j = begin; j < end && j < begin + kLookahead; ++j) ahead[j % kLookahead] = look_ahead(order[j]);
    for (std::uint32_t j = begin + kLookahead; j < end && j < begin + 2 * kLookahead; ++j) prefetch(segs_[order[j]]);
    for (std::uint32_t k = begin; k < end; ++k) {
      for (std::uint32_t j = k + 1; j < end && j < k + kLookahead; ++j) advance(ahead[j % kLookahead], order[j]);
      insert(order[k], ahead[k % kLookahead].search);
      if (k + kLookahead < end) ahead[k % kLookahead] = look_ahead(order[k + kLookahead]);
      if (k + 2 * kLookahead < end) prefetch(segs_[order[k + 2 * kLookahead]]);
    }
  }

  static constexpr std::uint32_t kLookahead = 6;  // measured best of 4, 6, 8, 12, 16, 24 at n = 10^6
  static constexpr std::uint32_t kWalkDone = kNone - 1;

  // A pending insertion's early work: where the search for its upper endpoint stands, and where the
  // read-only walk down along the edge stands (kNone before the search reaches a leaf, kWalkDone
  // after the walk ends), with whether what the next step reads besides that cell (a segment node's
  // lower endpoint, or the trapezoid's surroundings) has been prefetched.
  struct Lookahead {
    std::uint32_t search, walk;
    bool fetched;
  };

  Lookahead look_ahead(std::uint32_t s) {
    const Lookahead a{start_of(s, upper(s)), kNone, false};
    prefetch(cells_[a.search]);
    prefetch(point_phase_[upper(s)]);
    prefetch(point_phase_[lower(s)]);
    return a;
  }

  // One step of edge s's lookahead: a search step, or a step of the walk down along s. Each step only
  // reads records prefetched by the step before, and prefetches what the next one reads.
  void advance(Lookahead& a, std::uint32_t s) {
    const Cell& c = cells_[a.search];
    if (!c.is_leaf()) {
      if (c.is_segment_node() && !a.fetched) {
        prefetch(at(c.node.bottom));
        a.fetched = true;
        return;
      }
      a.search = child_toward(c, segs_[s].top, segs_[s].bottom);
      a.walk = kNone;
      a.fetched = false;
      ++search_steps_;
      prefetch(cells_[a.search]);
      return;
    }
    if (a.walk == kNone) a = {a.search, a.search, false};
    // A trapezoid the walk reached may have been replaced since by an insertion before this one.
    if (a.walk == kWalkDone || !cells_[a.walk].is_leaf()) {
      a.walk = kWalkDone;
    } else if (!a.fetched) {
      prefetch_surroundings(z(a.walk));
      a.fetched = true;
    } else {
      const std::uint32_t next = below_along(s, a.walk);
      a.walk = next == kNone ? kWalkDone : next;
      a.fetched = false;
      if (next != kNone) prefetch(cells_[next]);
    }
  }

  // What inserting an edge through trapezoid t reads next: its bottom vertex and its neighbours.
  void prefetch_surroundings(const Trapezoid& t) const {
    if (t.lo != kNone) prefetch(p_[t.lo]);
    for (std::uint32_t x : t.up)
      if (x != kNone) prefetch(cells_[x]);
    for (std::uint32_t x : t.down)
      if (x != kNone) prefetch(cells_[x]);
  }

  // The trapezoid below t that edge s (not yet inserted, crossing t) enters, or kNone if s ends in t.
  std::uint32_t below_along(std::uint32_t s, std::uint32_t t) const {
    const Trapezoid& z = cells_[t].z;
    const std::uint32_t b = z.lo;
    if (b == kNone || !above(at(b), segs_[s].bottom)) return kNone;
    return has_two(z.down) ? z.down[right_of(s, b) ? 0 : 1] : z.down[0];
  }

  // Starts the reads of a record (at most 48 bytes, so at most two cache lines) without waiting. A
  // record no larger than its alignment (a cell) lies in one line.
  template <class T>
  static void prefetch(const T& record) {
    __builtin_prefetch(&record);
    if constexpr (sizeof(T) > alignof(T)) __builtin_prefetch(reinterpret_cast<const char*>(&record) + sizeof(T) - 1);
  }

  // One search per edge, for its upper endpoint, from `from` (a cell on its search path from the
  // edge's start). The lower endpoint is met while threading.
  void insert(std::uint32_t s, std::uint32_t from) {
    const std::uint32_t u = upper(s);
    const std::uint32_t t = locate(segs_[s].top, segs_[s].bottom, from);
    Crossed first{z(t), t, t};
    if (!has_point(u)) first = cut_keeping_above(first, u, segs_[s].top);
    thread(s, first);
    flags_[s] |= kInserted;
  }

  // A trapezoid the edge being inserted crosses: its contents; the id its neighbours know it by; the
  // cell that becomes its search node. When an endpoint of the edge has just cut a trapezoid, the
  // part the edge then splits at once gets no record of its own: its neighbours across the far side
  // still know it by the old trapezoid's id, and its node is a fresh cell under the endpoint's node.
  struct Crossed {
    Trapezoid z;
    std::uint32_t id, node;
  };

  std::uint32_t new_node() {
    cells_.emplace_back();
    return static_cast<std::uint32_t>(cells_.size() - 1);
  }

  // Cuts c through vertex v (at q): the part above becomes a trapezoid, the part below is returned.
  Crossed cut_keeping_above(Crossed c, std::uint32_t v, const Point& q) {
    Trapezoid top = c.z;
    top.lo = v;
    const std::uint32_t a = allocate(top), below = new_node();
    for (std::uint32_t x : top.up)
      if (x != kNone) replace(z(x).down, c.id, a);
    make_point_node(c.node, q, a, below);
    mark_point(v, c.node);
    c.z.hi = v;
    c.z.up = {a, kNone};
    c.node = below;
    return c;
  }

  // Cuts c through vertex v (at q): the part below becomes a trapezoid, the part above is returned.
  Crossed cut_keeping_below(Crossed c, std::uint32_t v, const Point& q) {
    Trapezoid bottom = c.z;
    bottom.hi = v;
    const std::uint32_t b = allocate(bottom), above_v = new_node();
    for (std::uint32_t x : bottom.down)
      if (x != kNone) replace(z(x).up, c.id, b);
    make_point_node(c.node, q, above_v, b);
    mark_point(v, c.node);
    c.z.lo = v;
    c.z.down = {b, kNone};
    c.node = above_v;
    return c;
  }

  // Threads segment s down from c, just below its upper endpoint, to its lower endpoint, cutting the
  // trapezoid holding the lower endpoint at it first if it is new. Each crossed trapezoid is replaced
  // by a left and a right piece; at each cut the edge crosses, the pieces on the side away from the
  // cut's vertex merge (the cut now ends at s), those on its side stay apart.
  void thread(std::uint32_t s, Crossed c) {
    const std::uint32_t l = lower(s);
    const Point& bottom = segs_[s].bottom;
    std::uint32_t left = kNone, right = kNone;
    for (;;) {
      if (!has_point(l) && (c.z.lo == kNone || above(bottom, at(c.z.lo)))) c = cut_keeping_below(c, l, bottom);
      const Trapezoid& old = c.z;
      if (left == kNone) {
        left = allocate({old.hi, kNone, old.left, s, {kNone, kNone}, {kNone, kNone}});
        right = allocate({old.hi, kNone, s, old.right, {kNone, kNone}, {kNone, kNone}});
        link_top(old, c.id, left, right, other_edge(upper(s), s));
      }
      make_segment_node(c.node, s, left, right);
      if (old.lo == l) {
        z(left).lo = z(right).lo = l;
        link_bottom(old, c.id, left, right, other_edge(l, s));
        return;
      }
      const std::uint32_t b = old.lo;
      const bool b_right = right_of(s, b);
      const std::uint32_t next_t = has_two(old.down) ? old.down[b_right ? 0 : 1] : old.down[0];
      const Trapezoid next = z(next_t);
      const std::uint32_t down_other = other(old.down, next_t), up_other = other(next.up, c.id);
      if (b_right) {
        z(right).lo = b;
        const std::uint32_t below = allocate({b, kNone, s, next.right, pair_of(right, up_other), {kNone, kNone}});
        z(right).down = pair_of(below, down_other);
        if (down_other != kNone) replace(z(down_other).up, c.id, right);
        if (up_other != kNone) replace(z(up_other).down, next_t, below);
        right = below;
      } else {
        z(left).lo = b;
        const std::uint32_t below = allocate({b, kNone, next.left, s, pair_of(up_other, left), {kNone, kNone}});
        z(left).down = pair_of(down_other, below);
        if (down_other != kNone) replace(z(down_other).up, c.id, left);
        if (up_other != kNone) replace(z(up_other).down, next_t, below);
        left = below;
      }
      c = {next, next_t, next_t};
    }
  }

  // The polygon's other edge at vertex v, an endpoint of edge s.
  std::uint32_t other_edge(std::uint32_t v, std::uint32_t s) const { return s == v ? prev(v) : v; }

  // The neighbours above the first trapezoid t, which s splits from its top vertex hi: a side
  // starting at hi (it can only be `adjacent`, the polygon's other edge there) leaves the piece on
  // that side with no top edge; else the cut at hi is split at hi.
  void link_top(const Trapezoid& old, std::uint32_t t, std::uint32_t left, std::uint32_t right,
                std::uint32_t adjacent) {
    if (old.left == adjacent) {
      give_up(old.up, t, right);
    } else if (old.right == adjacent) {
      give_up(old.up, t, left);
    } else if (has_two(old.up)) {
      z(left).up = {old.up[0], kNone};
      z(right).up = {old.up[1], kNone};
      replace(z(old.up[0]).down, t, left);
      replace(z(old.up[1]).down, t, right);
    } else {
      z(left).up = z(right).up = {old.up[0], kNone};
      z(old.up[0]).down = {left, right};
    }
  }

  void link_bottom(const Trapezoid& old, std::uint32_t t, std::uint32_t left, std::uint32_t right,
                   std::uint32_t adjacent) {
    if (old.left == adjacent) {
      give_down(old.down, t, right);
    } else if (old.right == adjacent) {
      give_down(old.down, t, left);
    } else if (has_two(old.down)) {
      z(left).down = {old.down[0], kNone};
      z(right).down = {old.down[1], kNone};
      replace(z(old.down[0]).up, t, left);
      replace(z(old.down[1]).up, t, right);
    } else {
      z(left).down = z(right).down = {old.down[0], kNone};
      z(old.down[0]).up = {left, right};
    }
  }

  void give_up(const Pair& up, std::uint32_t t, std::uint32_t piece) {
    z(piece).up = up;
    for (std::uint32_t x : up)
      if (x != kNone) replace(z(x).down, t, piece);
  }

  void give_down(const Pair& down, std::uint32_t t, std::uint32_t piece) {
    z(piece).down = down;
    for (std::uint32_t x : down)
      if (x != kNone) replace(z(x).up, t, piece);
  }

  // Step 2: each maximal run of edges not yet inserted starts at a vertex of an inserted edge. One
  // search (from the run's old trapezoid) finds where the run starts; walking along each edge of the
  // run finds where it ends, which is where the next one starts (its shared vertex is no point of the
  // decomposition yet). A run only reads the decomposition and writes its own edges' starts, so
  // kTracers runs are traced at once, one step each in turn, and their cache misses overlap (the
  // header's hot-loop note). Every run takes the same steps as it would alone.
  void trace_pending() {
    std::array<Tracer, kTracers> tracers;
    std::uint32_t next_vertex = 0, busy = 0;
    for (Tracer& t : tracers) busy += start_run(t, next_vertex);
    while (busy > 0)
      for (Tracer& t : tracers) {
        if (t.edge == kNone || trace_step(t)) continue;
        if (!start_run(t, next_vertex)) --busy;
      }
  }

  static constexpr std::uint32_t kTracers = 16;  // at n = 10^6, 8 traced 10-30% slower and 32 no faster

  // A run being traced: the edge it stands on (kNone when idle), the cell (a search node while it
  // searches for the run's start, then the trapezoid holding the walk), and whether the point the
  // next step compares with (a segment node's lower endpoint, or the vertex whose cut the walk
  // leaves by) has been prefetched.
  struct Tracer {
    std::uint32_t edge = kNone, cell = 0;
    bool searching = false, fetched = false;
  };

  // Starts t on the first run at or after vertex `from`; false (t idle) if there is none.
  bool start_run(Tracer& t, std::uint32_t& from) {
    for (; from < n_; ++from) {
      const std::uint32_t v = from;
      if (inserted(v) || !inserted(prev(v))) continue;
      ++from;
      t = {v, run_search_start(v), true, false};
      prefetch(cells_[t.cell]);
      return true;
    }
    t.edge = kNone;
    return false;
  }

  // Where to search for the start of a run at vertex v: v's own point node if v became a point in
  // this phase (its subtree covers all of v's surroundings and only this phase's changes lie below
  // it), else where the last tracing found the run's first edge.
  std::uint32_t run_search_start(std::uint32_t v) {
    return point_phase_[v] == phases_ + 1 ? point_node_[v] : start_of(v, v);
  }

  // One step of t, of its search or of its walk; false when its run is done.
  bool trace_step(Tracer& t) {
    if (t.searching && search_step(t)) return true;
    return walk_step(t);
  }

  // A step of the search for the start of t's run; false once it stands on the trapezoid holding it.
  bool search_step(Tracer& t) {
    const std::uint32_t s = t.edge;
    const Cell& c = cells_[t.cell];
    if (c.is_leaf()) {
      t.searching = false;
      start_of(s, s) = t.cell;
      return false;
    }
    if (c.is_segment_node() && !t.fetched) {
      prefetch(at(c.node.bottom));
      t.fetched = true;
      return true;
    }
    t.fetched = false;
    t.cell = child_toward(c, at(s), at(next(s)));
    ++search_steps_;
    prefetch(cells_[t.cell]);
    return true;
  }

  // Reads t's trapezoid and prefetches the vertex the walk compares with; or, that done, moves on to
  // the next trapezoid along the edge, or to the run's next edge where the edge ends. False when the
  // run is done.
  bool walk_step(Tracer& t) {
    const std::uint32_t s = t.edge;
    if (!t.fetched) {
      const std::uint32_t b = compared_vertex(s, z(t.cell));
      if (b != kNone) prefetch(at(b));
      t.fetched = true;
      return true;
    }
    t.fetched = false;
    const std::uint32_t after = step_along(s, t.cell);
    if (after != kNone) {
      t.cell = after;
      ++trace_steps_;
      prefetch(cells_[after]);
      return true;
    }
    start_of(s, next(s)) = t.cell;
    t.edge = next(s);
    if (inserted(t.edge)) return false;
    start_of(t.edge, t.edge) = t.cell;
    return true;
  }

  // The vertex whose cut a walk along edge s (from vertex s to s+1) leaves trapezoid t by.
  std::uint32_t compared_vertex(std::uint32_t s, const Trapezoid& t) const { return s == upper(s) ? t.lo : t.hi; }

  // The trapezoid after t along edge s walked from vertex s to vertex s+1, or kNone if s+1 lies in t.
  std::uint32_t step_along(std::uint32_t s, std::uint32_t t) const {
    if (s == upper(s)) return below_along(s, t);
    const Trapezoid& z = cells_[t].z;
    const std::uint32_t b = compared_vertex(s, z);
    if (b == kNone || !above(segs_[s].top, at(b))) return kNone;
    return has_two(z.up) ? z.up[right_of(s, b) ? 0 : 1] : z.up[0];
  }

  const Polygon& p_;
  std::uint32_t n_;
  std::vector<Segment> segs_;
  std::vector<std::uint8_t> flags_;
  std::vector<std::uint8_t> point_phase_;  // 1 + the phase in which the vertex became a point; 0: not yet
  std::vector<std::uint32_t> point_node_;  // the point node of its cut
  std::vector<Cell> cells_;
  std::int64_t made_ = 0, search_steps_ = 0, trace_steps_ = 0, phases_ = 0;
};

Decomposition seidel(const Polygon& p, Counters& counters) {
  Trapezoidation trapezoidation(p);
  trapezoidation.build();
  trapezoidation.count(counters);
  return triangulate_monotone_pieces(p, trapezoidation.monotone_diagonals(), counters);
}

}  // namespace

REGISTER_ALGORITHM({.name = "seidel", .kind = Kind::Triangulation, .time_bound = "n*log*(n)",
                    .pieces_bound = "== n+2*h-2",
                    .source = "Seidel 1991, randomized trapezoidation + monotone triangulation (slides 003 table)",
                    .accepts = {.holes = true}, .run = seidel});

}  // namespace pd
