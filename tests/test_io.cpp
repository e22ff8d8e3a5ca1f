// Readers for plain text, WKT and GeoJSON; the run --json writer; the SVG writer.
#include "core/io.h"
#include "core/json.h"

#include <gtest/gtest.h>

namespace pd {
namespace {

std::string error_of(const std::string& text) {
  try {
    make_parts(parse_parts(text));
  } catch (const PolygonError& e) {
    return e.what();
  }
  return "accepted";
}

// The one ring of a text holding one part without holes.
std::vector<Point> parse_polygon(const std::string& text) {
  const std::vector<Rings> parts = parse_parts(text);
  EXPECT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts.at(0).size(), 1u);
  return parts.at(0).at(0);
}

// How many rings each part has.
std::vector<std::size_t> ring_counts(const std::string& text) {
  std::vector<std::size_t> counts;
  for (const Rings& part : parse_parts(text)) counts.push_back(part.size());
  return counts;
}

const std::vector<Point> kTriangle = {{0, 0}, {4, 0}, {0, 3}};

TEST(Readers, PlainTextWithCommentsAndCountLine) {
  EXPECT_EQ(parse_polygon("# a triangle\n3\n0 0\n4 0 # right\n0 3\n"), kTriangle);
  EXPECT_EQ(parse_polygon("0 0\n4,0\n\n0 3\n0 0\n").size(), 4u);  // closing vertex kept for Polygon::make
  EXPECT_EQ(parse_polygon("0.5 -1e3\n").front(), Point(0.5, -1000));
}

TEST(Readers, PlainTextErrors) {
  EXPECT_EQ(error_of(""), "the input is empty");
  EXPECT_EQ(error_of("  \n# nothing\n"), "the input holds no vertices");
  EXPECT_EQ(error_of("0 0\n1 x\n"), "line 2: 'x' is not a number");
  EXPECT_EQ(error_of("0 0 0\n"), "line 1: expected 'x y', found 3 numbers");
  EXPECT_EQ(error_of("not a polygon\n"), "line 1: 'not' is not a number");
  EXPECT_EQ(error_of("4\n0 0\n1 0\n0 1\n"), "the count line says 4 vertices but 3 follow");
  EXPECT_EQ(error_of("2\n0 0\n1 0\n0 1\n0 0\n"), "the count line says 2 vertices but 4 follow");
}

// The count line may count the repeated closing vertex or leave it out.
TEST(Readers, CountLineWithOrWithoutTheClosingVertex) {
  EXPECT_EQ(parse_polygon("3\n0 0\n4 0\n0 3\n0 0\n").size(), 4u);
  EXPECT_EQ(parse_polygon("4\n0 0\n4 0\n0 3\n0 0\n").size(), 4u);
}

// Input quoted in a message is escaped: no raw control byte, no NUL cutting the line short.
TEST(Readers, QuotedInputIsEscaped) {
  EXPECT_EQ(error_of("\x01\x02garbage"), "line 1: '\\x01\\x02garbage' is not a number");
  EXPECT_EQ(error_of(std::string("0 0\n1 \0x\n", 9)), "line 2: '\\x00x' is not a number");
  EXPECT_EQ(error_of("0 0\n\x1b[31m 1\n"), "line 2: '\\x1b[31m' is not a number");
  EXPECT_NE(error_of("0 0\n" + std::string(100, '9') + "x 1\n").find("9999...' is not a number"), std::string::npos);
}

// What a coordinate is (core/coordinate.h), in every reader: these forms are read whole or refused,
// never read in part or changed.
const std::vector<std::pair<std::string, std::string>> kBadNumbers = {
    {"...", "'...' is not a number"},
    {"e", "'e' is not a number"},
    {"-", "'-' is not a number"},
    {"+", "'+' is not a number"},
    {"1.2.3", "'1.2.3' is not a number"},
    {"1-2", "'1-2' is not a number"},
    {"1e", "'1e' is not a number"},
    {"0x10", "'0x10' is not a number"},
    {"1e-400", "'1e-400' is too small for a double (it is not 0)"},
    {"-4.9e-324", "'-4.9e-324' is too small for a double (it is not 0)"},
    {"1e400", "'1e400' is too large for a double"},
    {"9007199254740993", "'9007199254740993' is not exactly a double (the nearest is 9007199254740992)"},
    {"-18446744073709551617", "'-18446744073709551617' is not exactly a double (the nearest is -18446744073709551616)"},
};

TEST(Readers, PlainTextAndWktReadNumbersWholeOrNotAtAll) {
  for (const auto& [number, why] : kBadNumbers) {
    EXPECT_EQ(error_of("0 0\n1 0\n0 " + number + "\n"), "line 3: " + why) << number;
    EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 " + number + ", 0 0))"), "WKT: " + why) << number;
  }
}

