// The JSON reader (core/json.h): RFC 8259's grammar and nothing more, strings decoded and checked as
// UTF-8, numbers kept as written, positions packed by the coordinate rule, and every refusal one line
// naming its byte offset.
#include "core/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace pd {
namespace {

std::string error_of(const std::string& text, bool pack = false) {
  try {
    parse_json(text, pack);
  } catch (const JsonError& e) {
    return e.what();
  }
  return "accepted";
}

std::string string_of(const std::string& literal) {
  const Json j = parse_json(literal);
  EXPECT_EQ(j.type, Json::Type::String) << literal;
  return j.text;
}

TEST(Json, EveryValueForm) {
  const Json j = parse_json(
      " {\"null\": null, \"t\": true, \"f\": false, \"n\": -12.5e+3, \"s\": \"x\", \"a\": [1, [], {}], \"o\": {\"k\": 0}}\r\n\t");
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.fields.size(), 7u);
  EXPECT_EQ(j.get("null")->type, Json::Type::Null);
  EXPECT_TRUE(j.get("t")->boolean);
  EXPECT_EQ(j.get("f")->type, Json::Type::Bool);
  EXPECT_FALSE(j.get("f")->boolean);
  EXPECT_EQ(j.get("n")->text, "-12.5e+3");
  EXPECT_EQ(j.get("n")->number(), -12500.0);
  EXPECT_EQ(j.get("s")->text, "x");
  ASSERT_EQ(j.get("a")->items.size(), 3u);
  EXPECT_TRUE(j.get("a")->items[1].is_array());
  EXPECT_TRUE(j.get("a")->items[2].is_object());
  EXPECT_EQ(j.get("o")->get("k")->text, "0");
  EXPECT_EQ(j.get("missing"), nullptr);
  for (const std::string scalar : {"null", "true", "false", "0", "\"\"", "[]", "{}"})
    EXPECT_EQ(error_of(scalar), "accepted") << scalar;
}

TEST(Json, NumbersKeepTheirText) {
  for (const std::string n : {"0", "-0", "0.5", "-0.0", "1E+2", "1e-2", "123456789012345678901234567890", "1e-400"})
    EXPECT_EQ(parse_json(n).text, n);
  EXPECT_TRUE(std::signbit(parse_json("-0").number()));
  EXPECT_EQ(parse_json("[9007199254740993]").items[0].text, "9007199254740993");
}

TEST(Json, RepeatedNamesKeepTheLastValue) {
  EXPECT_EQ(parse_json(R"({"a": 1, "b": 2, "a": 3})").get("a")->text, "3");
}

TEST(Json, StringEscapesAndUtf8) {
  EXPECT_EQ(string_of(R"("\"\\\/\b\f\n\r\t")"), "\"\\/\b\f\n\r\t");
  EXPECT_EQ(string_of(R"("\u0041\u00e9\u20AC")"), "A\xC3\xA9\xE2\x82\xAC");
  EXPECT_EQ(string_of(R"("\ud83d\ude00")"), "\xF0\x9F\x98\x80");  // a surrogate pair
  EXPECT_EQ(string_of(R"("a\u0000b")"), std::string("a\0b", 3));
  EXPECT_EQ(string_of("\"\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\xF4\x8F\xBF\xBF\""), "\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\xF4\x8F\xBF\xBF");
  EXPECT_EQ(parse_json(R"({"\u00e9": 1})").fields.count("\xC3\xA9"), 1u);
}

TEST(Json, BadStringsAreRefusedWhereTheyGoWrong) {
  EXPECT_EQ(error_of(R"("\x")"), "JSON: syntax error: invalid escape at offset 1");
  EXPECT_EQ(error_of(R"("ab\u12")"), "JSON: syntax error: a \\u escape needs four hex digits at offset 3");
  EXPECT_EQ(error_of(R"("\u12G4")"), "JSON: syntax error: a \\u escape needs four hex digits at offset 1");
  EXPECT_EQ(error_of(R"("\ud800")"), "JSON: syntax error: a \\u escape of a high surrogate without a low one at offset 1");
  EXPECT_EQ(error_of(R"("\ud800\u0041")"), "JSON: syntax error: a \\u escape of a high surrogate without a low one at offset 1");
  EXPECT_EQ(error_of(R"("\ud800\ud800")"), "JSON: syntax error: a \\u escape of a high surrogate without a low one at offset 1");
  EXPECT_EQ(error_of(R"("x\udc00")"), "JSON: syntax error: a \\u escape of a low surrogate without a high one at offset 2");
  EXPECT_EQ(error_of("\"a\x01\""), "JSON: syntax error: a control character in a string must be escaped at offset 2");
  EXPECT_EQ(error_of("\"a\nb\""), "JSON: syntax error: a control character in a string must be escaped at offset 2");
  EXPECT_EQ(error_of("\"abc"), "JSON: syntax error: unexpected end of input in a string at offset 4");
  EXPECT_EQ(error_of("\"\\"), "JSON: syntax error: unexpected end of input in a string at offset 2");
  EXPECT_EQ(error_of("'a'"), "JSON: syntax error: expected a value at offset 0");
  // Overlong forms, encoded surrogates, beyond U+10FFFF, a stray continuation byte, a cut sequence,
  // bytes that never occur; the offset is the first byte that cannot be (the string starts at 1).
  const std::vector<std::pair<std::string, int>> bad_utf8 = {
      {"\xC0\x80", 4},         {"\xC1\xBF", 4}, {"\xE0\x80\x80", 5}, {"\xED\xA0\x80", 5}, {"\xF0\x80\x80\x80", 5},
      {"\xF4\x90\x80\x80", 5}, {"\xF5\x80\x80\x80", 4}, {"\x80", 4}, {"\xE2\x82", 6}, {"\xE2\x82x", 6},
      {"\xFF", 4},             {"\xFE", 4}};
  for (const auto& [bad, offset] : bad_utf8)
    EXPECT_EQ(error_of("[\"ok" + bad + "\"]"), "JSON: syntax error: invalid UTF-8 in a string at offset " + std::to_string(offset))
        << bad;
}

