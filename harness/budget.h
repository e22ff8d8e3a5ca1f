// The sweep's time budget: decides, before a key runs, whether it should, so that a sweep never
// stalls on an O(n^4) program. A key is skipped when
//   - n is above the algorithm's size ceiling (Algorithm::size_ceiling);
//   - a cheaper point of the same algorithm and family already went over the budget or timed out;
//   - its time, extrapolated from the nearest cheaper measured point with the claimed time bound
//     (Algorithm::time_bound), would exceed the budget.
// "Cheaper" means n' <= n and f(n', r') <= f(n, r) for the claimed bound f; when the claim is not in
// BoundExpr's grammar, n' <= n and r' <= r, and no extrapolation (the hard timeout still applies).
// Any seed counts: seeds of one grid point cost about the same. The budget is the sweep's, or the
// algorithm's own where the sweep gives it one.
#pragma once

#include "core/bound_expr.h"
#include "core/registry.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pd {

class Budget {
 public:
  Budget(double budget_seconds, std::map<std::string, double> budget_seconds_for)
      : budget_seconds_(budget_seconds), budget_seconds_for_(std::move(budget_seconds_for)) {}

  // A finished key: seconds per call of the algorithm.
  void record_time(const Algorithm& a, const std::string& family, std::size_t n, std::size_t r, double seconds);
  // A key skipped for the budget or stopped by the timeout.
  void record_over_budget(const Algorithm& a, const std::string& family, std::size_t n, std::size_t r);

  // "skipped (ceiling|budget): why", or nothing when the key should run.
  std::optional<std::string> skip_reason(const Algorithm& a, const std::string& family, std::size_t n,
                                         std::size_t r) const;

 private:
  struct Point {
    std::size_t n, r;
    double seconds;  // per call; unused when over
    bool over;
  };
  const std::optional<BoundExpr>& bound(const Algorithm& a) const;
  bool cheaper(const Algorithm& a, const Point& p, std::size_t n, std::size_t r) const;
  double seconds_for(const Algorithm& a) const;

  double budget_seconds_;
  std::map<std::string, double> budget_seconds_for_;  // by algorithm, in place of budget_seconds_
  std::map<std::pair<std::string, std::string>, std::vector<Point>> seen_;  // by (algorithm, family)
  mutable std::map<std::string, std::optional<BoundExpr>> bounds_;          // parsed claims, by algorithm
};

}  // namespace pd