TEST(Readers, GeoJsonReadsNumbersWholeOrNotAtAll) {
  for (const std::string form : {"...", "e", "-", "+", "1.2.3", "1-2", "01", "1.", ".5", "1e", "NaN", "0x10"}) {
    const std::string why = error_of(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,)" + form + "]]]}");
    EXPECT_EQ(why.rfind("JSON: syntax error", 0), 0u) << form << ": " << why;
  }
  // JSON's grammar refuses the malformed forms first; the JSON reader refuses an overflow itself, as
  // "JSON: ... at offset N" with the rule's reason.
  for (const auto& [number, why] : kBadNumbers) {
    if (why.find("not a number") != std::string::npos) continue;
    const std::string prefix = number == "1e400" ? "JSON: " : "GeoJSON: ";
    const std::string geojson = error_of(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,)" + number + "]]]}");
    const std::string earcut = error_of("[[0,0],[1,0],[0," + number + "]]");
    EXPECT_EQ(geojson.rfind(prefix + why, 0), 0u) << geojson;
    EXPECT_EQ(earcut.rfind(prefix + why, 0), 0u) << earcut;
  }
}

TEST(Readers, NumbersThatAreExactlyDoublesAreRead) {
  EXPECT_EQ(parse_polygon("0 9007199254740992\n1 0\n0 1\n")[0].y(), 9007199254740992.0);
  EXPECT_EQ(parse_polygon("0 18446744073709551616\n1 0\n0 1\n")[0].y(), 18446744073709551616.0);
  EXPECT_EQ(parse_polygon("-0 0.1\n1 0\n0 1\n")[0].y(), 0.1);
  EXPECT_EQ(parse_polygon("0 0e-999\n1 0\n0 1\n")[0].y(), 0.0);
  EXPECT_EQ(parse_polygon("0 2.2250738585072014e-308\n1 0\n0 1\n")[0].y(), 2.2250738585072014e-308);
  EXPECT_EQ(parse_polygon("[[0,9007199254740992],[1,0],[0,1]]")[0].y(), 9007199254740992.0);
  EXPECT_EQ(parse_polygon("POLYGON ((0 1.5e3, 1 0, 0 1, 0 1.5e3))")[0].y(), 1500.0);
}

// A ring that stops being packable (here a 3-D position after 2-D ones) is unpacked into numbers whose
// text reads back as the same doubles, 2^60 included; an altitude is dropped.
TEST(Readers, UnpackedPositionsKeepTheirValues) {
  const std::vector<Point> ring = parse_polygon("[[1152921504606846976,0],[1,0],[0,1,5]]");
  EXPECT_EQ(ring, (std::vector<Point>{{1152921504606846976.0, 0}, {1, 0}, {0, 1}}));
  EXPECT_EQ(parse_polygon("[[0,0,7],[4,0,7],[0,3,7]]"), kTriangle);
  EXPECT_EQ(parse_polygon(R"({"type":"Polygon","coordinates":[[[0,0,1,2],[4,0,1,2],[0,3,1,2]]]})"), kTriangle);
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0,"z"],[4,0],[0,3]]]})"), "GeoJSON: a coordinate is not a number");
  EXPECT_EQ(error_of("[[0,0,1e-400],[1,0,0],[0,1,0]]"), "GeoJSON: '1e-400' is too small for a double (it is not 0)");
}

