// The JSON reader (for GeoJSON input, fixtures and sweep files) and the string escaping the writers use,
// both through nlohmann/json (json.cpp). Numbers keep their source text so that coordinates parse to
// exactly the double they name.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
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

  bool is_array() const { return type == Type::Array; }
  bool is_object() const { return type == Type::Object; }
  bool is_number() const { return type == Type::Number; }
  const Json* get(const std::string& key) const;  // member or nullptr
  double number() const;                           // throws JsonError unless a finite number
};

// Parses a whole document; throws JsonError with the offset of the problem. Nesting is limited so that
// hostile input cannot exhaust the stack.
Json parse_json(const std::string& text);

std::string json_quote(const std::string& s);

}  // namespace pd