TEST(Json, NumbersKeepToJsonsGrammar) {
  for (const std::string bad : {"01", "-01", "1.", "1.e5", "1e", "1e+", "00"})
    EXPECT_EQ(error_of("[" + bad + "]"), "JSON: syntax error: invalid number at offset 1") << bad;
  for (const std::string bad : {"-", "-a", "- 1"})
    EXPECT_EQ(error_of("[" + bad + "]"), "JSON: syntax error: invalid number at offset 1") << bad;
  for (const std::string bad : {".5", "+1", "NaN", "nan", "Infinity", "-Infinity"})
    EXPECT_EQ(error_of("[" + bad + "]").rfind("JSON: syntax error: ", 0), 0u) << bad;
  EXPECT_EQ(error_of("[1.2.3]"), "JSON: syntax error: invalid number at offset 1");
  EXPECT_EQ(error_of("[0x10]"), "JSON: syntax error: expected ',' or ']' at offset 2");
  EXPECT_EQ(error_of("[1e400]"), "JSON: '1e400' is too large for a double at offset 1");
  EXPECT_EQ(error_of("[-" + std::string(400, '9') + "]").rfind("JSON: '-9999", 0), 0u);
}

TEST(Json, TheWholeDocumentAndNothingElse) {
  EXPECT_EQ(error_of(""), "JSON: syntax error: unexpected end of input at offset 0");
  EXPECT_EQ(error_of(" \n"), "JSON: syntax error: unexpected end of input at offset 2");
  EXPECT_EQ(error_of("[1"), "JSON: syntax error: unexpected end of input at offset 2");
  EXPECT_EQ(error_of("[1,"), "JSON: syntax error: unexpected end of input at offset 3");
  EXPECT_EQ(error_of(R"({"a")"), "JSON: syntax error: unexpected end of input at offset 4");
  EXPECT_EQ(error_of("{} x"), "JSON: syntax error: unexpected text after the document at offset 3");
  EXPECT_EQ(error_of("[1] ]"), "JSON: syntax error: unexpected text after the document at offset 4");
  EXPECT_EQ(error_of("1 2"), "JSON: syntax error: unexpected text after the document at offset 2");
  EXPECT_EQ(error_of("[1,]"), "JSON: syntax error: expected a value at offset 3");
  EXPECT_EQ(error_of("[1 2]"), "JSON: syntax error: expected ',' or ']' at offset 3");
  EXPECT_EQ(error_of(R"({"a":1,})"), "JSON: syntax error: expected a member name at offset 7");
  EXPECT_EQ(error_of(R"({a:1})"), "JSON: syntax error: expected a member name at offset 1");
  EXPECT_EQ(error_of(R"({"a" 1})"), "JSON: syntax error: expected ':' at offset 5");
  EXPECT_EQ(error_of(R"({"a":1 "b":2})"), "JSON: syntax error: expected ',' or '}' at offset 7");
  EXPECT_EQ(error_of("// c\n1"), "JSON: syntax error: expected a value at offset 0");
  EXPECT_EQ(error_of("[1 /* c */]"), "JSON: syntax error: expected ',' or ']' at offset 3");
  EXPECT_EQ(error_of("tru"), "JSON: syntax error: invalid literal at offset 0");
  EXPECT_EQ(error_of("[nul]"), "JSON: syntax error: invalid literal at offset 1");
  EXPECT_EQ(error_of("\xEF\xBB\xBF[1]"), "accepted");  // a byte order mark
  EXPECT_EQ(error_of(std::string("[1]\0", 4)), "JSON: syntax error: unexpected text after the document at offset 3");
  for (const std::string bad : {"", "[1,]", "\"\xFF\"", "[1e400]", "{} x"})
    EXPECT_EQ(error_of(bad).find('\n'), std::string::npos) << bad;  // one line
}

