// The reader and the escaping go through nlohmann/json (Debian's nlohmann-json3-dev), whose parser
// keeps to RFC 8259's grammar. Its SAX interface hands each floating-point number over with its source
// text, which Json keeps so that a coordinate parses to exactly the double it names; integers arrive
// exact, as 64-bit values.
#include "core/json.h"

#include "core/coordinate.h"
#include "core/geometry.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace pd {
namespace {

constexpr std::size_t kMaxDepth = 256;
constexpr int kNumberOverflow = 406;  // nlohmann's out_of_range.406: a number beyond a double

// Builds a Json tree from nlohmann's SAX events. Containers under construction are kept on a stack;
// nesting is limited so that hostile input cannot exhaust memory or, later, the stack of a recursive
// reader.
class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit TreeBuilder(bool pack_positions) : pack_(pack_positions) {}
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
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override {
    std::string why;
    const bool number_out_of_range = e.id == kNumberOverflow && !coordinate_value(token, why);
    failure_ = "JSON: " + (number_out_of_range ? why : reason_of(e)) + " at offset " + std::to_string(position);
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
      add_to_array(open_.back(), std::move(v));
    } else {
      open_.back().fields[keys_.back()] = std::move(v);
    }
    return true;
  }
  // A position joins its array's packed rows while the array holds only positions of one width.
  void add_to_array(Json& array, Json v) {
    if (pack_ && array.items.empty() && (array.packed.empty() || array.width == v.items.size()) &&
        pack_row(v, array.packed)) {
      array.width = v.items.size();
      return;
    }
    unpack(array);
    array.items.push_back(std::move(v));
  }
  // Appends v's values to `rows` if v is an array of valid coordinates; leaves `rows` as it was if not.
  static bool pack_row(const Json& v, std::vector<double>& rows) {
    if (!v.is_array() || v.is_packed() || v.items.empty()) return false;
    const std::size_t start = rows.size();
    std::string why;
    for (const Json& item : v.items) {
      const std::optional<double> d = item.is_number() ? coordinate_value(item.text, why) : std::nullopt;
      if (!d || !std::isfinite(*d)) {
        rows.resize(start);
        return false;
      }
      rows.push_back(*d);
    }
    return true;
  }
  // Turns packed rows back into items (an array that mixes positions with anything else).
  static void unpack(Json& array) {
    if (!array.is_packed()) return;
    for (std::size_t row = 0; row < array.packed.size(); row += array.width) {
      Json position;
      position.type = Json::Type::Array;
      for (std::size_t k = 0; k < array.width; ++k) position.items.push_back(number(double_text(array.packed[row + k])));
      array.items.push_back(std::move(position));
    }
    array.packed.clear();
    array.width = 0;
  }

  std::vector<Json> open_;
  std::vector<std::string> keys_;  // per open container: the member name being read
  Json root_;
  std::string failure_;
  bool pack_;
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

Json parse_json(std::string_view text, bool pack_positions) {
  TreeBuilder builder(pack_positions);
  if (!nlohmann::json::sax_parse(text.data(), text.data() + text.size(), &builder)) throw JsonError(builder.failure());
  return builder.result();
}

std::string json_quote(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace pd
