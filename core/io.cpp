#include "core/io.h"

#include "core/json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace pd {
namespace {

[[noreturn]] void bad(const std::string& why) { throw PolygonError(why); }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// A coordinate token: any text strtod reads completely ("nan" and "inf" included, so that the polygon
// check can name them as not finite).
bool parse_number(const std::string& token, double& out) {
  if (token.empty()) return false;
  char* end = nullptr;
  out = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

std::vector<std::string> split_numbers(const std::string& line) {
  std::vector<std::string> tokens;
  std::string cur;
  for (const char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      if (!cur.empty()) tokens.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) tokens.push_back(cur);
  return tokens;
}

std::vector<Point> parse_txt(const std::string& content) {
  std::istringstream in(content);
  std::string line;
  std::vector<Point> ring;
  std::optional<std::size_t> count;
  for (std::size_t line_no = 1; std::getline(in, line); ++line_no) {
    line = line.substr(0, line.find('#'));
    const auto tokens = split_numbers(line);
    if (tokens.empty()) continue;
    std::vector<double> values;
    for (const auto& t : tokens) {
      double v;
      if (!parse_number(t, v)) bad("line " + std::to_string(line_no) + ": '" + t.substr(0, 40) + "' is not a number");
      values.push_back(v);
    }
    if (values.size() == 1 && ring.empty() && !count) {
      if (values[0] < 0 || values[0] != std::floor(values[0]) || values[0] > 1e9)
        bad("line " + std::to_string(line_no) + ": a count line must hold a vertex count");
      count = static_cast<std::size_t>(values[0]);
      continue;
    }
    if (values.size() != 2)
      bad("line " + std::to_string(line_no) + ": expected 'x y', found " + std::to_string(values.size()) +
          " numbers");
    ring.emplace_back(values[0], values[1]);
  }
  if (ring.empty()) bad("the input holds no vertices");
  if (count && *count != ring.size())
    bad("the count line says " + std::to_string(*count) + " vertices but " + std::to_string(ring.size()) +
        " follow");
  return ring;
}

// WKT: POLYGON ((x y, x y, ...)[, (hole)...]) or POLYGON EMPTY.
std::vector<Point> parse_wkt(const std::string& content) {
  const std::string text = trim(content);
  const std::string head = lower(text.substr(0, 12));
  if (head.rfind("multipolygon", 0) == 0) bad("multipolygons are not supported");
  std::size_t i = 7;  // after "polygon"
  const std::string rest = lower(trim(text.substr(i)));
  if (rest.rfind("empty", 0) == 0) bad("the polygon is empty");
  if (rest.rfind("z", 0) == 0 || rest.rfind("m", 0) == 0) bad("WKT with Z or M coordinates is not supported");
  const auto open = text.find('(', i);
  if (open == std::string::npos) bad("WKT: expected '(' after POLYGON");
  const auto inner = text.find('(', open + 1);
  if (inner == std::string::npos) bad("WKT: expected '((' after POLYGON");
  if (trim(text.substr(open + 1, inner - open - 1)) != "") bad("WKT: unexpected text between '(' and '('");
  const auto close = text.find(')', inner);
  if (close == std::string::npos) bad("WKT: missing ')'");
  const std::string after = trim(text.substr(close + 1));
  if (!after.empty() && after[0] == ',') bad("holes are not supported");
  if (after != ")") bad("WKT: unexpected text after the ring");
  std::vector<Point> ring;
  std::istringstream points(text.substr(inner + 1, close - inner - 1));
  std::string item;
  while (std::getline(points, item, ',')) {
    std::istringstream xy(item);
    std::vector<std::string> tokens;
    for (std::string t; xy >> t;) tokens.push_back(t);
    double x, y;
    if (tokens.size() != 2 || !parse_number(tokens[0], x) || !parse_number(tokens[1], y))
      bad("WKT: '" + trim(item).substr(0, 40) + "' is not a point 'x y'");
    ring.emplace_back(x, y);
  }
  return ring;
}

std::vector<Point> ring_of(const Json& ring) {
  if (!ring.is_array()) bad("GeoJSON: a ring must be an array of positions");
  std::vector<Point> out;
  for (const Json& pos : ring.items) {
    if (!pos.is_array() || pos.items.size() < 2) bad("GeoJSON: a position must be [x, y]");
    if (pos.items.size() > 2) bad("GeoJSON: positions with more than 2 coordinates are not supported");
    if (!pos.items[0].is_number() || !pos.items[1].is_number()) bad("GeoJSON: a coordinate is not a number");
    out.emplace_back(std::strtod(pos.items[0].text.c_str(), nullptr), std::strtod(pos.items[1].text.c_str(), nullptr));
  }
  return out;
}

std::vector<Point> outer_ring(const Json& rings) {
  if (!rings.is_array()) bad("GeoJSON: coordinates must be an array of rings");
  if (rings.items.empty()) bad("the polygon is empty");
  if (rings.items.size() > 1) bad("holes are not supported");
  return ring_of(rings.items[0]);
}

std::vector<Point> from_geometry(const Json& doc) {
  if (doc.is_array()) {  // earcut's fixtures: an array of rings, or one ring
    if (!doc.items.empty() && doc.items[0].is_array() && !doc.items[0].items.empty() &&
        doc.items[0].items[0].is_array())
      return outer_ring(doc);
    return ring_of(doc);
  }
  if (!doc.is_object()) bad("GeoJSON: expected an object");
  const Json* type = doc.get("type");
  if (!type || type->type != Json::Type::String) bad("GeoJSON: missing \"type\"");
  if (type->text == "Feature") {
    const Json* g = doc.get("geometry");
    if (!g || !g->is_object()) bad("GeoJSON: the Feature has no geometry");
    return from_geometry(*g);
  }
  if (type->text == "FeatureCollection") {
    const Json* f = doc.get("features");
    if (!f || !f->is_array() || f->items.size() != 1) bad("GeoJSON: a FeatureCollection must hold exactly one feature");
    return from_geometry(f->items[0]);
  }
  if (type->text == "MultiPolygon") bad("multipolygons are not supported");
  if (type->text != "Polygon") bad("GeoJSON: a " + type->text.substr(0, 30) + " is not a Polygon");
  const Json* coords = doc.get("coordinates");
  if (!coords) bad("GeoJSON: the Polygon has no coordinates");
  return outer_ring(*coords);
}

}  // namespace

std::vector<Point> parse_polygon(const std::string& content) {
  const std::string start = lower(trim(content).substr(0, 12));
  if (start.empty()) bad("the input is empty");
  if (start[0] == '{' || start[0] == '[') {
    try {
      return from_geometry(parse_json(content));
    } catch (const JsonError& e) {
      bad(e.what());
    }
  }
  if (start.rfind("polygon", 0) == 0 || start.rfind("multipolygon", 0) == 0) return parse_wkt(content);
  return parse_txt(content);
}

std::vector<Point> read_polygon_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_polygon(text.str());
}

