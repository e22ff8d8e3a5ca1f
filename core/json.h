// The JSON reader (for GeoJSON input, fixtures and sweep files; json.cpp's own parser) and the string
// escaping the writers use (through nlohmann/json). Numbers keep their source text, and number() reads
// it by the rule of core/coordinate.h, so that no number is read in part or silently changed.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pd {

class JsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Json {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  bool boolean = false;
  std::string text;                   // a number's source text, or a string's value
  std::vector<Json> items;            // array elements
  std::map<std::string, Json> fields; // object members
  // Packed positions (parse_json with pack_positions): an array whose elements are arrays of `width`
  // numbers, each a valid coordinate, holds their values row after row in `packed`, not in `items`.
  std::vector<double> packed;
  std::size_t width = 0;

  bool is_array() const { return type == Type::Array; }
  bool is_object() const { return type == Type::Object; }
  bool is_number() const { return type == Type::Number; }
  bool is_packed() const { return width != 0; }
  const Json* get(const std::string& key) const;  // member or nullptr
  double number() const;  // throws JsonError unless a finite number by core/coordinate.h's rule
};

// Parses a whole document (RFC 8259; a leading UTF-8 byte order mark is skipped); throws JsonError
// with the byte offset of the problem. Nesting is limited so that hostile input cannot exhaust the
// stack. With pack_positions, arrays of positions are packed (see Json::packed), so that a GeoJSON
// polygon costs about its coordinates' doubles, not a tree node each.
Json parse_json(std::string_view text, bool pack_positions = false);

std::string json_quote(const std::string& s);
inline const char* json_bool(bool b) { return b ? "true" : "false"; }

}  // namespace pd
