// Reading polygons and writing results.
//
// Input formats are detected from the content: plain text (`x y` per line, `#` comments, an optional
// single-number count line), WKT `POLYGON((...))`, GeoJSON `Polygon` or a `Feature` holding one (also a
// `FeatureCollection` of one feature, and earcut's bare array of rings). A reader returns the outer ring
// as written; Polygon::make does the geometric checks.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"
#include "core/validate.h"

#include <optional>
#include <string>
#include <vector>

namespace pd {

// Parses polygon text in any supported format. Throws PolygonError naming the problem (garbage, an
// empty ring, holes, a multipolygon).
std::vector<Point> parse_polygon(const std::string& content);
// Reads and parses a file; an unreadable file is a PolygonError too ("cannot read FILE").
std::vector<Point> read_polygon_file(const std::string& path);

enum class Format { Txt, Wkt, GeoJson };
Format parse_format(const std::string& name);  // throws std::invalid_argument
std::string format_polygon(const std::vector<Point>& ring, Format f);

struct RunReport {
  std::string algorithm;
  const Polygon* polygon;
  const Decomposition* decomposition;
  const std::vector<Piece>* pieces;  // in Polygon (counter-clockwise) ids
  std::optional<bool> valid;         // absent with --no-validate
  double seconds;
  const Counters* counters;
};

// The `run --json` object of docs/CONTRACT.md: points in file order then Steiner points (exact), pieces
// as counter-clockwise cycles of indices into points.
std::string run_json(const RunReport& r);

// An SVG figure: the polygon, each piece in its own colour, reflex vertices and Steiner points marked.
std::string run_svg(const Polygon& p, const Decomposition& d, const std::vector<Piece>& pieces,
                    const std::string& title);

}  // namespace pd
