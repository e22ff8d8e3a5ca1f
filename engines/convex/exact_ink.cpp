// Exact comparison of sums of square roots; see exact_ink.h.
#include "engines/convex/exact_ink.h"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>

namespace pd::ink {
namespace {

static_assert(std::is_same_v<Rational, mpq_class>, "exact_ink reads Rational as GMP's mpq_class");

// sqrt(c^2 q) for q = num/den is sqrt(num den) / den: an integer radicand and a rational factor.
struct Radical {
  mpz_class radicand;
  mpq_class factor;
};

Radical as_radical(const Rational& c, const Rational& q) {
  Radical r;
  r.radicand = q.get_num() * q.get_den();
  r.factor = c / mpq_class(q.get_den());
  return r;
}

// Merges radicals whose radicands differ by a square factor: sqrt(m) = (isqrt(m m') / m') sqrt(m')
// when m m' is a perfect square.
std::vector<Radical> merge_equivalent(const std::vector<std::pair<Rational, Rational>>& terms) {
  std::vector<Radical> merged;
  for (const auto& [c, q] : terms) {
    if (c == 0 || q == 0) continue;
    Radical r = as_radical(c, q);
    bool placed = false;
    for (Radical& m : merged) {
      const mpz_class product = r.radicand * m.radicand;
      if (mpz_perfect_square_p(product.get_mpz_t()) == 0) continue;
      mpz_class root;
      mpz_sqrt(root.get_mpz_t(), product.get_mpz_t());
      m.factor += r.factor * mpq_class(root, m.radicand);
      placed = true;
      break;
    }
    if (!placed) merged.push_back(r);
  }
  return merged;
}

// Lower (upper) bound of factor * sqrt(radicand) at `bits` of precision, added into `sum`.
void add_bound(mpfr_t sum, const Radical& r, mpfr_prec_t bits, mpfr_rnd_t toward) {
  const bool positive = r.factor > 0;
  // A lower bound of a product with a negative factor needs the upper bound of the root.
  const mpfr_rnd_t root_rounding = positive == (toward == MPFR_RNDD) ? MPFR_RNDD : MPFR_RNDU;
  mpfr_t root;
  mpfr_init2(root, bits + static_cast<mpfr_prec_t>(mpz_sizeinbase(r.radicand.get_mpz_t(), 2)));
  mpfr_set_z(root, r.radicand.get_mpz_t(), root_rounding);
  mpfr_sqrt(root, root, root_rounding);
  mpfr_mul_q(root, root, r.factor.get_mpq_t(), toward);
  mpfr_add(sum, sum, root, toward);
  mpfr_clear(root);
}

int sign_by_evaluation(const std::vector<Radical>& radicals, long* precision_bits) {
  for (mpfr_prec_t bits = 64; bits <= (mpfr_prec_t{1} << 24); bits *= 2) {
    mpfr_t lo, hi;
    mpfr_init2(lo, bits);
    mpfr_init2(hi, bits);
    mpfr_set_zero(lo, 1);
    mpfr_set_zero(hi, 1);
    for (const Radical& r : radicals) {
      add_bound(lo, r, bits, MPFR_RNDD);
      add_bound(hi, r, bits, MPFR_RNDU);
    }
    const int sign = mpfr_sgn(lo) > 0 ? 1 : (mpfr_sgn(hi) < 0 ? -1 : 0);
    mpfr_clear(lo);
    mpfr_clear(hi);
    if (sign != 0) {
      if (precision_bits) *precision_bits = static_cast<long>(bits);
      return sign;
    }
  }
  throw std::runtime_error("sum of square roots not decided at 2^24 bits");
}

double next_down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

}  // namespace

int sign_of_root_sum(const std::vector<std::pair<Rational, Rational>>& terms, long* precision_bits) {
  if (precision_bits) *precision_bits = 0;
  const std::vector<Radical> merged = merge_equivalent(terms);
  std::vector<Radical> nonzero;
  for (const Radical& r : merged)
    if (r.factor != 0) nonzero.push_back(r);
  if (nonzero.empty()) return 0;
  return sign_by_evaluation(nonzero, precision_bits);
}

Interval add(const Interval& a, const Interval& b) { return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)}; }

std::uint32_t SegmentLengths::add(const Point& a, const Point& b) {
  const Rational dx = Rational(a.x()) - Rational(b.x()), dy = Rational(a.y()) - Rational(b.y());
  squared_.push_back(dx * dx + dy * dy);
  mpfr_t root;
  mpfr_init2(root, 53);
  mpfr_set_q(root, squared_.back().get_mpq_t(), MPFR_RNDD);
  mpfr_sqrt(root, root, MPFR_RNDD);
  const double lo = mpfr_get_d(root, MPFR_RNDD);
  mpfr_set_q(root, squared_.back().get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(root, root, MPFR_RNDU);
  const double hi = mpfr_get_d(root, MPFR_RNDU);
  mpfr_clear(root);
  enclosure_.push_back({lo, hi});
  return static_cast<std::uint32_t>(squared_.size() - 1);
}

void SegmentLengths::freeze() {
  std::vector<std::uint32_t> order(squared_.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return squared_[a] < squared_[b]; });
  class_of_.assign(squared_.size(), 0);
  for (std::size_t k = 1; k < order.size(); ++k)
    class_of_[order[k]] = squared_[order[k]] == squared_[order[k - 1]] ? class_of_[order[k - 1]] : order[k];
  if (!order.empty()) class_of_[order[0]] = order[0];
}

int SegmentLengths::compare(const std::vector<std::uint32_t>& lhs, const std::vector<std::uint32_t>& rhs) {
  ++exact_;
  auto classes = [&](const std::vector<std::uint32_t>& ids) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t id : ids) out.push_back(class_of_[id]);
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<std::uint32_t> l = classes(lhs), r = classes(rhs);
  std::vector<std::uint32_t> only_l, only_r;
  std::set_difference(l.begin(), l.end(), r.begin(), r.end(), std::back_inserter(only_l));
  std::set_difference(r.begin(), r.end(), l.begin(), l.end(), std::back_inserter(only_r));
  if (only_l.empty() && only_r.empty()) {
    ++cancelled_;
    return 0;
  }
  ++evaluated_;
  std::vector<std::pair<Rational, Rational>> terms;
  for (std::uint32_t c : only_l) terms.emplace_back(Rational(1), squared_[c]);
  for (std::uint32_t c : only_r) terms.emplace_back(Rational(-1), squared_[c]);
  return sign_of_root_sum(terms);
}

}  // namespace pd::ink
