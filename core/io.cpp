#include "core/io.h"

#include "core/json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

namespace pd {

std::optional<std::string> read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Format parse_format(const std::string& name) {
  if (name == "txt") return Format::Txt;
  if (name == "wkt") return Format::Wkt;
  if (name == "geojson") return Format::GeoJson;
  throw std::invalid_argument("unknown format '" + name + "'; formats: txt, wkt, geojson");
}

std::string format_polygon(const Rings& rings, Format f) {
  auto xy = [](const Point& p, const char* sep) { return double_text(p.x()) + sep + double_text(p.y()); };
  // Each ring closed, as WKT and GeoJSON want: the first vertex repeated.
  auto closed_rings = [&](const char* open, auto position, const char* close) {
    std::string out;
    for (const Ring& ring : rings) {
      out += out.empty() ? open : std::string(", ") + open;
      for (const Point& p : ring) out += position(p) + ", ";
      out += position(ring.front()) + close;
    }
    return out;
  };
  auto wkt_point = [&](const Point& p) { return xy(p, " "); };
  auto geojson_position = [&](const Point& p) { return "[" + xy(p, ", ") + "]"; };
  std::string out;
  switch (f) {
    case Format::Txt:
      if (rings.size() != 1) throw std::invalid_argument("plain text holds one ring; write a polygon with holes as wkt or geojson");
      out = std::to_string(rings[0].size()) + "\n";
      for (const Point& p : rings[0]) out += xy(p, " ") + "\n";
      return out;
    case Format::Wkt:
      return "POLYGON (" + closed_rings("(", wkt_point, ")") + ")\n";
    case Format::GeoJson:
      return "{\"type\": \"Polygon\", \"coordinates\": [" + closed_rings("[", geojson_position, "]") + "]}\n";
  }
  return out;
}

namespace {

// Where each part's vertices and Steiner points sit in run --json's points.
struct PointNumbering {
  std::vector<std::size_t> input_offset, steiner_offset;

