// The reader is a one-pass recursive descent over RFC 8259's grammar: strings are checked as UTF-8 and
// their escapes decoded, numbers keep their source text, and with pack_positions a position is read
// into doubles as it is met (core/coordinate.h's plain_coordinate, the full rule otherwise), so that a
// GeoJSON file of n vertices costs about a from_chars scan and 2n doubles, not a tree node per number.
// The escaping for the writers stays with nlohmann/json (Debian's nlohmann-json3-dev).
#include "core/json.h"

#include "core/coordinate.h"
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace pd {
namespace {

constexpr std::size_t kMaxDepth = 256;

class Parser {
 public:
  Parser(std::string_view text, bool pack_positions)
      : begin_(text.data()), at_(text.data()), end_(text.data() + text.size()), pack_(pack_positions) {}

  Json document() {
    if (end_ - at_ >= 3 && std::string_view(at_, 3) == "\xEF\xBB\xBF") at_ += 3;  // as nlohmann allowed
    Json root = value();
    skip_space();
    if (at_ != end_) fail("unexpected text after the document");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { fail_at(at_, "syntax error: " + why); }
  [[noreturn]] void fail_at(const char* where, const std::string& what) const {
    throw JsonError("JSON: " + what + " at offset " + std::to_string(where - begin_));
  }
  [[noreturn]] void fail_here_or_end(const std::string& why) const {
    fail(at_ == end_ ? "unexpected end of input" : why);
  }

  const char* after_space(const char* p) const {
    while (p < end_ && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t')) ++p;
    return p;
  }
  void skip_space() { at_ = after_space(at_); }

  Json value() {
    skip_space();
    if (at_ == end_) fail("unexpected end of input");
    switch (*at_) {
      case '{': return object();
      case '[': return array();
      case '"': {
        Json v;
        v.type = Json::Type::String;
        v.text = string();
        return v;
      }
      case 't': return literal("true", Json::Type::Bool, true);
      case 'f': return literal("false", Json::Type::Bool, false);
      case 'n': return literal("null", Json::Type::Null, false);
      default:
        if (*at_ != '-' && !is_digit(*at_)) fail("expected a value");
        return number();
    }
  }

  Json literal(std::string_view word, Json::Type type, bool boolean) {
    if (static_cast<std::size_t>(end_ - at_) < word.size() || std::string_view(at_, word.size()) != word)
      fail("invalid literal");
    at_ += word.size();
    Json v;
    v.type = type;
    v.boolean = boolean;
    return v;
  }

  void open() {
    if (depth_ >= kMaxDepth) throw JsonError("JSON: nesting too deep");
    ++depth_;
    ++at_;
    skip_space();
  }

  void close() {
    ++at_;
    --depth_;
  }

  // Just after the opening bracket: whether the container is empty (then closed).
  bool closes_at_once(char bracket) {
    if (at_ == end_ || *at_ != bracket) return false;
    close();
    return true;
  }

  // After an item: whether a ',' follows (another item comes), else the closing bracket (then closed).
  bool another_item(char bracket, const char* expected) {
    skip_space();
    if (at_ < end_ && *at_ == ',') {
      ++at_;
      skip_space();
      return true;
    }
    if (at_ == end_ || *at_ != bracket) fail_here_or_end(expected);
    close();
    return false;
  }

  Json object() {
    open();
    Json v;
    v.type = Json::Type::Object;
    if (closes_at_once('}')) return v;
    do {
      if (at_ == end_ || *at_ != '"') fail_here_or_end("expected a member name");
      std::string key = string();
      skip_space();
      if (at_ == end_ || *at_ != ':') fail_here_or_end("expected ':'");
      ++at_;
      v.fields.insert_or_assign(std::move(key), value());  // a repeated name keeps its last value
    } while (another_item('}', "expected ',' or '}'"));
    return v;
  }

  Json array() {
    open();
    Json v;
    v.type = Json::Type::Array;
    if (closes_at_once(']')) return v;
    do {
      if (!(pack_ && v.items.empty() && at_ < end_ && *at_ == '[' && position(v))) {
        unpack(v);
        v.items.push_back(value());
      }
    } while (another_item(']', "expected ',' or ']'"));
    return v;
  }

  // At '[': reads an array of numbers, each a coordinate, as one more row of `array`'s packed rows if it
  // has their width. Anything else (a non-number, a number the rule refuses, an error, another width)
  // leaves `array` and the position as they were, for value() to read as a tree or refuse.
  bool position(Json& array) {
    if (depth_ >= kMaxDepth) return false;
    const std::size_t start = array.packed.size();
    const char* p = at_ + 1;
    for (;;) {
      p = after_space(p);
      const char* stop = number_end(p);
      if (stop == nullptr) break;
      const char* read = p;
      std::optional<double> d = plain_coordinate(read, stop);
      if (!d || read != stop) {
        std::string why;
        d = coordinate_value(std::string_view(p, static_cast<std::size_t>(stop - p)), why);
        if (!d) break;
      }
      array.packed.push_back(*d);
      p = after_space(stop);
      if (p < end_ && *p == ',') {
        ++p;
        continue;
      }
      const std::size_t width = array.packed.size() - start;
      if (p == end_ || *p != ']' || (array.width != 0 && array.width != width)) break;
      array.width = width;
      at_ = p + 1;
      return true;
    }
    array.packed.resize(start);
    return false;
  }

  // Turns packed rows back into items (an array that mixes positions with anything else), with number
  // texts that read back as the same doubles.
  static void unpack(Json& array) {
    if (!array.is_packed()) return;
    for (std::size_t row = 0; row < array.packed.size(); row += array.width) {
      Json position;
      position.type = Json::Type::Array;
      for (std::size_t k = 0; k < array.width; ++k) {
        Json number;
        number.type = Json::Type::Number;
        number.text = double_text(array.packed[row + k]);
        position.items.push_back(std::move(number));
      }
      array.items.push_back(std::move(position));
    }
    array.packed.clear();
    array.width = 0;
  }

  // The end of the JSON number -?(0|[1-9]D*)(.D+)?([eE][+-]?D+)? at p, or nullptr if there is none.
  const char* number_end(const char* p) const {
    if (p < end_ && *p == '-') ++p;
    if (p < end_ && *p == '0') {
      ++p;
    } else {
      if (p == end_ || !is_digit(*p)) return nullptr;
      while (p < end_ && is_digit(*p)) ++p;
    }
    if (p < end_ && *p == '.') {
      if (++p == end_ || !is_digit(*p)) return nullptr;
      while (p < end_ && is_digit(*p)) ++p;
    }
    if (p < end_ && (*p == 'e' || *p == 'E')) {
      if (++p < end_ && (*p == '+' || *p == '-')) ++p;
      if (p == end_ || !is_digit(*p)) return nullptr;
      while (p < end_ && is_digit(*p)) ++p;
    }
    return p;
  }

  // A number keeps its text; one beyond a double is refused here, as nlohmann did, with the rule's
  // reason (a number too small, or not exactly a double, is refused only where it is read).
  Json number() {
    const char* stop = number_end(at_);
    if (stop == nullptr || (stop < end_ && (is_digit(*stop) || *stop == '.' || *stop == 'e' || *stop == 'E')))
      fail("invalid number");
    const std::string_view text(at_, static_cast<std::size_t>(stop - at_));
    double d;
    if (std::from_chars(at_, stop, d).ec == std::errc::result_out_of_range &&
        std::isinf(std::strtod(std::string(text).c_str(), nullptr))) {
      std::string why;
      coordinate_value(text, why);
      fail_at(at_, why);
    }
    Json v;
    v.type = Json::Type::Number;
    v.text = text;
    at_ = stop;
    return v;
  }

  // At '"': the string's value, its escapes decoded, its bytes checked as UTF-8 (RFC 3629).
  std::string string() {
    std::string out;
    ++at_;
    for (;;) {
      const char* run = at_;
      while (at_ < end_ && *at_ != '"' && *at_ != '\\' && static_cast<unsigned char>(*at_) >= 0x20 &&
             static_cast<unsigned char>(*at_) < 0x80)
        ++at_;
      out.append(run, static_cast<std::size_t>(at_ - run));
      if (at_ == end_) fail("unexpected end of input in a string");
      const unsigned char c = static_cast<unsigned char>(*at_);
      if (c == '"') {
        ++at_;
        return out;
      }
      if (c == '\\') {
        escape(out);
      } else if (c < 0x20) {
        fail("a control character in a string must be escaped");
      } else {
        utf8_sequence(out);
      }
    }
  }

  void escape(std::string& out) {
    const char* start = at_++;
    if (at_ == end_) fail("unexpected end of input in a string");
    switch (*at_++) {
      case '"': out += '"'; return;
      case '\\': out += '\\'; return;
      case '/': out += '/'; return;
      case 'b': out += '\b'; return;
      case 'f': out += '\f'; return;
      case 'n': out += '\n'; return;
      case 'r': out += '\r'; return;
      case 't': out += '\t'; return;
      case 'u': break;
      default: at_ = start; fail("invalid escape");
    }
    std::uint32_t code = hex4(start);
    if (code >= 0xDC00 && code <= 0xDFFF) {
      at_ = start;
      fail("a \\u escape of a low surrogate without a high one");
    }
    if (code >= 0xD800 && code <= 0xDBFF) {
      const char* low_start = at_;
      if (end_ - at_ < 2 || at_[0] != '\\' || at_[1] != 'u') {
        at_ = start;
        fail("a \\u escape of a high surrogate without a low one");
      }
      at_ += 2;
      const std::uint32_t low = hex4(low_start);
      if (low < 0xDC00 || low > 0xDFFF) {
        at_ = start;
        fail("a \\u escape of a high surrogate without a low one");
      }
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    }
    append_utf8(out, code);
  }

  // The four hex digits at at_, of the \u escape that starts at `start`.
  std::uint32_t hex4(const char* start) {
    std::uint32_t code = 0;
    for (int k = 0; k < 4; ++k, ++at_) {
      const char c = at_ < end_ ? *at_ : '\0';
      const int digit = is_digit(c) ? c - '0' : (c | 0x20) >= 'a' && (c | 0x20) <= 'f' ? (c | 0x20) - 'a' + 10 : -1;
      if (digit < 0) {
        at_ = start;
        fail("a \\u escape needs four hex digits");
      }
      code = code << 4 | static_cast<std::uint32_t>(digit);
    }
    return code;
  }

  static void append_utf8(std::string& out, std::uint32_t code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | code >> 6);
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | code >> 12);
      out += static_cast<char>(0x80 | (code >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | code >> 18);
      out += static_cast<char>(0x80 | (code >> 12 & 0x3F));
      out += static_cast<char>(0x80 | (code >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  // A multi-byte UTF-8 character at at_ (its lead byte is >= 0x80): RFC 3629's table, so no overlong
  // form, no surrogate, nothing above U+10FFFF.
  void utf8_sequence(std::string& out) {
    const unsigned char lead = static_cast<unsigned char>(*at_);
    unsigned char low = 0x80, high = 0xBF;
    int tail;
    if (lead >= 0xC2 && lead <= 0xDF) {
      tail = 1;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      tail = 2;
      if (lead == 0xE0) low = 0xA0;
      if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      tail = 3;
      if (lead == 0xF0) low = 0x90;
      if (lead == 0xF4) high = 0x8F;
    } else {
      fail("invalid UTF-8 in a string");
    }
    const char* start = at_++;
    for (int k = 0; k < tail; ++k, ++at_, low = 0x80, high = 0xBF) {
      const unsigned char c = at_ < end_ ? static_cast<unsigned char>(*at_) : 0;
      if (c < low || c > high) fail("invalid UTF-8 in a string");
    }
    out.append(start, static_cast<std::size_t>(at_ - start));
  }

  const char* begin_;
  const char* at_;
  const char* end_;
  bool pack_;
  std::size_t depth_ = 0;
};

}  // namespace

const Json* Json::get(const std::string& key) const {
  const auto it = fields.find(key);
  return it == fields.end() ? nullptr : &it->second;
}

double Json::number() const {
  if (type != Type::Number) throw JsonError("expected a number");
  std::string why;
  const std::optional<double> d = coordinate_value(text, why);
  if (!d) throw JsonError(why);
  if (!std::isfinite(*d)) throw JsonError(quoted_input(text) + " is not a finite number");
  return *d;
}

Json parse_json(std::string_view text, bool pack_positions) { return Parser(text, pack_positions).document(); }

std::string json_quote(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace pd
