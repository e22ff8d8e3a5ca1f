// The readers of core/io.h: plain text, WKT and GeoJSON (with earcut's ring arrays). Each keeps to its
// format's grammar and refuses anything else with one reason; every coordinate is read by the rule of
// core/coordinate.h. A reader returns every part with its rings as written; Polygon::make_with_holes
// and make_parts do the geometric checks.
#include "core/coordinate.h"
#include "core/io.h"
#include "core/json.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string_view>

namespace pd {
namespace {

[[noreturn]] void bad(const std::string& why) { throw PolygonError(why); }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// `where` names the place for the message ("WKT: ", "line 3: "); it is only called on a failure.
template <typename Where>
double coordinate(std::string_view text, const Where& where) {
  std::string why;
  const std::optional<double> d = coordinate_value(text, why);
  if (!d) bad(where() + why);
  return *d;
}

std::string in_wkt() { return "WKT: "; }
std::string in_geojson() { return "GeoJSON: "; }

// A polygon of one part, or of one ring, moved into place (a braced list would copy every vertex).
std::vector<Rings> one_part(Rings rings) {
  std::vector<Rings> parts;
  parts.push_back(std::move(rings));
  return parts;
}
Rings one_ring(Ring ring) {
  Rings rings;
  rings.push_back(std::move(ring));
  return rings;
}

// A file must hold a polygon: at least one part, each with its outer ring.
std::vector<Rings> not_empty(std::vector<Rings> parts) {
  if (parts.empty()) bad("the polygon is empty");
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (parts[k].empty()) bad(parts.size() == 1 ? "the polygon is empty" : "part " + std::to_string(k) + " is empty");
  return parts;
}

bool starts_with_word(std::string_view text, std::string_view word) {
  if (text.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != word[i]) return false;
  return true;
}

// ---- plain text: `x y` per line, '#' comments, an optional count line before the first vertex.

// What separates the fields of a line.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

// The fields of a line into `fields` (reused from line to line, so that a million lines make no
// million vectors).
void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || is_blank(line[i])) {
      if (i > start) fields.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
}

// A line at `at` that is exactly `x y` in plain numbers, read in one pass: the vertex, with `at` moved
// past the line's end; nothing for any other line (a comment, a count, an error, a number in another
// form), which the full reading takes.
std::optional<Point> plain_vertex(const char*& at, const char* end) {
  const char* p = at;
  double xy[2];
  for (double& v : xy) {
    while (p < end && is_blank(*p)) ++p;
    const std::optional<double> d = plain_coordinate(p, end);
    if (!d || (p < end && !is_blank(*p) && *p != '\n')) return std::nullopt;
    v = *d;
  }
  while (p < end && is_blank(*p)) ++p;
  if (p < end && *p != '\n') return std::nullopt;
  at = p < end ? p + 1 : p;
  return Point(xy[0], xy[1]);
}

// The count line may count the repeated closing vertex or not.
void check_count(std::size_t count, const Ring& ring) {
  const bool closed = ring.size() >= 2 && ring.front() == ring.back();
  if (count == ring.size() || (closed && count + 1 == ring.size())) return;
  bad("the count line says " + std::to_string(count) + " vertices but " + std::to_string(ring.size()) + " follow");
}

Ring parse_txt(std::string_view content) {
  Ring ring;
  ring.reserve(static_cast<std::size_t>(std::count(content.begin(), content.end(), '\n')) + 1);
  std::optional<std::size_t> count;
  std::vector<std::string_view> fields;
  std::size_t line_no = 0;
  while (!content.empty()) {
    ++line_no;
    const char* at = content.data();
    if (const std::optional<Point> vertex = plain_vertex(at, content.data() + content.size())) {
      ring.push_back(*vertex);
      content.remove_prefix(static_cast<std::size_t>(at - content.data()));
      continue;
    }
    const std::size_t end = std::min(content.find('\n'), content.size());
    std::string_view line = content.substr(0, end);
    content.remove_prefix(std::min(end + 1, content.size()));
    line = line.substr(0, std::min(line.find('#'), line.size()));
    split_fields(line, fields);
    if (fields.empty()) continue;
    const auto where = [line_no] { return "line " + std::to_string(line_no) + ": "; };
    if (fields.size() == 1 && ring.empty() && !count) {
      const double c = coordinate(fields[0], where);
      if (!(c >= 0 && c <= 1e9 && c == static_cast<double>(static_cast<std::size_t>(c))))
        bad(where() + "a count line must hold a vertex count");
      count = static_cast<std::size_t>(c);
      continue;
    }
    if (fields.size() != 2) {
      for (const auto& field : fields) coordinate(field, where);  // a word is named as such, not counted
      bad(where() + "expected 'x y', found " + std::to_string(fields.size()) + " numbers");
    }
    const double x = coordinate(fields[0], where);
    ring.emplace_back(x, coordinate(fields[1], where));
  }
  if (ring.empty()) bad("the input holds no vertices");
  if (count) check_count(*count, ring);
  return ring;
}

// ---- WKT (OGC 06-103r4, 7.2): POLYGON | MULTIPOLYGON, Z | M | ZM, EMPTY, rings of points; EWKT's
// `SRID=N;` prefix. Z and M values are read (by the coordinate rule) and dropped.

class WktReader {
 public:
  explicit WktReader(std::string_view text) : text_(text) {}