Format parse_format(const std::string& name) {
  if (name == "txt") return Format::Txt;
  if (name == "wkt") return Format::Wkt;
  if (name == "geojson") return Format::GeoJson;
  throw std::invalid_argument("unknown format '" + name + "'; formats: txt, wkt, geojson");
}

std::string format_polygon(const std::vector<Point>& ring, Format f) {
  std::string out;
  auto xy = [](const Point& p, const char* sep) { return double_text(p.x()) + sep + double_text(p.y()); };
  switch (f) {
    case Format::Txt:
      out = std::to_string(ring.size()) + "\n";
      for (const Point& p : ring) out += xy(p, " ") + "\n";
      return out;
    case Format::Wkt:
      out = "POLYGON ((";
      for (const Point& p : ring) out += xy(p, " ") + ", ";
      return out + xy(ring.front(), " ") + "))\n";
    case Format::GeoJson:
      out = "{\"type\": \"Polygon\", \"coordinates\": [[";
      for (const Point& p : ring) out += "[" + xy(p, ", ") + "], ";
      return out + "[" + xy(ring.front(), ", ") + "]]]}\n";
  }
  return out;
}

std::string run_json(const RunReport& r) {
  const Polygon& p = *r.polygon;
  const std::size_t n = p.size();
  auto file_index = [&](VertexId v) { return v < n ? static_cast<VertexId>(p.input_index(v)) : v; };
  std::vector<const Point*> in_file_order(n);
  for (std::size_t i = 0; i < n; ++i) in_file_order[p.input_index(i)] = &p[i];
  auto coord = [](const Rational& v) {
    const std::string t = rational_text(v);
    return t.find('/') == std::string::npos ? t : "\"" + t + "\"";
  };
  std::string out = "{\"algorithm\": " + json_quote(r.algorithm) + ", \"n\": " + std::to_string(n) +
                    ", \"reflex\": " + std::to_string(p.reflex_count()) + ", \"points\": [";
  for (std::size_t i = 0; i < n; ++i)
    out += (i ? ", [" : "[") + double_text(in_file_order[i]->x()) + ", " + double_text(in_file_order[i]->y()) + "]";
  for (const SteinerPoint& s : r.decomposition->steiner)
    out += ", [" + coord(s.point.x()) + ", " + coord(s.point.y()) + "]";
  out += "], \"pieces\": [";
  for (std::size_t k = 0; k < r.pieces->size(); ++k) {
    out += k ? ", [" : "[";
    const Piece& piece = (*r.pieces)[k];
    for (std::size_t i = 0; i < piece.size(); ++i) out += (i ? ", " : "") + std::to_string(file_index(piece[i]));
    out += "]";
  }
  out += "], \"piece_count\": " + std::to_string(r.pieces->size()) +
         ", \"steiner_count\": " + std::to_string(r.decomposition->steiner.size());
  if (r.valid) out += std::string(", \"valid\": ") + (*r.valid ? "true" : "false");
  out += ", \"seconds\": " + double_text(r.seconds) + ", \"counters\": {";
  bool first = true;
  for (const auto& [name, value] : *r.counters) {
    out += (first ? "" : ", ") + json_quote(name) + ": " + std::to_string(value);
    first = false;
  }
  return out + "}}\n";
}

