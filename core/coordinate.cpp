#include "core/coordinate.h"

#include <cfloat>
#include <cstddef>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace pd {
namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if ((a[i] | 0x20) != b[i]) return false;
  return true;
}

// How the text is written: not a number, a non-finite word, an integer, or a decimal with a fraction
// or an exponent.
enum class Form { Invalid, NonFinite, Integer, Decimal };

Form form_of(std::string_view t) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const std::string_view word = t.substr(i);
  if (equals_ignoring_case(word, "nan") || equals_ignoring_case(word, "inf") ||
      equals_ignoring_case(word, "infinity"))
    return Form::NonFinite;
  std::size_t digits = 0;
  for (; i < t.size() && is_digit(t[i]); ++i) ++digits;
  bool integer = true;
  if (i < t.size() && t[i] == '.') {
    integer = false;
    for (++i; i < t.size() && is_digit(t[i]); ++i) ++digits;
  }
  if (digits == 0) return Form::Invalid;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    integer = false;
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    for (; i < t.size() && is_digit(t[i]); ++i) ++exponent_digits;
    if (exponent_digits == 0) return Form::Invalid;
  }
  if (i != t.size()) return Form::Invalid;
  return integer ? Form::Integer : Form::Decimal;
}

bool has_nonzero_digit(std::string_view t) {
  for (const char c : t) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

// The integer's digits without sign and leading zeros ("0" for zero).
std::string_view magnitude_digits(std::string_view t) {
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.remove_prefix(1);
  while (t.size() > 1 && t[0] == '0') t.remove_prefix(1);
  return t;
}

// Integers of at most 15 digits are below 2^53, so exactly doubles.
constexpr std::size_t kAlwaysExactDigits = 15;
// A decimal without an exponent this short is far from overflow (309 digits) and underflow (307 zeros).
constexpr std::ptrdiff_t kPlainDecimalLength = 300;

// The nearest double (strtod's rounding; from_chars, which needs no terminated copy, where it can).
double nearest_double(std::string_view t) {
  const std::string_view unsigned_part = !t.empty() && t[0] == '+' ? t.substr(1) : t;
  double d = 0;
  const auto [end, error] = std::from_chars(unsigned_part.data(), unsigned_part.data() + unsigned_part.size(), d);
  if (error == std::errc() && end == unsigned_part.data() + unsigned_part.size()) return d;
  const std::string copy(t);  // out of range, or a form from_chars does not take: strtod says
  return std::strtod(copy.c_str(), nullptr);
}

// An integer-valued double's exact decimal digits.
std::string exact_integer_text(double d) {
  char buffer[400];
  std::snprintf(buffer, sizeof buffer, "%.0f", std::fabs(d));
  return buffer;
}

}  // namespace

std::optional<double> plain_coordinate(const char*& at, const char* end) {
  // The commonest coordinate, an integer of at most 15 characters, is exactly its digits' value and
  // needs no from_chars; anything longer, or with more to it, goes on to from_chars.
  const char* p = at + (at < end && *at == '-');
  std::int64_t magnitude = 0;
  for (; p < end && is_digit(*p) && p - at < static_cast<std::ptrdiff_t>(kAlwaysExactDigits); ++p)
    magnitude = magnitude * 10 + (*p - '0');
  if (p > at && is_digit(p[-1]) && (p == end || !(is_digit(*p) || *p == '.' || *p == 'e' || *p == 'E'))) {
    const double d = static_cast<double>(magnitude);
    const bool negative = *at == '-';
    at = p;
    return negative ? -d : d;
  }
  double d;
  const char* start = at;
  const auto [stop, error] = std::from_chars(start, end, d);
  if (error != std::errc()) return std::nullopt;
  bool point = false;
  for (const char* c = start; c < stop; ++c) {
    if (*c == '.') point = true;
    else if (!is_digit(*c) && *c != '-') return std::nullopt;
  }
  if (stop - start > (point ? kPlainDecimalLength : static_cast<std::ptrdiff_t>(kAlwaysExactDigits))) return std::nullopt;
  at = stop;
  return d;
}

std::string quoted_input(std::string_view text, std::size_t limit) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c > 0x7e || c == '\'' || c == '\\') {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", c);
      out += escape;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + (text.size() > limit ? "...'" : "'");
}

std::optional<double> coordinate_value(std::string_view text, std::string& why) {
  const Form form = form_of(text);
  if (form == Form::Invalid) {
    why = quoted_input(text) + " is not a number";
    return std::nullopt;
  }
  const double d = nearest_double(text);
  if (form == Form::NonFinite) return d;
  if (std::isinf(d)) {
    why = quoted_input(text) + " is too large for a double";
    return std::nullopt;
  }
  if (has_nonzero_digit(text) && std::fabs(d) < DBL_MIN) {
    why = quoted_input(text) + " is too small for a double (it is not 0)";
    return std::nullopt;
  }
  if (form == Form::Integer && magnitude_digits(text).size() > kAlwaysExactDigits &&
      exact_integer_text(d) != magnitude_digits(text)) {
    why = quoted_input(text) + " is not exactly a double (the nearest is " + (d < 0 ? "-" : "") + exact_integer_text(d) + ")";
    return std::nullopt;
  }
  return d;
}

}  // namespace pd
