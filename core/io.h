// Reading polygons and writing results.
//
// Input formats are detected from the content (readers.cpp): plain text (`x y` per line, `#` comments,
// an optional single-number count line), WKT `POLYGON` or a one-part `MULTIPOLYGON`, GeoJSON `Polygon`,
// a one-part `MultiPolygon`, a `Feature` holding one, a `FeatureCollection` of one such feature, and
// earcut's bare array of rings; a UTF-8 byte order mark is skipped. Every coordinate is read by
// core/coordinate.h's rule. A reader returns the outer ring as written; Polygon::make does the
// geometric checks. Writers are in io.cpp.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"
#include "core/validate.h"

#include <optional>
#include <string>
#include <vector>

namespace pd {

// Parses polygon text in any supported format. Throws PolygonError naming the problem (garbage, a
// number that is not a coordinate, an empty ring, holes, a multipolygon).
std::vector<Point> parse_polygon(const std::string& content);
// Reads and parses a file ("-": the standard input); an unreadable file, a directory and a file holding
// a NUL byte (binary data, /dev/zero) are PolygonErrors too.
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