namespace {

// Distinct, evenly spread colours: hues stepped by the golden angle.
std::string piece_colour(std::size_t k) {
  const double hue = std::fmod(static_cast<double>(k) * 137.50776405, 360.0);
  std::ostringstream s;
  s << "hsl(" << static_cast<int>(hue) << ",65%," << (k % 2 ? 72 : 62) << "%)";
  return s.str();
}

}  // namespace

std::string run_svg(const Polygon& p, const Decomposition& d, const std::vector<Piece>& pieces,
                    const std::string& title) {
  const std::vector<QPoint> exact = exact_points(p, d);
  std::vector<std::pair<double, double>> pts;
  for (const QPoint& q : exact) pts.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  double x0 = pts[0].first, x1 = x0, y0 = pts[0].second, y1 = y0;
  for (const auto& [x, y] : pts) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  const double size = 800, margin = 20, span = std::max({x1 - x0, y1 - y0, 1e-300});
  const double scale = (size - 2 * margin) / span;
  const double width = (x1 - x0) * scale + 2 * margin, height = (y1 - y0) * scale + 2 * margin + 24;
  auto sx = [&](double x) { return margin + (x - x0) * scale; };
  auto sy = [&](double y) { return 24 + margin + (y1 - y) * scale; };  // SVG's y axis points down
  auto path = [&](auto begin, auto end) {
    std::ostringstream s;
    s.precision(10);
    for (auto it = begin; it != end; ++it) s << (it == begin ? "M" : "L") << sx(pts[*it].first) << "," << sy(pts[*it].second);
    s << "Z";
    return s.str();
  };
  const double mark = std::max(1.5, std::min(5.0, 400.0 / std::sqrt(static_cast<double>(pts.size()))));
  std::ostringstream svg;
  svg.precision(10);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << margin << "\" y=\"18\" font-family=\"sans-serif\" font-size=\"14\">" << title << "</text>\n";
  for (std::size_t k = 0; k < pieces.size(); ++k)
    svg << "<path d=\"" << path(pieces[k].begin(), pieces[k].end()) << "\" fill=\"" << piece_colour(k)
        << "\" stroke=\"#333\" stroke-width=\"0.6\"/>\n";
  std::vector<std::size_t> ring(p.size());
  for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = i;
  svg << "<path d=\"" << path(ring.begin(), ring.end()) << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.6\"/>\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_reflex(i))
      svg << "<circle cx=\"" << sx(pts[i].first) << "\" cy=\"" << sy(pts[i].second) << "\" r=\"" << mark
          << "\" fill=\"#d62728\"><title>reflex " << p.input_index(i) << "</title></circle>\n";
  for (std::size_t s = p.size(); s < pts.size(); ++s)
    svg << "<rect x=\"" << sx(pts[s].first) - mark << "\" y=\"" << sy(pts[s].second) - mark << "\" width=\""
        << 2 * mark << "\" height=\"" << 2 * mark << "\" fill=\"#1f77b4\"><title>Steiner " << s
        << "</title></rect>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace pd