  std::vector<Rings> read() {
    skip_srid();
    const std::string tag = upper(word());
    if (tag != "POLYGON" && tag != "MULTIPOLYGON") bad("WKT: " + quoted_input(tag) + " is not POLYGON or MULTIPOLYGON");
    std::vector<Rings> parts;
    std::string next = peek_word();
    if (next == "Z" || next == "M" || next == "ZM") {
      dimension_ = next == "ZM" ? 4 : 3;
      word();
      next = peek_word();
    }
    if (next == "EMPTY") {
      word();
    } else if (tag == "POLYGON") {
      parts.push_back(polygon_text());
    } else {
      for (expect('('); parts.push_back(polygon_text()), next_is(',');) {
      }
      expect(')');
    }
    skip_space();
    if (at_ < text_.size()) fail("unexpected text after the " + lower(tag));
    return parts;
  }

 private:
  Rings polygon_text() {
    Rings rings;
    for (expect('('); rings.push_back(ring_text()), next_is(',');) {
    }
    expect(')');
    return rings;
  }
  Ring ring_text() {
    Ring ring;
    for (expect('('); ring.push_back(point()), next_is(',');) {
    }
    expect(')');
    return ring;
  }
  // x y, then the Z and M values the tag (or, untagged, the first point) says each point has.
  Point point() {
    const double x = number(), y = number();
    std::size_t extra = 0;
    for (; extra < 2 && (dimension_ == 0 || extra + 2 < dimension_) && starts_number(); ++extra) number();
    if (dimension_ == 0) dimension_ = 2 + extra;
    if (extra + 2 != dimension_) fail("expected " + std::to_string(dimension_) + " coordinates in each point");
    return Point(x, y);
  }
  bool starts_number() {
    skip_space();
    return at_ < text_.size() && text_[at_] != ',' && text_[at_] != ')' && text_[at_] != '(';
  }
  void skip_srid() {
    skip_space();
    if (!starts_with_word(text_.substr(at_), "srid=")) return;
    const std::size_t semicolon = text_.find(';', at_);
    if (semicolon == std::string_view::npos) fail("expected ';' after SRID=");
    at_ = semicolon + 1;
  }
  double number() {
    skip_space();
    const char* end = text_.data() + text_.size();
    const char* at = text_.data() + at_;
    if (const std::optional<double> d = plain_coordinate(at, end); d && (at == end || ends_number(*at))) {
      at_ = static_cast<std::size_t>(at - text_.data());
      return *d;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && !ends_number(text_[at_])) ++at_;
    if (at_ == start) fail("expected a coordinate");
    return coordinate(text_.substr(start, at_ - start), in_wkt);
  }
  static bool ends_number(char c) { return is_space(c) || c == ',' || c == '(' || c == ')'; }
  std::string word() {
    skip_space();
    const std::size_t start = at_;
    while (at_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[at_]))) ++at_;
    return std::string(text_.substr(start, at_ - start));
  }
  std::string peek_word() {
    const std::size_t saved = at_;
    const std::string w = upper(word());
    at_ = saved;
    return w;
  }
  void expect(char c) {
    skip_space();
    if (at_ >= text_.size() || text_[at_] != c) fail(std::string("expected '") + c + "'");
    ++at_;
  }
  bool next_is(char c) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == c) return ++at_, true;
    return false;
  }
  void skip_space() {
    while (at_ < text_.size() && is_space(text_[at_])) ++at_;
  }
  [[noreturn]] void fail(const std::string& what) {
    const std::string found = at_ < text_.size() ? quoted_input(text_.substr(at_, 20), 20) : "the end";
    bad("WKT: " + what + " at offset " + std::to_string(at_) + ", found " + found);
  }
  static std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  }
  static std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t dimension_ = 0;  // coordinates per point: 2, 3 or 4; 0 until known
};

// ---- GeoJSON (RFC 7946): Polygon, MultiPolygon, a Feature of one, a FeatureCollection of Features;
// earcut's fixtures: a bare array of rings, or one ring. A position's altitude (and anything after it)
// is dropped.

Ring ring_of(const Json& ring) {
  if (!ring.is_array()) bad("GeoJSON: a ring must be an array of positions");
  Ring out;
  if (ring.is_packed()) {
    if (ring.width < 2) bad("GeoJSON: a position must be [x, y]");
    out.reserve(ring.packed.size() / ring.width);
    for (std::size_t k = 0; k < ring.packed.size(); k += ring.width) out.emplace_back(ring.packed[k], ring.packed[k + 1]);
    return out;
  }
  for (const Json& pos : ring.items) {
    if (!pos.is_array() || pos.items.size() < 2) bad("GeoJSON: a position must be [x, y]");
    for (const Json& c : pos.items)
      if (!c.is_number()) bad("GeoJSON: a coordinate is not a number");
    for (std::size_t k = 2; k < pos.items.size(); ++k) coordinate(pos.items[k].text, in_geojson);  // read, dropped
    const double x = coordinate(pos.items[0].text, in_geojson);
    out.emplace_back(x, coordinate(pos.items[1].text, in_geojson));
  }
  return out;
}

