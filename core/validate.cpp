#include "core/validate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace pd {
namespace {

Validation fail(std::string why) { return {false, std::move(why)}; }

std::string piece_name(std::size_t k) { return "piece " + std::to_string(k); }

template <class P>
Rational twice_area(const std::vector<P>& pts, const Piece& piece) {
  Rational sum = 0;
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const P& a = pts[piece[i]];
    const P& b = pts[piece[(i + 1) % piece.size()]];
    sum += Rational(a.x()) * Rational(b.y()) - Rational(b.x()) * Rational(a.y());
  }
  return sum;
}

// Twice a piece's area in 128-bit integers, exact when every coordinate is an integer below 2^50 in
// magnitude: each edge's cross term is below 2^101, so fewer than 2^26 edges in all cannot overflow.
using Wide = __int128;
constexpr double kWideCoordinate = 1125899906842624.0;  // 2^50
constexpr std::size_t kWideEdges = std::size_t(1) << 26;

Wide twice_area_wide(const std::vector<Point>& pts, const Piece& piece) {
  Wide sum = 0;
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const Point& a = pts[piece[i]];
    const Point& b = pts[piece[(i + 1) % piece.size()]];
    sum += Wide(static_cast<std::int64_t>(a.x())) * static_cast<std::int64_t>(b.y()) -
           Wide(static_cast<std::int64_t>(b.x())) * static_cast<std::int64_t>(a.y());
  }
  return sum;
}

bool wide_is_exact(const std::vector<Point>& pts, const std::vector<Piece>& pieces) {
  for (const Point& q : pts)
    for (const double c : {q.x(), q.y()})
      if (!(std::abs(c) < kWideCoordinate) || c != std::floor(c)) return false;
  std::size_t edges = pts.size();
  for (const Piece& piece : pieces) edges += piece.size();
  return edges < kWideEdges;
}

// The area test: the first piece whose area is not positive (clockwise or flat), and whether the
// areas add up to the polygon's (its outer ring's less its holes', from its first n points).
struct AreaCheck {
  std::string piece_fault;
  bool adds_up = false;
};

template <class Number, class AreaOf>
AreaCheck check_areas(const Polygon& p, const std::vector<Piece>& pieces, AreaOf twice_area_of) {
  Number total = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Number area = twice_area_of(pieces[k]);
    if (area <= 0) return {piece_name(k) + " is clockwise or has no area"};
    total += area;
  }
  Number polygon = 0;
  for (std::size_t r = 0; r < p.ring_count(); ++r) {
    Piece ring(p.ring_end(r) - p.ring_begin(r));
    std::iota(ring.begin(), ring.end(), static_cast<VertexId>(p.ring_begin(r)));
    polygon += twice_area_of(ring);
  }
  return {{}, total == polygon};
}

template <class P>
AreaCheck check_areas(const Polygon& p, const std::vector<P>& pts, const std::vector<Piece>& pieces) {
  if constexpr (std::is_same_v<P, Point>) {
    if (wide_is_exact(pts, pieces))
      return check_areas<Wide>(p, pieces, [&](const Piece& piece) { return twice_area_wide(pts, piece); });
  }
  return check_areas<Rational>(p, pieces, [&](const Piece& piece) { return twice_area(pts, piece); });
}

// Upwards (or rightwards along the horizontal) versus downwards edge directions.
template <class P>
bool points_up(const P& a, const P& b) {
  return b.y() > a.y() || (b.y() == a.y() && b.x() > a.x());
}

// Convex, counter-clockwise and simple: every turn is left or straight on (never back), and the edge
// directions wind exactly once (they switch between up and down exactly twice).
template <class P>
std::string convexity_fault(const std::vector<P>& pts, const Piece& piece) {
  const std::size_t k = piece.size();
  std::size_t switches = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const P& a = pts[piece[i]];
    const P& b = pts[piece[(i + 1) % k]];
    const P& c = pts[piece[(i + 2) % k]];
    const int turn = orient(a, b, c);
    if (turn < 0) return "turns right at vertex " + std::to_string(piece[(i + 1) % k]);
    if (turn == 0 && !CGAL::collinear_are_strictly_ordered_along_line(a, b, c))
      return "folds back at vertex " + std::to_string(piece[(i + 1) % k]);
    switches += points_up(a, b) != points_up(b, c);
  }
  if (switches != 2) return "winds more than once";
  return {};
}

