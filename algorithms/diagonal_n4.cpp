// diagonal-n4: diagonal-based triangulation, exactly as the slides give it (Rosen, "Polygon
// Partitioning", lecture slides 003, "Diagonal-based triangulation" and "Brute force triangulation").
//
// Time O(n^4), space O(n^2). Pre: a simple counter-clockwise polygon; collinear (180-degree) vertices
// are allowed. Output: n-3 diagonals, n-2 non-degenerate triangles (the greedy triangulation), no
// Steiner points.
//
// Repeat n-3 times: for each of the O(n^2) candidate segments v_i v_j not yet output, test it against
// every edge and both neighbourhoods (O(n), engines/triangulation/diagonal_test.h) and against the diagonals already output
// (O(n)), each test in full, so that every round costs Theta(n^3); output a proper one. The slides
// leave open which proper diagonal to output; this one outputs the shortest (ties by endpoints), so
// that every round really examines every candidate, as the slides' count has it, and so that
// `diagonal-n3` can be checked against it: both build the greedy triangulation. A maximal set of
// non-crossing diagonals triangulates the polygon, and with collinear vertices too its faces are
// non-degenerate triangles (a face with more than three vertices still has a diagonal), so n-3 rounds
// always find one.
#include "core/registry.h"
#include "engines/triangulation/diagonal_test.h"

#include <optional>
#include <vector>

namespace pd {
namespace {

using namespace diagonal_test;

class RepeatedDiagonalSearch {
 public:
  explicit RepeatedDiagonalSearch(const Polygon& p) : p_(p), n_(p.size()), output_(n_ * n_, 0) {}

  Decomposition run(Counters& counters) {
    Decomposition d;
    d.cuts.reserve(n_ - 3);
    for (std::size_t round = 0; round + 3 < n_; ++round) {
      const Cut c = *best_candidate(d.cuts);
      output_[c.a * n_ + c.b] = 1;
      d.add_cut(c.a, c.b);
    }
    counters["diagonal_tests"] = diagonal_tests_;
    counters["edge_tests"] = edge_tests_;
    counters["crossing_tests"] = crossing_tests_;
    return d;
  }

 private:
  std::optional<Cut> best_candidate(const std::vector<Cut>& chosen) {
    std::optional<Cut> best;
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = i + 2; j < n_; ++j) {
        if ((i == 0 && j + 1 == n_) || output_[i * n_ + j]) continue;
        const Cut c{static_cast<VertexId>(i), static_cast<VertexId>(j)};
        if (proper(c, chosen) && (!best || picked_before(p_, c, *best))) best = c;
      }
    return best;
  }

  // In full, like the diagonal test: against every diagonal already output as well.
  bool proper(const Cut& c, const std::vector<Cut>& chosen) {
    ++diagonal_tests_;
    bool crosses_one = false;
    for (const Cut& t : chosen) crosses_one |= cross(p_, c, t);
    crossing_tests_ += static_cast<std::int64_t>(chosen.size());
    return is_diagonal(p_, c.a, c.b, edge_tests_) && !crosses_one;
  }

  const Polygon& p_;
  std::size_t n_;
  std::vector<char> output_;  // output_[i*n + j]: v_i v_j (i < j) already output
  std::int64_t diagonal_tests_ = 0, edge_tests_ = 0, crossing_tests_ = 0;
};

Decomposition diagonal_n4(const Polygon& p, Counters& counters) { return RepeatedDiagonalSearch(p).run(counters); }

}  // namespace

REGISTER_ALGORITHM({.name = "diagonal-n4", .kind = Kind::Triangulation, .time_bound = "n^4",
                    .pieces_bound = "== n-2",
                    .source = "Rosen slides (003), diagonal-based triangulation, O(n^4)",
                    .size_ceiling = 200, .run = diagonal_n4});

}  // namespace pd
