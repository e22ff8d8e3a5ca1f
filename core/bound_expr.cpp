#include "core/bound_expr.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace pd {
namespace {

using Fn = std::function<double(double, double)>;

struct ParseFailure {};

double log2_at_least_1(double x) { return std::max(1.0, std::log2(std::max(x, 2.0))); }

double log_star(double x) {
  double count = 0;
  for (; x > 1; x = std::log2(x)) ++count;
  return std::max(1.0, count);
}

class Parser {
 public:
  explicit Parser(const std::string& text) {
    for (char c : text)
      if (!std::isspace(static_cast<unsigned char>(c))) s_ += c;
  }

  Fn whole() {
    Fn f = sum();
    if (i_ != s_.size()) throw ParseFailure{};
    return f;
  }

 private:
  bool take(char c) {
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) throw ParseFailure{};
  }
  bool take_word(const std::string& w) {
    if (s_.compare(i_, w.size(), w) != 0) return false;
    i_ += w.size();
    return true;
  }

  Fn sum() {
    Fn f = product();
    for (;;) {
      if (take('+')) {
        f = [a = f, b = product()](double n, double r) { return a(n, r) + b(n, r); };
      } else if (take('-')) {
        f = [a = f, b = product()](double n, double r) { return a(n, r) - b(n, r); };
      } else {
        return f;
      }
    }
  }

  Fn product() {
    Fn f = power();
    for (;;) {
      if (take('*')) {
        f = [a = f, b = power()](double n, double r) { return a(n, r) * b(n, r); };
      } else if (take('/')) {
        f = [a = f, b = power()](double n, double r) { return a(n, r) / b(n, r); };
      } else {
        return f;
      }
    }
  }

  Fn power() {
    Fn base = atom();
    if (!take('^')) return base;
    Fn exponent = atom();
    return [base, exponent](double n, double r) { return std::pow(base(n, r), exponent(n, r)); };
  }

  Fn atom() {
    if (take('(')) {
      Fn f = sum();
      expect(')');
      return f;
    }
    if (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) return number();
    if (take_word("log")) return logarithm();
    if (take_word("min")) return extremum([](double a, double b) { return std::min(a, b); });
    if (take_word("max")) return extremum([](double a, double b) { return std::max(a, b); });
    if (take_word("sqrt")) {
      Fn x = argument();
      return [x](double n, double r) { return std::sqrt(x(n, r)); };
    }
    if (take('n')) return [](double n, double) { return std::max(n, 2.0); };
    if (take('r')) return [](double, double r) { return std::max(r, 1.0); };
    throw ParseFailure{};
  }

  Fn number() {
    const char* start = s_.c_str() + i_;
    char* end = nullptr;
    const double v = std::strtod(start, &end);
    if (end == start) throw ParseFailure{};
    i_ += static_cast<std::size_t>(end - start);
    return [v](double, double) { return v; };
  }

  // After "log": log(x), log*(x) or log^k(x).
  Fn logarithm() {
    if (i_ + 1 < s_.size() && s_[i_] == '*' && s_[i_ + 1] == '(') {
      ++i_;
      Fn x = argument();
      return [x](double n, double r) { return log_star(x(n, r)); };
    }
    Fn k = [](double, double) { return 1.0; };
    if (take('^')) k = number();
    Fn x = argument();
    return [x, k](double n, double r) { return std::pow(log2_at_least_1(x(n, r)), k(n, r)); };
  }

  Fn argument() {
    expect('(');
    Fn x = sum();
    expect(')');
    return x;
  }

  Fn extremum(double (*pick)(double, double)) {
    expect('(');
    std::vector<Fn> args{sum()};
    while (take(',')) args.push_back(sum());
    expect(')');
    return [args, pick](double n, double r) {
      double v = args[0](n, r);
      for (std::size_t k = 1; k < args.size(); ++k) v = pick(v, args[k](n, r));
      return v;
    };
  }

  std::string s_;
  std::size_t i_ = 0;
};

}  // namespace

std::optional<BoundExpr> BoundExpr::parse(const std::string& text) {
  try {
    return BoundExpr(Parser(text).whole());
  } catch (const ParseFailure&) {
    return std::nullopt;
  }
}

double BoundExpr::operator()(double n, double r) const { return f_(n, r); }

}  // namespace pd
