#include "core/geometry.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

namespace pd {

bool is_double(const Rational& v) {
  const double d = CGAL::to_double(v);
  return std::isfinite(d) && Rational(d) == v;
}

std::string double_text(double d) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, d);
  // From 2^53 up, the shortest text may be an integer that is not the double's exact value (2^60
  // prints as 1152921504606847000, not ...976); an integer is read as exact (core/coordinate.h), so
  // such values are written with an exponent.
  if (std::fabs(d) >= 9007199254740992.0 && std::string_view(buf, res.ptr - buf).find_first_of(".e") == std::string_view::npos)
    res = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific);
  return std::string(buf, res.ptr);
}

std::string rational_text(const Rational& v) {
  if (is_double(v)) return double_text(CGAL::to_double(v));
  std::ostringstream out;
  out << v.get_num() << '/' << v.get_den();
  return out.str();
}

}  // namespace pd
