#include "core/io.h"

#include "core/json.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pd {

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
  // Long double, whose range is far beyond a double's, so that a polygon spanning +-1.7e308 still maps
  // to finite figure coordinates.
  std::vector<std::pair<long double, long double>> pts;
  for (const QPoint& q : exact) pts.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  long double x0 = pts[0].first, x1 = x0, y0 = pts[0].second, y1 = y0;
  for (const auto& [x, y] : pts) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  const long double size = 800, margin = 20, span = std::max({x1 - x0, y1 - y0, 1e-300L});
  const long double scale = (size - 2 * margin) / span;
  const double width = static_cast<double>((x1 - x0) * scale + 2 * margin);
  const double height = static_cast<double>((y1 - y0) * scale + 2 * margin + 24);
  auto sx = [&](long double x) { return static_cast<double>(margin + (x - x0) * scale); };
  auto sy = [&](long double y) { return static_cast<double>(24 + margin + (y1 - y) * scale); };  // SVG's y axis points down
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
