// The reader and the escaping go through nlohmann/json (Debian's nlohmann-json3-dev), whose parser
// keeps to RFC 8259's grammar. Its SAX interface hands each floating-point number over with its source
// text, which Json keeps so that a coordinate parses to exactly the double it names; integers arrive
// exact, as 64-bit values.
#include "core/json.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>

namespace pd {
namespace {

constexpr std::size_t kMaxDepth = 256;

// Builds a Json tree from nlohmann's SAX events. Containers under construction are kept on a stack;
// nesting is limited so that hostile input cannot exhaust memory or, later, the stack of a recursive
// reader.
class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  Json result() { return std::move(root_); }
  const std::string& failure() const { return failure_; }

  bool null() override { return add(Json{}); }
  bool boolean(bool value) override {
    Json v;
    v.type = Json::Type::Bool;
    v.boolean = value;
    return add(std::move(v));
  }
  bool number_integer(number_integer_t value) override { return add(number(std::to_string(value))); }
  bool number_unsigned(number_unsigned_t value) override { return add(number(std::to_string(value))); }
  bool number_float(number_float_t, const string_t& text) override { return add(number(text)); }
  bool string(string_t& value) override {
    Json v;
    v.type = Json::Type::String;
    v.text = std::move(value);
    return add(std::move(v));
  }
  bool binary(binary_t&) override { return false; }
  bool start_object(std::size_t) override { return open(Json::Type::Object); }
  bool key(string_t& name) override {
    keys_.back() = std::move(name);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json::Type::Array); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    failure_ = "JSON: " + reason_of(e) + " at offset " + std::to_string(position);
    return false;
  }

 private:
  static Json number(std::string text) {
    Json v;
    v.type = Json::Type::Number;
    v.text = std::move(text);
    return v;
  }
  // nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1, column 3: "
  // prefix, whose position the offset already gives.
  static std::string reason_of(const nlohmann::detail::exception& e) {
    const std::string what = e.what();
    const std::size_t colon = what.find(": ");
    return colon == std::string::npos ? what : what.substr(colon + 2);
  }
  bool open(Json::Type type) {
    if (open_.size() >= kMaxDepth) {
      failure_ = "JSON: nesting too deep";
      return false;
    }
    Json v;
    v.type = type;
    open_.push_back(std::move(v));
    keys_.emplace_back();
    return true;
  }
  bool close() {
    Json done = std::move(open_.back());
    open_.pop_back();
    keys_.pop_back();
    return add(std::move(done));
  }
  bool add(Json v) {
    if (open_.empty()) {
      root_ = std::move(v);
    } else if (open_.back().is_array()) {
      open_.back().items.push_back(std::move(v));
    } else {
      open_.back().fields[keys_.back()] = std::move(v);
    }
    return true;
  }

  std::vector<Json> open_;
  std::vector<std::string> keys_;  // per open container: the member name being read
  Json root_;
  std::string failure_;
};

}  // namespace

const Json* Json::get(const std::string& key) const {
  const auto it = fields.find(key);
  return it == fields.end() ? nullptr : &it->second;
}

double Json::number() const {
  if (type != Type::Number) throw JsonError("expected a number");
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) throw JsonError("'" + text + "' is not a number");
  if (!std::isfinite(d)) throw JsonError("'" + text + "' is not a finite number");
  return d;
}

Json parse_json(const std::string& text) {
  TreeBuilder builder;
  if (!nlohmann::json::sax_parse(text, &builder)) throw JsonError(builder.failure());
  return builder.result();
}

std::string json_quote(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace pd