// Weakly y-monotone: with runs of equal y merged, exactly one local maximum and one local minimum.
template <class P>
bool is_y_monotone(const std::vector<P>& pts, const Piece& piece) {
  std::vector<int> steps;  // +1 up, -1 down, horizontal steps skipped
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const P& a = pts[piece[i]];
    const P& b = pts[piece[(i + 1) % piece.size()]];
    if (a.y() != b.y()) steps.push_back(b.y() > a.y() ? 1 : -1);
  }
  std::size_t changes = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) changes += steps[i] != steps[(i + 1) % steps.size()];
  return changes == 2;
}

template <class P>
std::string shape_fault(const std::vector<P>& pts, const Piece& piece, Kind kind) {
  switch (kind) {
    case Kind::Triangulation:
      if (piece.size() != 3) return "has " + std::to_string(piece.size()) + " vertices, not 3";
      if (orient(pts[piece[0]], pts[piece[1]], pts[piece[2]]) <= 0) return "is not a counter-clockwise triangle";
      return {};
    case Kind::Convex:
      return convexity_fault(pts, piece);
    case Kind::Partition:
    case Kind::Cut: {
      std::vector<P> cycle;
      for (VertexId v : piece) cycle.push_back(pts[v]);
      std::string why;
      if (!is_simple_cycle(cycle, &why)) return "is not simple: " + why;
      if (kind == Kind::Partition && !is_y_monotone(pts, piece)) return "is not y-monotone";
      return {};
    }
  }
  return {};
}

constexpr std::size_t kSmallPiece = 8;

std::string index_fault(const Piece& piece, std::size_t m) {
  if (piece.size() < 3) return "has " + std::to_string(piece.size()) + " vertices";
  for (VertexId v : piece)
    if (v >= m) return "names vertex " + std::to_string(v) + ", which does not exist";
  if (piece.size() <= kSmallPiece) {  // pairwise, without a sorted copy (a triangulation has 10^6 pieces)
    for (std::size_t i = 0; i < piece.size(); ++i)
      for (std::size_t j = i + 1; j < piece.size(); ++j)
        if (piece[i] == piece[j]) return "visits vertex " + std::to_string(piece[i]) + " twice";
    return {};
  }
  Piece sorted = piece;
  std::sort(sorted.begin(), sorted.end());
  if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
    return "visits vertex " + std::to_string(*it) + " twice";
  return {};
}

std::string edge_text(VertexId a, VertexId b) { return std::to_string(a) + "-" + std::to_string(b); }

constexpr VertexId kNoSuccessor = ~VertexId(0);

// One use of an edge by a piece, in the row of the edge's lower endpoint: the other endpoint, and +1
// when the piece walks it upwards (lower to higher id), -1 when downwards.
struct EdgeUse {
  VertexId other;
  std::int32_t sign;
  bool operator<(const EdgeUse& u) const { return other < u.other; }
};

// The pieces' directed edges that no piece matches in the opposite direction, as a successor per
// vertex (kNoSuccessor when none), with their number. Returns a fault when an edge is used twice in
// one direction (overlap) or a vertex starts two of them. The uses are rows by lower endpoint (a
// counting sort, then each row's few uses sorted), so an edge and its reverse meet in one row: O(E)
// for E piece edges but for the few edges at each vertex. The polygon's own edges walked forwards,
// a third of a triangulation's piece edges, are counted per edge instead of joining the rows.
class EdgeMatch {
 public:
  EdgeMatch(const Polygon& p, std::size_t m) : p_(p), n_(p.size()), forward_(n_, 0), start_(m + 2, 0) {}

