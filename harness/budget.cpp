#include "harness/budget.h"

#include <cstdio>

namespace pd {
namespace {

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

std::string point_text(std::size_t n, std::size_t r) {
  return "n:" + std::to_string(n) + "/r:" + std::to_string(r);
}

}  // namespace

void Budget::record_time(const Algorithm& a, const std::string& family, std::size_t n, std::size_t r,
                         double seconds) {
  seen_[{a.name, family}].push_back({n, r, seconds, false});
}

void Budget::record_over_budget(const Algorithm& a, const std::string& family, std::size_t n, std::size_t r) {
  seen_[{a.name, family}].push_back({n, r, 0, true});
}

const std::optional<BoundExpr>& Budget::bound(const Algorithm& a) const {
  auto at = bounds_.find(a.name);
  if (at == bounds_.end()) at = bounds_.emplace(a.name, BoundExpr::parse(a.time_bound)).first;
  return at->second;
}

bool Budget::cheaper(const Algorithm& a, const Point& p, std::size_t n, std::size_t r) const {
  if (p.n > n) return false;
  const auto& f = bound(a);
  return f ? (*f)(p.n, p.r) <= (*f)(n, r) : p.r <= r;
}

double Budget::seconds_for(const Algorithm& a) const {
  for (const std::string& name : {a.name, a.variant_of}) {  // a variant's curve needs its base's sizes
    const auto own = budget_seconds_for_.find(name);
    if (own != budget_seconds_for_.end()) return own->second;
  }
  return budget_seconds_;
}

std::optional<std::string> Budget::skip_reason(const Algorithm& a, const std::string& family, std::size_t n,
                                               std::size_t r) const {
  if (n > a.size_ceiling)
    return "skipped (ceiling): n=" + std::to_string(n) + " is above the size ceiling " + std::to_string(a.size_ceiling);
  const auto at = seen_.find({a.name, family});
  if (at == seen_.end()) return std::nullopt;
  const auto& f = bound(a);
  const Point* reference = nullptr;
  for (const Point& p : at->second) {
    if (!cheaper(a, p, n, r)) continue;
    if (p.over) return "skipped (budget): the cheaper point " + point_text(p.n, p.r) + " already exceeded the budget";
    if (f && (!reference || (*f)(p.n, p.r) > (*f)(reference->n, reference->r))) reference = &p;
  }
  if (!reference) return std::nullopt;
  const double predicted = reference->seconds * (*f)(n, r) / (*f)(reference->n, reference->r);
  const double budget = seconds_for(a);
  if (predicted <= budget) return std::nullopt;
  return "skipped (budget): predicted " + seconds_text(predicted) + " > budget " + seconds_text(budget) +
         " from " + seconds_text(reference->seconds) + " at " + point_text(reference->n, reference->r) + " and the claimed O(" +
         a.time_bound + ")";
}

}  // namespace pd
