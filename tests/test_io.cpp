// Readers for plain text, WKT and GeoJSON; the run --json writer; the SVG writer.
#include "core/io.h"
#include "core/json.h"

#include <gtest/gtest.h>

namespace pd {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_polygon(text);
  } catch (const PolygonError& e) {
    return e.what();
  }
  return "accepted";
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
  EXPECT_EQ(error_of("4\n0 0\n1 0\n0 1\n"), "the count line says 4 vertices but 3 follow");
  EXPECT_EQ(error_of("\x01\x02garbage"), "line 1: '\x01\x02garbage' is not a number");
}

TEST(Readers, Wkt) {
  EXPECT_EQ(parse_polygon("POLYGON ((0 0, 4 0, 0 3, 0 0))").size(), 4u);
  EXPECT_EQ(parse_polygon("polygon((0 0,4 0,0 3))"), kTriangle);
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0, 0 3), (1 1, 2 1, 1 2))"), "holes are not supported");
  EXPECT_EQ(error_of("POLYGON EMPTY"), "the polygon is empty");
  EXPECT_EQ(error_of("MULTIPOLYGON (((0 0, 1 0, 0 1)))"), "multipolygons are not supported");
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0, 0 a))"), "WKT: '0 a' is not a point 'x y'");
  EXPECT_EQ(error_of("POLYGON ((0 0, 4 0, 0 3)"), "WKT: unexpected text after the ring");
}

TEST(Readers, GeoJson) {
  const std::string poly = R"({"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 3], [0, 0]]]})";
  EXPECT_EQ(parse_polygon(poly).size(), 4u);
  EXPECT_EQ(parse_polygon(R"({"type":"Feature","properties":{},"geometry":)" + poly + "}").size(), 4u);
  EXPECT_EQ(parse_polygon("[[[0,0],[4,0],[0,3]]]"), kTriangle);  // earcut's array of rings
  EXPECT_EQ(error_of(R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[0,3]],[[1,1],[2,1],[1,2]]]})"),
            "holes are not supported");
  EXPECT_EQ(error_of(R"({"type":"Point","coordinates":[0,0]})"), "GeoJSON: a Point is not a Polygon");
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
  const std::vector<Point> ring = {{0, 0}, {0.1, 0}, {1e-300, 3}};
  for (Format f : {Format::Txt, Format::Wkt, Format::GeoJson}) {
    auto back = parse_polygon(format_polygon(ring, f));
    if (back.size() == 4) back.pop_back();  // WKT and GeoJSON close the ring
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
  const std::string text = run_json({"demo", &p, &d, &pieces, true, 0.25, &counters});
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
  const std::string svg = run_svg(p, d, pieces_of(p, d), "naive");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("reflex 3"), std::string::npos);
  EXPECT_NE(svg.find("Steiner 6"), std::string::npos);
  EXPECT_NE(svg.find("hsl("), std::string::npos);
}

}  // namespace
}  // namespace pd