  std::string unmatched(const std::vector<Piece>& pieces, std::vector<VertexId>& successor, std::size_t& count) {
    fill_rows(pieces);
    count = 0;
    for (std::size_t lo = 0; lo + 2 < start_.size(); ++lo) {
      const auto first = uses_.begin() + static_cast<std::ptrdiff_t>(start_[lo]);
      const auto last = uses_.begin() + static_cast<std::ptrdiff_t>(start_[lo + 1]);
      if (last - first > 1) std::sort(first, last);
      for (auto it = first; it != last;) {
        const VertexId hi = it->other;
        int net = 0;
        for (; it != last && it->other == hi; ++it) net += it->sign;
        net += take_forward(static_cast<VertexId>(lo), hi) - take_forward(hi, static_cast<VertexId>(lo));
        if (std::string f = record(static_cast<VertexId>(lo), hi, net, successor, count); !f.empty()) return f;
      }
    }
    for (std::size_t i = 0; i < n_; ++i) {
      const auto a = static_cast<VertexId>(i), b = static_cast<VertexId>(p_.next(i));
      const int net = take_forward(a, b);
      if (std::string f = a < b ? record(a, b, net, successor, count) : record(b, a, -net, successor, count); !f.empty())
        return f;
    }
    return {};
  }

 private:
  bool is_polygon_edge(VertexId a, VertexId b) const { return a < n_ && b < n_ && p_.next(a) == b; }

  // Rows by lower endpoint: a pass counting each row's uses (and the polygon's edges walked forwards),
  // then a pass placing them.
  void fill_rows(const std::vector<Piece>& pieces) {
    auto each_edge = [&](auto visit) {
      for (const Piece& piece : pieces)
        for (std::size_t i = 0; i < piece.size(); ++i) visit(piece[i], piece[(i + 1) % piece.size()]);
    };
    each_edge([&](VertexId a, VertexId b) {
      if (!is_polygon_edge(a, b)) ++start_[std::min(a, b) + 2];
      else if (forward_[a] < 255) ++forward_[a];
    });
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    uses_.resize(start_.back());
    each_edge([&](VertexId a, VertexId b) {  // row r then lies in [start[r], start[r+1])
      if (!is_polygon_edge(a, b)) uses_[start_[std::min(a, b) + 1]++] = EdgeUse{std::max(a, b), a < b ? 1 : -1};
    });
  }

  // The uses of polygon edge a -> b walked forwards, once: they leave the count when taken.
  int take_forward(VertexId a, VertexId b) {
    if (!is_polygon_edge(a, b)) return 0;
    const int uses = forward_[a];
    forward_[a] = 0;
    return uses;
  }

  // Edge lo-hi used `net` times more upwards than downwards: matched (0), or an unshared edge.
  static std::string record(VertexId lo, VertexId hi, int net, std::vector<VertexId>& successor, std::size_t& count) {
    if (net == 0) return {};
    if (net > 1 || net < -1)
      return "edge " + edge_text(lo, hi) + " is covered " + std::to_string(net > 0 ? net : -net) +
             " times from one side (overlap)";
    const VertexId from = net > 0 ? lo : hi, to = net > 0 ? hi : lo;
    if (successor[from] != kNoSuccessor) return "vertex " + std::to_string(from) + " starts two unshared edges (gap or overlap)";
    successor[from] = to;
    ++count;
    return {};
  }

  const Polygon& p_;
  std::size_t n_;
  std::vector<std::uint8_t> forward_;  // uses of polygon edge i -> next(i), at most 255 counted
  std::vector<std::size_t> start_;
  std::vector<EdgeUse> uses_;
};