Rings rings_of(const Json& rings) {
  if (!rings.is_array() || rings.is_packed()) bad("GeoJSON: a polygon's coordinates must be an array of rings");
  Rings out;
  for (const Json& ring : rings.items) out.push_back(ring_of(ring));
  return out;
}

const std::string& type_of(const Json& doc) {
  if (!doc.is_object()) bad("GeoJSON: expected an object");
  const Json* type = doc.get("type");
  if (!type || type->type != Json::Type::String) bad("GeoJSON: missing \"type\"");
  return type->text;
}

const Json& member(const Json& doc, const char* name, const std::string& type) {
  const Json* m = doc.get(name);
  if (!m) bad("GeoJSON: the " + type + " has no \"" + name + "\"");
  return *m;
}

std::vector<Rings> geometry_parts(const Json& geometry) {
  const std::string& type = type_of(geometry);
  const Json& coordinates = member(geometry, "coordinates", type);
  if (type == "Polygon") return one_part(rings_of(coordinates));
  if (type == "MultiPolygon") {
    if (!coordinates.is_array() || coordinates.is_packed()) bad("GeoJSON: a MultiPolygon's coordinates must be an array of polygons");
    std::vector<Rings> parts;
    for (const Json& polygon : coordinates.items) parts.push_back(rings_of(polygon));
    return parts;
  }
  bad("GeoJSON: a " + quoted_input(type, 30) + " is not a Polygon or MultiPolygon");
}

std::vector<Rings> feature_parts(const Json& feature) {
  const Json& geometry = member(feature, "geometry", "Feature");
  if (geometry.type == Json::Type::Null) bad("GeoJSON: the Feature has no geometry");
  const std::string& type = type_of(geometry);
  if (type == "Feature" || type == "FeatureCollection") bad("GeoJSON: a Feature's geometry cannot be a " + type);
  return geometry_parts(geometry);
}

std::vector<Rings> geojson_parts(const Json& doc) {
  if (doc.is_array()) {  // earcut's fixtures: an array of rings, or one ring
    if (doc.is_packed()) return one_part(one_ring(ring_of(doc)));
    if (!doc.items.empty() && doc.items[0].is_array() && (doc.items[0].is_packed() || doc.items[0].items.empty() ||
                                                         doc.items[0].items[0].is_array()))
      return one_part(rings_of(doc));
    return one_part(one_ring(ring_of(doc)));
  }
  const std::string& type = type_of(doc);
  if (type == "Feature") return feature_parts(doc);
  if (type == "FeatureCollection") {
    const Json& features = member(doc, "features", type);
    if (!features.is_array() || features.items.size() != 1)
      bad("GeoJSON: a FeatureCollection must hold exactly one feature");
    if (type_of(features.items[0]) != "Feature") bad("GeoJSON: a FeatureCollection's features must be Features");
    return feature_parts(features.items[0]);
  }
  return geometry_parts(doc);
}

std::string_view without_bom(std::string_view content) {
  return content.substr(0, 3) == "\xEF\xBB\xBF" ? content.substr(3) : content;
}

// Reads a stream whole, refusing a NUL byte as soon as it arrives (binary data, or /dev/zero, which
// would otherwise be read until memory runs out).
std::string read_text(std::FILE* in, const std::string& name) {
  std::string text;
  char buffer[1 << 16];
  for (std::size_t k; (k = std::fread(buffer, 1, sizeof buffer, in)) > 0;) {
    if (const void* nul = std::memchr(buffer, '\0', k))
      bad(name + " holds a NUL byte at offset " +
          std::to_string(text.size() + static_cast<std::size_t>(static_cast<const char*>(nul) - buffer)) +
          "; polygon files are text");
    text.append(buffer, k);
  }
  if (std::ferror(in)) bad("cannot read " + name + ": " + std::strerror(errno));
  return text;
}

}  // namespace

std::vector<Rings> parse_parts(const std::string& input) {
  const std::string_view content = without_bom(input);
  const std::string_view start = trim(content);
  if (start.empty()) bad("the input is empty");
  if (start[0] == '{' || start[0] == '[') {
    try {
      return not_empty(geojson_parts(parse_json(content, true)));
    } catch (const JsonError& e) {
      bad(e.what());
    }
  }
  if (starts_with_word(start, "polygon") || starts_with_word(start, "multipolygon") || starts_with_word(start, "srid="))
    return not_empty(WktReader(start).read());
  return one_part(one_ring(parse_txt(content)));
}

std::vector<Rings> read_parts_file(const std::string& path) {
  if (path == "-") return parse_parts(read_text(stdin, "the standard input"));
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    bad(path + " is a directory; --input takes one polygon file");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!in) bad("cannot read " + path + ": " + std::strerror(errno));
  return parse_parts(read_text(in.get(), path));
}

}  // namespace pd