TEST(Readers, Wkt) {
  EXPECT_EQ(parse_polygon("POLYGON ((0 0, 4 0, 0 3, 0 0))").size(), 4u);
  EXPECT_EQ(parse_polygon("polygon((0 0,4 0,0 3))"), kTriangle);
  EXPECT_EQ(ring_counts("POLYGON ((0 0, 9 0, 0 9), (1 1, 1 2, 2 1))"), std::vector<std::size_t>{2});
  EXPECT_EQ(error_of("POLYGON EMPTY"), "the polygon is empty");
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0, 0 a))"), "WKT: 'a' is not a number");
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0, 0 3)"), "WKT: expected ')' at offset 24, found the end");
  EXPECT_EQ(ring_counts("MULTIPOLYGON (((0 0, 1 0, 0 1)), ((5 5, 6 5, 5 6), (5.1 5.1, 5.1 5.2, 5.2 5.1)))"),
            (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(parse_polygon("MULTIPOLYGON (((0 0, 4 0, 0 3)))"), kTriangle);  // one part, as ogr2ogr writes
}

// Only the format: a keyword that merely starts like one, text between the keyword and its rings,
// a trailing comma, a missing coordinate, text after the end are refused.
TEST(Readers, WktIsReadByItsGrammar) {
  EXPECT_EQ(error_of("POLYGONAL ((0 0, 1 0, 0 1))"), "WKT: 'POLYGONAL' is not POLYGON or MULTIPOLYGON");
  EXPECT_EQ(error_of("POLYGON garbage ((0 0, 1 0, 0 1))"), "WKT: expected '(' at offset 8, found 'garbage ((0 0, 1 0, '");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1,))"), "WKT: expected a coordinate at offset 24, found '))'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0))"), "WKT: expected a coordinate at offset 21, found '))'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1 2))"), "WKT: expected ')' at offset 24, found '2))'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 1 0, 0 1)) x"), "WKT: unexpected text after the polygon at offset 26, found 'x'");
}

// EWKT's SRID prefix is skipped; Z and M values are read and dropped, as many as the tag (or, without
// one, the first point) says each point has.
TEST(Readers, WktDimensionsAndSrid) {
  EXPECT_EQ(parse_polygon("POLYGON Z ((0 0 1, 4 0 1, 0 3 1))"), kTriangle);
  EXPECT_EQ(parse_polygon("POLYGON M ((0 0 1, 4 0 1, 0 3 1))"), kTriangle);
  EXPECT_EQ(parse_polygon("POLYGON ZM ((0 0 1 2, 4 0 1 2, 0 3 1 2))"), kTriangle);
  EXPECT_EQ(parse_polygon("POLYGON ((0 0 1, 4 0 1, 0 3 1))"), kTriangle);
  EXPECT_EQ(parse_polygon("SRID=4326;POLYGON((0 0,4 0,0 3))"), kTriangle);
  EXPECT_EQ(parse_polygon("srid=4326; MULTIPOLYGON Z (((0 0 5, 4 0 5, 0 3 5)))"), kTriangle);
  EXPECT_EQ(error_of("POLYGON Z ((0 0, 4 0, 0 3))"), "WKT: expected 3 coordinates in each point at offset 15, found ', 4 0, 0 3))'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0 1, 0 3))"), "WKT: expected ')' at offset 19, found '1, 0 3))'");
  EXPECT_EQ(error_of("POLYGON ZM ((0 0 1, 4 0 1, 0 3 1))"), "WKT: expected 4 coordinates in each point at offset 18, found ', 4 0 1, 0 3 1))'");
  EXPECT_EQ(error_of("POLYGON ((0 0 1 2 3, 4 0, 0 3))"), "WKT: expected ')' at offset 18, found '3, 4 0, 0 3))'");
  EXPECT_EQ(error_of("SRID=4326 POLYGON((0 0,4 0,0 3))"), "WKT: expected ';' after SRID= at offset 0, found 'SRID=4326 POLYGON((0'");
  EXPECT_EQ(error_of("POLYGON Z ((0 0 nan, 4 0 1, 0 3 1))"), "accepted");  // a Z value is dropped, whatever it is
}

