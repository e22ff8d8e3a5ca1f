#include "core/validate.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>
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

std::string index_fault(const Piece& piece, std::size_t m) {
  if (piece.size() < 3) return "has " + std::to_string(piece.size()) + " vertices";
  for (VertexId v : piece)
    if (v >= m) return "names vertex " + std::to_string(v) + ", which does not exist";
  Piece sorted = piece;
  std::sort(sorted.begin(), sorted.end());
  if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
    return "visits vertex " + std::to_string(*it) + " twice";
  return {};
}

std::string edge_text(VertexId a, VertexId b) { return std::to_string(a) + "-" + std::to_string(b); }

// The pieces' directed edges that no piece matches in the opposite direction, as a successor map.
// Returns a fault when an edge is used twice in one direction (overlap) or a vertex starts two of them.
std::string unmatched_edges(const std::vector<Piece>& pieces, std::unordered_map<VertexId, VertexId>& out) {
  std::unordered_map<std::uint64_t, std::int64_t> net;  // key (lo, hi): count lo->hi minus hi->lo
  for (const Piece& piece : pieces)
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const VertexId a = piece[i], b = piece[(i + 1) % piece.size()];
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      net[key] += a < b ? 1 : -1;
    }
  for (const auto& [key, count] : net) {
    if (count == 0) continue;
    const VertexId lo = static_cast<VertexId>(key >> 32), hi = static_cast<VertexId>(key & 0xffffffffu);
    if (count > 1 || count < -1)
      return "edge " + edge_text(lo, hi) + " is covered " + std::to_string(count > 0 ? count : -count) +
             " times from one side (overlap)";
    const VertexId from = count > 0 ? lo : hi, to = count > 0 ? hi : lo;
    if (!out.emplace(from, to).second)
      return "vertex " + std::to_string(from) + " starts two unshared edges (gap or overlap)";
  }
  return {};
}

// The tiling test: the unshared edges of the pieces must be exactly the polygon's boundary, each edge
// (i, i+1) walked forwards, possibly through Steiner points strictly inside it, in order.
template <class P>
std::string chain_fault(const Polygon& p, const std::vector<P>& pts, const std::vector<Piece>& pieces) {
  std::unordered_map<VertexId, VertexId> out;
  if (std::string f = unmatched_edges(pieces, out); !f.empty()) return f;
  const std::size_t n = p.size();
  std::size_t walked = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const VertexId end = static_cast<VertexId>(p.next(i));
    const std::string missing =
        "boundary edge " + edge_text(static_cast<VertexId>(i), end) + " is not covered exactly once from inside";
    for (VertexId cur = static_cast<VertexId>(i);;) {
      const auto it = out.find(cur);
      if (it == out.end() || walked == out.size()) return missing;
      const VertexId step = it->second;
      ++walked;
      if (step == end) break;
      if (step < n || orient(pts[i], pts[end], pts[step]) != 0 ||
          !CGAL::collinear_are_strictly_ordered_along_line(pts[cur], pts[step], pts[end]))
        return missing;
      cur = step;
    }
  }
  if (walked != out.size())
    for (const auto& [from, to] : out)
      if (from >= n || p.next(from) != to)
        return "edge " + edge_text(from, to) +
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
    if (twice_area(pts, pieces[k]) <= 0) return fail(piece_name(k) + " is clockwise or has no area");
  }
  if (std::string f = chain_fault(p, pts, pieces); !f.empty()) return fail(f);
  Rational total = 0;
  for (const Piece& piece : pieces) total += twice_area(pts, piece);
  if (total != twice_signed_area(p.vertices())) return fail("the pieces' areas do not add up to the polygon's");
  if (kind == Kind::Triangulation && pieces.size() + 2 != pts.size())
    return fail(std::to_string(pieces.size()) + " triangles; a triangulation of " + std::to_string(pts.size()) +
                " vertices has " + std::to_string(pts.size() - 2));
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
  return validate_pieces(p, exact_points(p, d), pieces, kind, allow_steiner);
}

}  // namespace pd