TEST(Json, NestingIsLimited) {
  for (const bool pack : {false, true}) {
    EXPECT_EQ(error_of(std::string(256, '[') + std::string(256, ']'), pack), "accepted");
    EXPECT_EQ(error_of(std::string(257, '[') + std::string(257, ']'), pack), "JSON: nesting too deep");
    EXPECT_EQ(error_of(std::string(255, '[') + "[1,2]" + std::string(255, ']'), pack), "accepted");
    EXPECT_EQ(error_of(std::string(256, '[') + "[1,2]" + std::string(256, ']'), pack), "JSON: nesting too deep");
    EXPECT_EQ(error_of(std::string(128, '[') + R"({"a":)" + std::string(127, '[') + "1" + std::string(127, ']') + "}" +
                       std::string(128, ']'), pack), "accepted");
    EXPECT_EQ(error_of(std::string(100000, '['), pack), "JSON: nesting too deep");
    EXPECT_EQ(error_of(std::string(50000, '{'), pack), "JSON: syntax error: expected a member name at offset 1");
    std::string objects;
    for (int k = 0; k < 300; ++k) objects += R"({"a":)";
    EXPECT_EQ(error_of(objects, pack), "JSON: nesting too deep");
  }
}

TEST(Json, PositionsArePackedByTheCoordinateRule) {
  const Json two = parse_json("[[1, 2], [ 3 ,-4.5 ]]", true);
  EXPECT_TRUE(two.is_packed());
  EXPECT_EQ(two.width, 2u);
  EXPECT_TRUE(two.items.empty());
  EXPECT_EQ(two.packed, (std::vector<double>{1, 2, 3, -4.5}));
  const Json three = parse_json("[[0.1,-0,1e2],[2.5e-3,1152921504606846976,7]]", true);
  EXPECT_EQ(three.width, 3u);
  EXPECT_EQ(three.packed, (std::vector<double>{0.1, 0, 100, 0.0025, 1152921504606846976.0, 7}));
  EXPECT_TRUE(std::signbit(three.packed[1]));
  EXPECT_FALSE(parse_json("[[1,2],[3,4]]").is_packed());                 // only when asked
  EXPECT_FALSE(parse_json("[1,2]", true).is_packed());                  // a position alone is not packed
  EXPECT_TRUE(parse_json(R"({"c": [[1,2]]})", true).get("c")->is_packed());
  for (const std::string doc : {"[[]]", "[[1,2],[]]", "[[1,2],[3]]", "[[1,2],[3,4,5]]", R"([[1,2],[3,"a"]])",
                                "[[1,2],3]", "[[1,2],[[3,4]]]", "[[1,2],[3,null]]"}) {
    const Json j = parse_json(doc, true);
    EXPECT_FALSE(j.is_packed()) << doc;
    EXPECT_EQ(j.items.size(), 2u - (doc == "[[]]")) << doc;
  }
  // Rows packed before a position that does not fit are unpacked into numbers that read back the same.
  const Json mixed = parse_json("[[0.1,1152921504606846976],[3,4,5]]", true);
  ASSERT_EQ(mixed.items.size(), 2u);
  EXPECT_EQ(mixed.items[0].items[0].number(), 0.1);
  EXPECT_EQ(mixed.items[0].items[1].number(), 1152921504606846976.0);
  EXPECT_EQ(mixed.items[1].items[2].text, "5");
}

// A number the coordinate rule refuses is never packed: it stays as written, for the reader to refuse
// with the rule's reason; one beyond a double is refused by the parser.
TEST(Json, RefusedCoordinatesAreNotPacked) {
  for (const std::string n : {"9007199254740993", "1e-400", "-4.9e-324", "-18446744073709551617"}) {
    const Json j = parse_json("[[1,2],[0," + n + "]]", true);
    ASSERT_FALSE(j.is_packed()) << n;
    EXPECT_EQ(j.items[1].items[1].text, n);
    EXPECT_THROW(j.items[1].items[1].number(), JsonError) << n;
  }
  EXPECT_EQ(error_of("[[1,2],[0,1e400]]", true), "JSON: '1e400' is too large for a double at offset 10");
  EXPECT_EQ(error_of("[[1,2],[0,NaN]]", true), "JSON: syntax error: expected a value at offset 10");
  EXPECT_EQ(error_of("[[1,2],[0,01]]", true), "JSON: syntax error: invalid number at offset 10");
  EXPECT_EQ(error_of("[[1,2],[0,1.]]", true), "JSON: syntax error: invalid number at offset 10");
  EXPECT_EQ(error_of("[[1,2],[0,1]", true), "JSON: syntax error: unexpected end of input at offset 12");
  EXPECT_EQ(error_of("[[1,2],[0,1,]]", true), "JSON: syntax error: expected a value at offset 12");
}

}  // namespace
}  // namespace pd