// A Feature's geometry is a geometry; a FeatureCollection holds Features; JSON's own grammar (no
// trailing comma) holds; a UTF-8 byte order mark is not content.
TEST(Readers, GeoJsonIsReadByItsGrammar) {
  const std::string poly = R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[0,3]]]})";
  const std::string feature = R"({"type":"Feature","properties":null,"geometry":)" + poly + "}";
  EXPECT_EQ(parse_polygon("\xEF\xBB\xBF" + poly), kTriangle);
  EXPECT_EQ(parse_polygon(R"({"type":"FeatureCollection","features":[)" + feature + "]}"), kTriangle);
  EXPECT_EQ(error_of(R"({"type":"Feature","geometry":)" + feature + "}"), "GeoJSON: a Feature's geometry cannot be a Feature");
  EXPECT_EQ(error_of(R"({"type":"FeatureCollection","features":[)" + poly + "]}"),
            "GeoJSON: a FeatureCollection's features must be Features");
  EXPECT_EQ(error_of(R"({"type":"Feature","geometry":null})"), "GeoJSON: the Feature has no geometry");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[0,3],]]})").rfind("JSON: syntax error", 0), 0u);
  EXPECT_EQ(ring_counts(R"({"type":"MultiPolygon","coordinates":[[[[0,0],[4,0],[0,3]]],[[[5,5],[6,5],[5,6]]]]})"),
            (std::vector<std::size_t>{1, 1}));
}

// A JSON refusal is one line naming its byte offset; the GeoJSON reader's own messages hold for packed
// positions as for the others.
TEST(Readers, GeoJsonErrorsNameTheirPlace) {
  EXPECT_EQ(error_of("[[0,0],[1,0],[0,1]"), "JSON: syntax error: unexpected end of input at offset 18");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1]]],})"),
            "JSON: syntax error: expected a member name at offset 54");
  EXPECT_EQ(error_of("[[0,0],[1,0],[0,\"1\"]]"), "GeoJSON: a coordinate is not a number");
  EXPECT_EQ(error_of("[[0,0],[1,0],[0]]"), "GeoJSON: a position must be [x, y]");
  EXPECT_EQ(error_of("[[0],[1],[0]]"), "GeoJSON: a position must be [x, y]");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[0,0],[1,0],[0,1]]})"),
            "GeoJSON: a polygon's coordinates must be an array of rings");
  EXPECT_EQ(error_of(R"({"type":"MultiPolygon","coordinates":[[0,0],[1,0],[0,1]]})"),
            "GeoJSON: a MultiPolygon's coordinates must be an array of polygons");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,9007199254740993]]]})"),
            "GeoJSON: '9007199254740993' is not exactly a double (the nearest is 9007199254740992)");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1]]]} x)"),
            "JSON: syntax error: unexpected text after the document at offset 55");
}

TEST(Readers, GeoJson) {
  const std::string poly = R"({"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 3], [0, 0]]]})";
  EXPECT_EQ(parse_polygon(poly).size(), 4u);
  EXPECT_EQ(parse_polygon(R"({"type":"Feature","properties":{},"geometry":)" + poly + "}").size(), 4u);
  EXPECT_EQ(parse_polygon("[[[0,0],[4,0],[0,3]]]"), kTriangle);  // earcut's array of rings
  EXPECT_EQ(ring_counts(R"({"type":"Polygon","coordinates":[[[0,0],[9,0],[0,9]],[[1,1],[1,2],[2,1]]]})"),
            std::vector<std::size_t>{2});
  EXPECT_EQ(ring_counts("[[[0,0],[9,0],[0,9]],[[1,1],[1,2],[2,1]]]"), std::vector<std::size_t>{2});  // earcut's rings
  EXPECT_EQ(error_of(R"({"type":"Point","coordinates":[0,0]})"), "GeoJSON: a 'Point' is not a Polygon or MultiPolygon");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[]})"), "the polygon is empty");
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[4,"a"],[0,3]]]})"),
            "GeoJSON: a coordinate is not a number");
  EXPECT_NE(error_of(R"({"type": "Polygon", "coordinates": [[[0, 0], [4, 0)"), "accepted");
  EXPECT_NE(error_of(std::string(100000, '[')), "accepted");  // nesting too deep, no stack overflow
}