// The tiling test: the unshared edges of the pieces must be exactly the polygon's boundary, each edge
// (i, next(i)) walked forwards, possibly through Steiner points strictly inside it, in order.
template <class P>
std::string chain_fault(const Polygon& p, const std::vector<P>& pts, const std::vector<Piece>& pieces) {
  std::vector<VertexId> successor(pts.size(), kNoSuccessor);
  std::size_t unshared = 0;
  if (std::string f = EdgeMatch(p, pts.size()).unmatched(pieces, successor, unshared); !f.empty()) return f;
  const std::size_t n = p.size();
  std::size_t walked = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const VertexId end = static_cast<VertexId>(p.next(i));
    auto missing = [&] {
      return "boundary edge " + edge_text(static_cast<VertexId>(i), end) + " is not covered exactly once from inside";
    };
    for (VertexId cur = static_cast<VertexId>(i);;) {
      const VertexId step = successor[cur];
      if (step == kNoSuccessor || walked == unshared) return missing();
      ++walked;
      if (step == end) break;
      if (step < n || orient(pts[i], pts[end], pts[step]) != 0 ||
          !CGAL::collinear_are_strictly_ordered_along_line(pts[cur], pts[step], pts[end]))
        return missing();
      cur = step;
    }
  }
  if (walked != unshared)
    for (VertexId from = 0; from < successor.size(); ++from)
      if (successor[from] != kNoSuccessor && (from >= n || p.next(from) != successor[from]))
        return "edge " + edge_text(from, successor[from]) +
               " is not shared by pieces on both sides (gap, overlap or a cut leaving the polygon)";
  return {};
}

std::string coincidence_fault(const std::vector<QPoint>& pts, std::size_t n) {
  if (pts.size() == n) return {};
  std::vector<std::size_t> order(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pts[a] < pts[b]; });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (pts[order[k - 1]] == pts[order[k]])
      return "Steiner point " + std::to_string(std::max(order[k - 1], order[k])) + " coincides with point " +
             std::to_string(std::min(order[k - 1], order[k]));
  return {};
}

template <class P>
Validation validate_with(const Polygon& p, const std::vector<P>& pts, const std::vector<Piece>& pieces, Kind kind) {
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (std::string f = index_fault(pieces[k], pts.size()); !f.empty()) return fail(piece_name(k) + " " + f);
    if (std::string f = shape_fault(pts, pieces[k], kind); !f.empty()) return fail(piece_name(k) + " " + f);
  }
  const AreaCheck areas = check_areas(p, pts, pieces);
  if (!areas.piece_fault.empty()) return fail(areas.piece_fault);
  if (std::string f = chain_fault(p, pts, pieces); !f.empty()) return fail(f);
  if (!areas.adds_up) return fail("the pieces' areas do not add up to the polygon's");
  // Euler's formula: m vertices, all on the boundary, and h holes make m + 2h - 2 triangles. Each
  // Steiner point inside adds two; with Steiner points the tiling proven above is the whole check.
  const std::size_t triangles = pts.size() + 2 * p.hole_count() - 2;
  if (kind == Kind::Triangulation && pts.size() == p.size() && pieces.size() != triangles)
    return fail(std::to_string(pieces.size()) + " triangles; a triangulation of " + std::to_string(pts.size()) +
                " vertices" + (p.hole_count() ? " and " + std::to_string(p.hole_count()) + " holes" : "") + " has " +
                std::to_string(triangles));
  return {};
}

}  // namespace

Validation validate_pieces(const Polygon& p, const std::vector<QPoint>& points, const std::vector<Piece>& pieces,
                           Kind kind, bool allow_steiner) {
  const std::size_t n = p.size();
  if (points.size() > n && !allow_steiner)
    return fail(std::to_string(points.size() - n) + " Steiner points from a diagonal-only algorithm");
  if (pieces.empty()) return fail("no pieces");
  if (points.size() == n) return validate_with(p, p.vertices(), pieces, kind);
  if (std::string f = coincidence_fault(points, n); !f.empty()) return fail(f);
  return validate_with(p, points, pieces, kind);
}

Validation validate(const Polygon& p, const Decomposition& d, Kind kind, bool allow_steiner) {
  std::vector<Piece> pieces;
  try {
    pieces = pieces_of(p, d);
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  return validate_pieces(p, d, pieces, kind, allow_steiner);
}

Validation validate_pieces(const Polygon& p, const Decomposition& d, const std::vector<Piece>& pieces, Kind kind,
                           bool allow_steiner) {
  if (!d.steiner.empty()) return validate_pieces(p, exact_points(p, d), pieces, kind, allow_steiner);
  if (pieces.empty()) return fail("no pieces");
  return validate_with(p, p.vertices(), pieces, kind);
}

}  // namespace pd
