// Claimed time bounds as functions of n and r, so that the harness can predict how long the next grid
// point will take from the last measured one.
//
// Grammar (the registry's `time_bound` strings): sums, products, quotients and powers of numbers, `n`,
// `r`, parentheses, and the functions log(x), log^k(x), log*(x) (iterated logarithm), min(a, b, ...),
// max(a, b, ...), sqrt(x). Examples: "n^4", "n*log(n)", "n*r^2*log(r)", "n+r^5*log(n/r)",
// "n+min(n*r^2,r^4)", "n*log*(n)". analysis/polydecomp_analysis/bound_expr.py reads the same grammar;
// tests/data/bound_expr_vectors.json holds the cases both are tested on.
//
// Evaluation is for ratios, not absolute costs, so it keeps every factor at least 1: n and r are
// raised to at least 2 and 1 (a convex polygon, r = 0, still costs "n*r^2" = n, not 0), and
// logarithms are base 2 and at least 1.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace pd {

class BoundExpr {
 public:
  // The bound, or nothing when `text` is not in the grammar.
  static std::optional<BoundExpr> parse(const std::string& text);
  double operator()(double n, double r) const;

 private:
  explicit BoundExpr(std::function<double(double, double)> f) : f_(std::move(f)) {}
  std::function<double(double, double)> f_;
};

}  // namespace pd
