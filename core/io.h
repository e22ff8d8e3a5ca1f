// Reading polygons and writing results.
//
// Input formats are detected from the content (readers.cpp): plain text (`x y` per line, `#` comments,
// an optional single-number count line; one ring), WKT or EWKT `POLYGON` and `MULTIPOLYGON` (Z and M
// values dropped), GeoJSON `Polygon`, `MultiPolygon`, a `Feature` holding one, a `FeatureCollection` of
// one such feature, and earcut's bare array of rings; a UTF-8 byte order mark is skipped. Every
// coordinate is read by core/coordinate.h's rule. A reader returns every part's rings as written;
// make_parts (core/polygon.h) does the geometric checks. Writers are in io.cpp.
#pragma once

#include "core/decomposition.h"
#include "core/polygon.h"
#include "core/validate.h"

#include <optional>
#include <string>
#include <vector>

namespace pd {

// Parses polygon text in any supported format into its parts (one for a polygon), each its outer ring
// then its holes. Throws PolygonError naming the problem (garbage, a number that is not a coordinate,
// an empty polygon).
std::vector<Rings> parse_parts(const std::string& content);
// Reads and parses a file ("-": the standard input); an unreadable file, a directory and a file holding
// a NUL byte (binary data, /dev/zero) are PolygonErrors too.
std::vector<Rings> read_parts_file(const std::string& path);

// A file's bytes as they are, or nothing when it cannot be opened (for the callers' own messages).
std::optional<std::string> read_file_bytes(const std::string& path);

enum class Format { Txt, Wkt, GeoJson };
Format parse_format(const std::string& name);  // throws std::invalid_argument
// The rings (the outer ring, then its holes) in format f, each ring closed where the format wants it.
// Throws std::invalid_argument for holes in plain text, which holds one ring.
std::string format_polygon(const Rings& rings, Format f);

// One part's result: its polygon, what the algorithm returned and the pieces in Polygon ids.
struct PartResult {
  const Polygon* polygon;
  const Decomposition* decomposition;
  const std::vector<Piece>* pieces;
};

// The parts' totals, and their pieces and Steiner points.
struct RunTotals : PolygonTotals {
  std::size_t pieces = 0, steiner = 0;
};
RunTotals totals_of(const std::vector<PartResult>& parts);

struct RunReport {
  std::string algorithm;
  std::vector<PartResult> parts;  // one for a polygon; a multipolygon's parts in file order
  std::optional<bool> valid;      // absent with --no-validate
  double seconds;
  const Counters* counters;
};

// The `run --json` object of docs/CONTRACT.md: points in file order (every part's input vertices, then
// every part's Steiner points, exact), pieces as counter-clockwise cycles of indices into points,
// "holes", "merged" when input vertices were merged, "parts" for more than one part.
std::string run_json(const RunReport& r);

// An SVG figure: the polygon, each piece in its own colour, reflex vertices and Steiner points marked.
std::string run_svg(const std::vector<PartResult>& parts, const std::string& title);

}  // namespace pd