TEST(Readers, NonFiniteNumbersReachThePolygonCheck) {
  const auto ring = parse_polygon("0 0\n1 nan\n0 1\n");
  EXPECT_THROW(Polygon::make(ring), PolygonError);
}

TEST(Writers, FormatsRoundTrip) {
  const std::vector<Point> ring = {{0, 0}, {0.1, 0}, {1e-300, 3}, {1.2345678901234568e20, -1152921504606846976.0}};
  for (Format f : {Format::Txt, Format::Wkt, Format::GeoJson}) {
    auto back = parse_polygon(format_polygon({ring}, f));
    if (back.size() == ring.size() + 1) back.pop_back();  // WKT and GeoJSON close the ring
    EXPECT_EQ(back, ring);
  }
}

TEST(Writers, RunJsonFollowsTheContract) {
  // Clockwise input: points keep the file's order; pieces are counter-clockwise cycles in file indices.
  const Polygon p = Polygon::make({{0, 0}, {0, 3}, {3, 3}, {3, 0}});
  Decomposition d;
  const VertexId s = 4 + d.add_steiner(QPoint(Rational(1, 3), Rational(1)));
  d.add_cut(0, s);
  d.add_cut(s, 2);
  d.add_cut(1, s);
  d.add_cut(3, s);
  const auto pieces = pieces_of(p, d);
  const Counters counters{{"tests", 7}};
  const std::string text = run_json({"demo", {{&p, &d, &pieces}}, true, 0.25, &counters});
  const Json j = parse_json(text);
  EXPECT_EQ(j.get("algorithm")->text, "demo");
  EXPECT_EQ(j.get("n")->text, "4");
  EXPECT_EQ(j.get("reflex")->text, "0");
  const auto& pts = j.get("points")->items;
  ASSERT_EQ(pts.size(), 5u);
  EXPECT_EQ(pts[1].items[0].text, "0");
  EXPECT_EQ(pts[1].items[1].text, "3");
  EXPECT_EQ(pts[4].items[0].type, Json::Type::String);
  EXPECT_EQ(pts[4].items[0].text, "1/3");
  EXPECT_EQ(pts[4].items[1].text, "1");
  EXPECT_EQ(j.get("piece_count")->text, "4");
  EXPECT_EQ(j.get("steiner_count")->text, "1");
  EXPECT_TRUE(j.get("valid")->boolean);
  EXPECT_EQ(j.get("seconds")->text, "0.25");
  EXPECT_EQ(j.get("counters")->get("tests")->text, "7");
  // Each piece, read back in file indices, turns left: counter-clockwise.
  for (const Json& piece : j.get("pieces")->items) {
    ASSERT_EQ(piece.items.size(), 3u);
    auto at = [&](const Json& idx) {
      const Json& q = pts[std::stoul(idx.text)];
      return QPoint(Rational(q.items[0].text), Rational(q.items[1].text));
    };
    EXPECT_EQ(orient(at(piece.items[0]), at(piece.items[1]), at(piece.items[2])), 1);
  }
}

TEST(Writers, SvgMarksPiecesReflexVerticesAndSteinerPoints) {
  const Polygon p = Polygon::make({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}});
  Decomposition d;
  const VertexId s = 6 + d.add_steiner(QPoint(2, 0), 0);
  d.add_cut(3, s);
  const std::vector<Piece> pieces = pieces_of(p, d);
  const std::string svg = run_svg({{&p, &d, &pieces}}, "naive");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("reflex 3"), std::string::npos);
  EXPECT_NE(svg.find("Steiner 6"), std::string::npos);
  EXPECT_NE(svg.find("hsl("), std::string::npos);
}

}  // namespace
}  // namespace pd
