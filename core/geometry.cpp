#include "core/geometry.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace pd {

bool is_double(const Rational& v) {
  const double d = CGAL::to_double(v);
  return std::isfinite(d) && Rational(d) == v;
}

std::string double_text(double d) {
  char buf[64];
  // When the shortest text is an integer it is the exact value (to_chars breaks ties between texts of
  // one length by the smallest difference), so it reads back under core/coordinate.h's rule.
  const auto res = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, res.ptr);
}

std::string rational_text(const Rational& v) {
  if (is_double(v)) return double_text(CGAL::to_double(v));
  std::ostringstream out;
  out << v.get_num() << '/' << v.get_den();
  return out.str();
}

}  // namespace pd