  explicit PointNumbering(const std::vector<PartResult>& parts) {
    std::size_t next = 0;
    for (const PartResult& part : parts) {
      input_offset.push_back(next);
      next += part.polygon->input_size();
    }
    for (const PartResult& part : parts) {
      steiner_offset.push_back(next);
      next += part.decomposition->steiner.size();
    }
  }
  std::size_t index(const PartResult& part, std::size_t k, VertexId v) const {
    const Polygon& p = *part.polygon;
    return v < p.size() ? input_offset[k] + p.input_index(v) : steiner_offset[k] + (v - p.size());
  }
};

std::string exact_coordinate(const Rational& v) {
  const std::string t = rational_text(v);
  return t.find('/') == std::string::npos ? t : "\"" + t + "\"";
}

}  // namespace

RunTotals totals_of(const std::vector<PartResult>& parts) {
  RunTotals t;
  for (const PartResult& part : parts) {
    t.add(*part.polygon);
    t.pieces += part.pieces->size();
    t.steiner += part.decomposition->steiner.size();
  }
  return t;
}

std::string run_json(const RunReport& r) {
  const PointNumbering numbering(r.parts);
  const RunTotals t = totals_of(r.parts);
  std::string out = "{\"algorithm\": " + json_quote(r.algorithm) + ", \"n\": " + std::to_string(t.n) +
                    ", \"reflex\": " + std::to_string(t.reflex) + ", \"holes\": " + std::to_string(t.holes) +
                    ", \"points\": [";
  bool first = true;
  for (const PartResult& part : r.parts)
    for (const Point& q : part.polygon->input_points()) {
      out += (first ? "[" : ", [") + double_text(q.x()) + ", " + double_text(q.y()) + "]";
      first = false;
    }
  for (const PartResult& part : r.parts)
    for (const SteinerPoint& s : part.decomposition->steiner)
      out += ", [" + exact_coordinate(s.point.x()) + ", " + exact_coordinate(s.point.y()) + "]";
  out += "], \"pieces\": [";
  std::string parts = "[";
  std::size_t piece_index = 0;
  for (std::size_t k = 0; k < r.parts.size(); ++k) {
    parts += k ? "], [" : "[";
    const std::size_t part_start = piece_index;
    for (const Piece& piece : *r.parts[k].pieces) {
      out += piece_index ? ", [" : "[";
      for (std::size_t i = 0; i < piece.size(); ++i)
        out += (i ? ", " : "") + std::to_string(numbering.index(r.parts[k], k, piece[i]));
      out += "]";
      parts += (piece_index == part_start ? "" : ", ") + std::to_string(piece_index);
      ++piece_index;
    }
  }
  out += "], \"piece_count\": " + std::to_string(t.pieces) + ", \"steiner_count\": " + std::to_string(t.steiner);
  std::string merged;
  for (std::size_t k = 0; k < r.parts.size(); ++k)
    for (const auto& [index, repeats] : r.parts[k].polygon->merged())
      merged += (merged.empty() ? "[" : ", [") + std::to_string(numbering.input_offset[k] + index) + ", " +
                std::to_string(numbering.input_offset[k] + repeats) + "]";
  if (!merged.empty()) out += ", \"merged\": [" + merged + "]";
  if (r.parts.size() > 1) out += ", \"parts\": " + parts + "]]";
  if (r.valid) out += std::string(", \"valid\": ") + (*r.valid ? "true" : "false");
  out += ", \"seconds\": " + double_text(r.seconds) + ", \"counters\": {";
  first = true;
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

namespace {

std::string xml_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string run_svg(const std::vector<PartResult>& parts, const std::string& title) {
  // Long double, whose range is far beyond a double's, so that a polygon spanning +-1.7e308 still maps
  // to finite figure coordinates. Part k's ids start at base[k].
  std::vector<std::pair<long double, long double>> pts;
  std::vector<std::size_t> base;
  for (const PartResult& part : parts) {
    base.push_back(pts.size());
    for (const QPoint& q : exact_points(*part.polygon, *part.decomposition))
      pts.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  }
  long double x0 = pts[0].first, x1 = x0, y0 = pts[0].second, y1 = y0;
  for (const auto& [x, y] : pts) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  const long double size = 800, margin = 20, span = std::max({x1 - x0, y1 - y0, 1e-300L});
  const long double scale = (size - 2 * margin) / span;
  const double width = static_cast<double>((x1 - x0) * scale + 2 * margin);
  const double height = static_cast<double>((y1 - y0) * scale + 2 * margin + 24);
  auto sx = [&](long double x) { return static_cast<double>(margin + (x - x0) * scale); };
  auto sy = [&](long double y) { return static_cast<double>(24 + margin + (y1 - y) * scale); };  // SVG's y axis points down
  auto path = [&](std::size_t from, auto begin, auto end) {
    std::ostringstream s;
    s.precision(10);
    for (auto it = begin; it != end; ++it)
      s << (it == begin ? "M" : "L") << sx(pts[from + *it].first) << "," << sy(pts[from + *it].second);
    s << "Z";
    return s.str();
  };
  const double mark = std::max(1.5, std::min(5.0, 400.0 / std::sqrt(static_cast<double>(pts.size()))));
  std::ostringstream svg;
  svg.precision(10);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << margin << "\" y=\"18\" font-family=\"sans-serif\" font-size=\"14\">" << xml_text(title)
      << "</text>\n";
  const PointNumbering numbering(parts);
  std::size_t colour = 0;
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (const Piece& piece : *parts[k].pieces)
      svg << "<path d=\"" << path(base[k], piece.begin(), piece.end()) << "\" fill=\"" << piece_colour(colour++)
          << "\" stroke=\"#333\" stroke-width=\"0.6\"/>\n";
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Polygon& p = *parts[k].polygon;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
      std::vector<std::size_t> ring(p.ring_end(r) - p.ring_begin(r));
      std::iota(ring.begin(), ring.end(), p.ring_begin(r));
      svg << "<path d=\"" << path(base[k], ring.begin(), ring.end())
          << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.6\"/>\n";
    }
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.is_reflex(i))
        svg << "<circle cx=\"" << sx(pts[base[k] + i].first) << "\" cy=\"" << sy(pts[base[k] + i].second) << "\" r=\""
            << mark << "\" fill=\"#d62728\"><title>reflex " << numbering.index(parts[k], k, static_cast<VertexId>(i))
            << "</title></circle>\n";
    for (std::size_t s = base[k] + p.size(); s < (k + 1 < parts.size() ? base[k + 1] : pts.size()); ++s)
      svg << "<rect x=\"" << sx(pts[s].first) - mark << "\" y=\"" << sy(pts[s].second) - mark << "\" width=\""
          << 2 * mark << "\" height=\"" << 2 * mark << "\" fill=\"#1f77b4\"><title>Steiner "
          << numbering.index(parts[k], k, static_cast<VertexId>(s - base[k])) << "</title></rect>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace pd
