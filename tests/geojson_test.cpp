// Tests of the GeoJSON reader (madd::parse_geojson, include/madd/polygons.hpp)
// and of the JSON lexer under it (src/gis/json_lexer.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gis/json_lexer.hpp"
#include "madd/error.hpp"
#include "madd/polygons.hpp"

namespace {

using madd::GisPolygon;
using madd::GisRing;
using madd::Point;
using madd::PolygonSet;

PolygonSet parse(std::string_view text) { return madd::parse_geojson(text, "t.geojson"); }

madd::ParseError parse_error_of(std::string_view text) {
  try {
    parse(text);
  } catch (const madd::ParseError& e) {
    CHECK(e.path() == "t.geojson");
    CHECK(std::string(e.what()) ==
          "t.geojson:" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": " + e.message());
    return e;
  } catch (const madd::Error& e) {
    FAIL("expected a ParseError, got: " << e.what());
  }
  FAIL("expected a ParseError for: " << text);
  return madd::ParseError("", 0, 0, "");
}

// The message of the InvalidInputError the text gives.
std::string invalid_of(std::string_view text) {
  try {
    parse(text);
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == madd::InputProblem::other);
    CHECK(e.path() == "t.geojson");
    CHECK(e.line() == 0);
    return e.what();
  } catch (const madd::Error& e) {
    FAIL("expected an InvalidInputError, got: " << e.what());
  }
  FAIL("expected an InvalidInputError for: " << text);
  return "";
}

// " (line L, column C)" for the first occurrence of `token` in single-line text.
std::string at(std::string_view text, std::string_view token, std::size_t occurrence = 0) {
  std::size_t pos = text.find(token);
  for (std::size_t k = 0; k < occurrence; ++k) pos = text.find(token, pos + 1);
  REQUIRE(pos != std::string_view::npos);
  return " (line 1, column " + std::to_string(pos + 1) + ")";
}

const char* const square = "[[0,0],[1,0],[1,1],[0,1],[0,0]]";
const char* const hole = "[[0.25,0.25],[0.25,0.5],[0.5,0.5],[0.25,0.25]]";
const std::vector<Point> square_points{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const std::vector<Point> hole_points{{0.25, 0.25}, {0.25, 0.5}, {0.5, 0.5}};

std::string polygon(const std::string& rings) { return R"({"type":"Polygon","coordinates":[)" + rings + "]}"; }
std::string feature(const std::string& geometry, const std::string& properties = "null") {
  return R"({"type":"Feature","properties":)" + properties + R"(,"geometry":)" + geometry + "}";
}
std::string collection(const std::vector<std::string>& features) {
  std::string text = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < features.size(); ++i) text += (i ? "," : "") + features[i];
  return text + "]}";
}

GisPolygon expected_polygon(std::vector<std::vector<Point>> rings, std::uint32_t feature = 0,
                            std::uint32_t polygon_index = 0, int marker = 1) {
  GisPolygon p;
  p.outer = {rings[0], 0};
  for (std::uint32_t r = 1; r < rings.size(); ++r) p.holes.push_back({rings[r], r});
  p.feature = feature;
  p.polygon = polygon_index;
  p.marker = marker;
  return p;
}

std::string shortest(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

double signed_area(const std::vector<Point>& ring) {
  double s = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k], b = ring[(k + 1) % ring.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return 0.5 * s;
}

}  // namespace

TEST_SUITE("geojson") {

TEST_CASE("a bare Polygon: the closing vertex dropped, holes in order, lon/lat") {
  const PolygonSet set = parse(polygon(std::string(square) + "," + hole));
  CHECK(set.coordinates == madd::Coordinates::lonlat);
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0] == expected_polygon({square_points, hole_points}));
  CHECK(set.polygons[0].holes[0].source == 1);
}

TEST_CASE("a bare MultiPolygon numbers its polygons; an empty polygon is skipped but counted") {
  const std::string text =
      std::string(R"({"type":"MultiPolygon","coordinates":[[)") + square + "],[],[" + square + "," + hole + "]]}";
  const PolygonSet set = parse(text);
  REQUIRE(set.polygons.size() == 2);
  CHECK(set.polygons[0] == expected_polygon({square_points}, 0, 0));
  CHECK(set.polygons[1] == expected_polygon({square_points, hole_points}, 0, 2));
  CHECK(parse(R"({"type":"Polygon","coordinates":[]})").polygons.empty());
  CHECK(parse(R"({"type":"MultiPolygon","coordinates":[]})").polygons.empty());
}

TEST_CASE("a FeatureCollection: features counted in file order, skipped ones too") {
  const std::string text = collection({
      feature(R"({"type":"Point","coordinates":[1,2]})"),
      feature("null"),
      feature(polygon(square)),
      feature(R"({"type":"LineString","coordinates":[[1,2],[3,4]]})", R"({"marker":7})"),
      feature(R"({"type":"MultiPoint","coordinates":[]})"),
      feature(R"({"type":"MultiLineString","coordinates":[[[1,2],[3,4]]]})"),
      feature(R"({"type":"MultiPolygon","coordinates":[[)" + std::string(square) + "],[" + square + "]]}",
              R"({"marker":-4,"name":"x"})"),
  });
  const PolygonSet set = parse(text);
  REQUIRE(set.polygons.size() == 3);
  CHECK(set.polygons[0] == expected_polygon({square_points}, 2, 0, 1));
  CHECK(set.polygons[1] == expected_polygon({square_points}, 6, 0, -4));
  CHECK(set.polygons[2] == expected_polygon({square_points}, 6, 1, -4));
  CHECK(parse(R"({"type":"FeatureCollection","features":[]})").polygons.empty());
}

TEST_CASE("a bare Feature; properties may be null or missing") {
  PolygonSet set = parse(feature(polygon(square), R"({"marker":2})"));
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0] == expected_polygon({square_points}, 0, 0, 2));
  set = parse(R"({"type":"Feature","geometry":)" + polygon(square) + "}");
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].marker == 1);
  CHECK(parse(feature("null")).polygons.empty());
}

TEST_CASE("GeometryCollections: a bare one's members stand for features; inside a feature polygons count on") {
  const std::string members = "[" + polygon(square) + R"(,{"type":"Point","coordinates":[0,0]},)" +
                              R"({"type":"MultiPolygon","coordinates":[[)" + square + "],[" + square + "]]}," +
                              R"({"type":"GeometryCollection","geometries":[)" + polygon(square) + "]}]";
  PolygonSet set = parse(R"({"type":"GeometryCollection","geometries":)" + members + "}");
  REQUIRE(set.polygons.size() == 4);
  CHECK(set.polygons[0] == expected_polygon({square_points}, 0, 0));
  CHECK(set.polygons[1] == expected_polygon({square_points}, 2, 0));
  CHECK(set.polygons[2] == expected_polygon({square_points}, 2, 1));
  CHECK(set.polygons[3] == expected_polygon({square_points}, 3, 0));
  set = parse(collection(
      {feature("null"), feature(R"({"type":"GeometryCollection","geometries":)" + members + "}", R"({"marker":5})")}));
  REQUIRE(set.polygons.size() == 4);
  for (std::uint32_t i = 0; i < 4; ++i) CHECK(set.polygons[i] == expected_polygon({square_points}, 1, i, 5));
  CHECK(parse(R"({"type":"GeometryCollection","geometries":[]})").polygons.empty());
}

TEST_CASE("members in any order read alike: type last, properties after geometry") {
  const std::string geometry_members[] = {R"("type":"Polygon")", std::string(R"("coordinates":[)") + square + "]",
                                          R"("bbox":[0,0,1,1])"};
  const std::string reference_text = collection({feature(polygon(square), R"({"marker":9})")});
  const PolygonSet reference = parse(reference_text);
  REQUIRE(reference.polygons.size() == 1);
  CHECK(reference.polygons[0].marker == 9);
  std::vector<int> g{0, 1, 2};
  do {
    const std::string geometry =
        "{" + geometry_members[g[0]] + "," + geometry_members[g[1]] + "," + geometry_members[g[2]] + "}";
    std::vector<std::string> feature_members{R"("type":"Feature")", R"("properties":{"marker":9})",
                                             R"("geometry":)" + geometry, R"("id":17)"};
    std::sort(feature_members.begin(), feature_members.end());
    do {
      std::string text = R"({"features":[{)";
      for (std::size_t i = 0; i < feature_members.size(); ++i) text += (i ? "," : "") + feature_members[i];
      text += R"(}],"type":"FeatureCollection"})";
      CAPTURE(text);
      CHECK(parse(text) == reference);
    } while (std::next_permutation(feature_members.begin(), feature_members.end()));
  } while (std::next_permutation(g.begin(), g.end()));
}

TEST_CASE("foreign members, bbox, crs and members of other objects' kinds are ignored") {
  const std::string text =
      R"({"type":"FeatureCollection","bbox":[0,0,1,1],"crs":{"type":"name","properties":{"name":"x"}},)"
      R"("geometry":"ignored","coordinates":{"a":[1,{}]},"features":[{"type":"Feature","id":"f1",)"
      R"("coordinates":"not read","features":null,"properties":{"nested":{"marker":"no"},"markers":true},)"
      R"("geometry":{"type":"Polygon","geometries":7,"properties":1,"coordinates":[)" +
      std::string(square) + R"(],"extra":[true,false,null,-0.5e-3,"s"]}}],"foreign":{}})";
  const PolygonSet set = parse(text);
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0] == expected_polygon({square_points}));
}

TEST_CASE("positions: an altitude is dropped; the extreme longitudes and latitudes are accepted") {
  const PolygonSet set = parse(polygon("[[-180,-90,5],[180,-90,-1e300],[180,90],[-180,90,0],[-180,-90,2.5]]"));
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points == std::vector<Point>{{-180, -90}, {180, -90}, {180, 90}, {-180, 90}});
}

TEST_CASE("consecutive duplicates and touching rings are kept as the file has them") {
  const PolygonSet set = parse(polygon("[[0,0],[1,0],[1,0],[1,1],[0,0]],[[0,0],[0.5,0.2],[0.5,0.1],[0,0]]"));
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points == std::vector<Point>{{0, 0}, {1, 0}, {1, 0}, {1, 1}});
  CHECK(set.polygons[0].holes[0].points == std::vector<Point>{{0, 0}, {0.5, 0.2}, {0.5, 0.1}});
}

TEST_CASE("white space, CRLF and a byte order mark are allowed") {
  const std::string text = "\xef\xbb\xbf \r\n\t{ \"type\" : \"Polygon\" ,\r\n \"coordinates\" : [ [ [ 0 , 0 ] ,"
                           "\n[1,0] , [1,1],[0,1],\t[0,0] ] ] }\r\n\n ";
  const PolygonSet set = parse(text);
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points == square_points);
  // Columns count from the first byte after the mark.
  const madd::ParseError e = parse_error_of("\xef\xbb\xbfx");
  CHECK(e.line() == 1);
  CHECK(e.column() == 1);
}

TEST_CASE("the marker property: integers of any spelling, null as absent, applied to every polygon") {
  auto marker_of = [](const std::string& value) {
    const PolygonSet set = parse(feature(polygon(square), R"({"marker":)" + value + "}"));
    REQUIRE(set.polygons.size() == 1);
    return set.polygons[0].marker;
  };
  CHECK(marker_of("3") == 3);
  CHECK(marker_of("-12") == -12);
  CHECK(marker_of("0") == 0);
  CHECK(marker_of("3.0") == 3);
  CHECK(marker_of("4e0") == 4);
  CHECK(marker_of("2.5e1") == 25);
  CHECK(marker_of("-0") == 0);
  CHECK(marker_of("2147483647") == std::numeric_limits<int>::max());
  CHECK(marker_of("-2147483648") == std::numeric_limits<int>::min());
  CHECK(marker_of("null") == 1);
  // A name spelled with escapes is the same name.
  const PolygonSet set = parse(feature(polygon(square), R"({"\u006darker":6})"));
  CHECK(set.polygons[0].marker == 6);
}

TEST_CASE("unicode: escapes and raw UTF-8 in names and values") {
  // "type" with an escape, a surrogate pair, raw 2-, 3- and 4-byte characters.
  const std::string text = "{\"typ\\u0065\":\"\\u0050olygon\",\"name\\ud83c\\udf0a\":\"Baie synth\xc3\xa9tique "
                           "\xe6\xb5\xb7 \xf0\x9f\x8c\x8a \\\" \\\\ \\/ \\b\\f\\n\\r\\t\",\"coordinates\":[" +
                           std::string(square) + "]}";
  const PolygonSet set = parse(text);
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points == square_points);
}

TEST_CASE("the lexer unescapes strings to UTF-8 and reads numbers as from_chars does") {
  madd::detail::JsonLexer json(R"(["a\u00e9\u6d77\ud83c\udf0a\u0000z", 0.1, -0, 1e400, -1e400, 1e-400, 5e-324,)"
                               R"( 123456789012345678901234567890, 0.30000000000000004])",
                               "x.json");
  json.begin_array();
  REQUIRE(json.next_element());
  std::string s;
  json.string(s);
  CHECK(s == std::string("a\xc3\xa9\xe6\xb5\xb7\xf0\x9f\x8c\x8a\0z", 12));
  const double expected[] = {0.1,
                             -0.0,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             0.0,
                             5e-324,
                             1.2345678901234568e29,
                             0.30000000000000004};
  for (const double e : expected) {
    REQUIRE(json.next_element());
    const double v = json.number();
    CAPTURE(json.number_text());
    CHECK(v == e);
    CHECK(std::signbit(v) == std::signbit(e));
  }
  CHECK(!json.next_element());
  json.finish();
}

TEST_CASE("the lexer's marks: a value read again from its mark reads the same") {
  madd::detail::JsonLexer json(R"({"a":[1,[2,{"b":3}]],"c":"x"})", "x.json");
  json.begin_object();
  std::string name;
  REQUIRE(json.next_member(name));
  CHECK(name == "a");
  const madd::detail::JsonMark mark = json.mark();
  json.skip_value();
  REQUIRE(json.next_member(name));
  CHECK(name == "c");
  json.skip_value();
  CHECK(!json.next_member(name));
  const madd::detail::JsonMark end = json.mark();
  json.restore(mark);
  json.begin_array();
  REQUIRE(json.next_element());
  CHECK(json.number() == 1.0);
  REQUIRE(json.next_element());
  CHECK(json.peek() == madd::detail::JsonType::array);
  json.skip_value();
  CHECK(!json.next_element());
  json.restore(end);
  json.finish();
}

TEST_CASE("numbers round-trip exactly, in shortest and in 17-digit form") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> lon(-180.0, 180.0), lat(-90.0, 90.0);
  std::vector<Point> ring;
  for (int k = 0; k < 500; ++k) ring.push_back({lon(rng), lat(rng)});
  ring.push_back({std::nextafter(180.0, 0.0), -std::numeric_limits<double>::denorm_min()});
  ring.push_back({1e-300, 4.9406564584124654e-324});
  for (int form = 0; form < 2; ++form) {
    std::string text = R"({"type":"Polygon","coordinates":[[)";
    for (std::size_t k = 0; k <= ring.size(); ++k) {
      const Point p = ring[k % ring.size()];
      char buffer[64];
      if (form == 0) {
        text += "[" + shortest(p.x) + "," + shortest(p.y) + "],";
      } else {
        std::snprintf(buffer, sizeof buffer, "[%.17g,%.17g],", p.x, p.y);
        text += buffer;
      }
    }
    text.back() = ']';
    text += "]}";
    const PolygonSet set = parse(text);
    REQUIRE(set.polygons.size() == 1);
    CHECK(set.polygons[0].outer.points == ring);
  }
}

TEST_CASE("huge and long numbers") {
  // Out of a double's range: refused as a coordinate, fine where ignored.
  CHECK(parse(R"({"type":"Polygon","bbox":[1e400,-1e99999999999999999999],"coordinates":[]})").polygons.empty());
  const std::string digits(2000, '7');
  PolygonSet set = parse(polygon("[[0.000" + digits + ",0],[1,0],[1,1],[0.000" + digits + ",0]]"));
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points[0].x == 7.0 / 9000.0);  // division rounds correctly too
  set = parse(polygon("[[1e-400,0],[1,0],[1,1],[0,0]]"));    // below a double's range: zero, closing the ring
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points[0] == Point{0, 0});
  const std::string text = polygon("[[0,0],[1e400,0],[1,1],[0,0]]");
  CHECK(invalid_of(text) ==
        "t.geojson: ring 0, vertex 1: longitude 1e400 is beyond the range of a double" + at(text, "1e400"));
  const std::string text2 = polygon("[[0,0],[1,0,-1" + digits + "],[1,1],[0,0]]");
  CHECK(invalid_of(text2) == "t.geojson: ring 0, vertex 1: altitude -1" + std::string(38, '7') +
                                 "... is beyond the range of a double" + at(text2, "-1"));
}

TEST_CASE("malformed JSON: ParseError with line and column") {
  struct Case {
    std::string text;
    std::size_t line;
    std::size_t column;
    const char* message;
  };
  const Case cases[] = {
      {"", 1, 1, "unexpected end of text: expected a value"},
      {"  \n  ", 2, 3, "unexpected end of text: expected a value"},
      {"{\"type\":\"Polygon\",}", 1, 19, "expected a member name (a string), got '}'"},
      {"[1,2,]", 1, 6, "expected a value, got ']'"},
      {"[1 2]", 1, 4, "expected ',' or ']', got '2'"},
      {"{\"a\" 1}", 1, 6, "expected ':' after the member name, got '1'"},
      {"{\"a\":1 \"b\":2}", 1, 8, "expected ',' or '}', got '\"'"},
      {"[01]", 1, 2, "a number may not start with the digit 0 followed by digits"},
      {"[+1]", 1, 2, "expected a value, got '+'"},
      {"[-]", 1, 3, "expected a digit, got ']'"},
      {"[1.]", 1, 4, "expected a digit after the decimal point, got ']'"},
      {"[.5]", 1, 2, "expected a value, got '.'"},
      {"[1e]", 1, 4, "expected a digit in the exponent, got ']'"},
      {"[NaN]", 1, 2, "expected a value, got 'N'"},
      {"[nan]", 1, 2, "invalid literal: expected 'null'"},
      {"[Infinity]", 1, 2, "expected a value, got 'I'"},
      {"[tru]", 1, 2, "invalid literal: expected 'true'"},
      {"['a']", 1, 2, "expected a value, got '''"},
      {"// c\n{}", 1, 1, "expected a value, got '/'"},
      {"{}\n/* c */", 2, 1, "unexpected '/' after the end of the JSON value"},
      {"{} {}", 1, 4, "unexpected '{' after the end of the JSON value"},
      {"[\"abc", 1, 6, "unexpected end of text in a string"},
      {"[\"a\tb\"]", 1, 4, "control character byte 0x09 in a string (write it as an escape)"},
      {"[\"a\nb\"]", 1, 4, "control character byte 0x0a in a string (write it as an escape)"},
      {"[\"\\x\"]", 1, 3, "invalid escape \\x in a string"},
      {"[\"\\u12G4\"]", 1, 7, "expected 4 hexadecimal digits after \\u, got 'G'"},
      {"[\"\\udc00\"]", 1, 3, "unpaired low surrogate in a \\u escape"},
      {"[\"\\ud800\"]", 1, 3, "high surrogate not followed by a \\u low surrogate"},
      {"[\"\\ud800\\u0041\"]", 1, 3, "high surrogate not followed by a \\u low surrogate"},
      {"[\"\xc0\x80\"]", 1, 3, "invalid UTF-8 in a string (byte 0xc0)"},
      {"[\"\xe0\x80\x80\"]", 1, 3, "invalid UTF-8 in a string (byte 0x80 after byte 0xe0)"},
      {"[\"\xed\xa0\x80\"]", 1, 3, "invalid UTF-8 in a string (byte 0xa0 after byte 0xed)"},
      {"[\"\xf4\x90\x80\x80\"]", 1, 3, "invalid UTF-8 in a string (byte 0x90 after byte 0xf4)"},
      {"[\"\xf5\x80\x80\x80\"]", 1, 3, "invalid UTF-8 in a string (byte 0xf5)"},
      {"[\"\xc3\"]", 1, 3, "invalid UTF-8 in a string ('\"' after byte 0xc3)"},
      {"[\"\xc3", 1, 3, "unexpected end of text in a UTF-8 character"},
      {"\xc3\xa9", 1, 1, "expected a value, got byte 0xc3"},
      {"{\"type\":1,\n \"t\\u0079pe\":2}", 2, 2, "repeated member name \"type\" in one object"},
      {"{\"a\":{\"a\":1},\"b\":[{\"a\":1,\"a\":2}]}", 1, 26, "repeated member name \"a\" in one object"},
      {std::string("[\"a\0b\"]", 7), 1, 4, "control character byte 0x00 in a string (write it as an escape)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    const madd::ParseError e = parse_error_of(c.text);
    CHECK(e.message() == c.message);
    CHECK(e.line() == c.line);
    CHECK(e.column() == c.column);
  }
}

TEST_CASE("repeated names are found in objects of many members too") {
  std::string text = R"({"type":"Polygon","coordinates":[],)";
  for (int k = 0; k < 1000; ++k) text += "\"m" + std::to_string(k) + "\":" + std::to_string(k) + ",";
  CHECK(parse(text + R"("last":0})").polygons.empty());
  const madd::ParseError e = parse_error_of(text + R"("m512":0})");
  CHECK(e.message() == "repeated member name \"m512\" in one object");
  // A large object, then small ones at the same depth: each starts afresh.
  std::string many = R"({"type":"Polygon","coordinates":[],"a":[)";
  std::string big = "{";
  for (int k = 0; k < 100; ++k) big += (k ? ",\"" : "\"") + std::to_string(k) + "\":0";
  many += big + "}";
  for (int k = 0; k < 1000; ++k) many += R"(,{"1":0,"2":0})";
  CHECK(parse(many + "]}").polygons.empty());
}

TEST_CASE("nesting: 64 levels are read, 65 refused, a million refused quickly") {
  auto nested = [](std::size_t levels) {
    // The object, and a foreign member holding levels - 1 arrays.
    const std::size_t extra = levels - 1;
    return R"({"type":"Polygon","coordinates":[],"x":)" + std::string(extra, '[') + std::string(extra, ']') + "}";
  };
  CHECK(parse(nested(64)).polygons.empty());
  madd::ParseError e = parse_error_of(nested(65));
  CHECK(e.message() == "nesting deeper than 64 levels");
  CHECK(e.column() == std::string(R"({"type":"Polygon","coordinates":[],"x":)").size() + 64);  // the 64th '['
  e = parse_error_of(std::string(1000000, '['));
  CHECK(e.column() == 65);
  e = parse_error_of("{\"a\":" + std::string(1000000, '{'));
  CHECK(e.message() == "expected a member name (a string), got '{'");
  // Deep where coordinates are expected: the same limit.
  const std::string deep =
      R"({"type":"MultiPolygon","coordinates":)" + std::string(70, '[') + std::string(70, ']') + "}";
  e = parse_error_of(deep);
  CHECK(e.message() == "nesting deeper than 64 levels");
}

TEST_CASE("not GeoJSON: InvalidInputError naming the place in the file's arrays") {
  struct Case {
    std::string text;
    std::string location;  // the message's start, after the path
    std::string token;     // where line and column point
    std::size_t occurrence;
  };
  const std::string sq(square);
  const std::string with_feature = R"({"type":"FeatureCollection","features":[{"type":"Feature","geometry":null},)";
  const Case cases[] = {
      {"[1,2]", "a GeoJSON text must be an object, got an array", "[", 0},
      {"{\"coordinates\":[]}", "the object has no \"type\" member", "{", 0},
      {"{\"type\":7}", "\"type\" must be a string, got a number", "7", 0},
      {"{\"type\":\"polygon\",\"coordinates\":[]}", "unknown GeoJSON type \"polygon\"", "\"polygon\"", 0},
      {"{\"type\":\"Topology\"}", "unknown GeoJSON type \"Topology\"", "\"Topology\"", 0},
      {"{\"type\":\"FeatureCollection\"}", "a FeatureCollection must have a \"features\" member", "{", 0},
      {"{\"type\":\"FeatureCollection\",\"features\":{}}", "\"features\" must be an array, got an object", "{", 1},
      {with_feature + "7]}", "feature 1: a feature must be an object, got a number", "7", 0},
      {with_feature + polygon(sq) + "]}", "feature 1: a member of \"features\" must be a Feature, got type \"Polygon\"",
       "\"Polygon\"", 0},
      {with_feature + "{\"type\":\"Feature\"}]}", "feature 1: a Feature must have a \"geometry\" member", "{", 2},
      {with_feature + "{\"type\":\"Feature\",\"geometry\":[]}]}",
       "feature 1: \"geometry\" must be an object or null, got an array", "[]", 0},
      {with_feature + "{\"type\":\"Feature\",\"geometry\":{\"type\":\"Feature\"}}]}",
       "feature 1: expected a geometry, got type \"Feature\"", "\"Feature\"", 2},
      {with_feature + "{\"type\":\"Feature\",\"properties\":[],\"geometry\":null}]}",
       "feature 1: \"properties\" must be an object or null, got an array", "[]", 0},
      {"{\"type\":\"Polygon\"}", "a geometry must have a \"coordinates\" member", "{", 0},
      {"{\"type\":\"Point\"}", "a geometry must have a \"coordinates\" member", "{", 0},
      {"{\"type\":\"GeometryCollection\"}", "a GeometryCollection must have a \"geometries\" member", "{", 0},
      {"{\"type\":\"GeometryCollection\",\"geometries\":[" + polygon(sq) + ",null]}",
       "geometry 1: a member of \"geometries\" must be an object, got null", "null", 0},
      {"{\"type\":\"Polygon\",\"coordinates\":{}}",
       "the coordinates of a polygon must be an array of rings, got an object", "{", 1},
      {"{\"type\":\"MultiPolygon\",\"coordinates\":[" + sq + "]}",
       "polygon 0, ring 0, vertex 0: a position must be an array of 2 or 3 numbers, got a number", "0", 0},
      {"{\"type\":\"MultiPolygon\",\"coordinates\":[[" + sq + "]," + sq + "]}",
       "polygon 1, ring 0, vertex 0: a position must be an array of 2 or 3 numbers, got a number", "0", 6},
      {polygon("\"ring\""), "ring 0: a ring must be an array of positions, got a string", "\"ring\"", 0},
      {polygon(sq + ",[[0,0],[1,1],[0,0]]"),
       "ring 1: a ring needs at least 4 positions (the last repeating the first), "
       "this one has 3",
       "[[0,0],[1,1]", 0},
      {polygon("[]"), "ring 0: a ring needs at least 4 positions (the last repeating the first), this one has 0", "[]",
       0},
      {polygon("[[0,0],[1,0],[1,1],[0,1e-300]]"),
       "ring 0, vertex 3: the ring is not closed: its last position differs from its first (vertex 0)", "[0,1e-300]",
       0},
      {polygon("[[0,0],[1,0],[1,1],{},[0,0]]"),
       "ring 0, vertex 3: a position must be an array of 2 or 3 numbers, got an object", "{}", 0},
      {polygon("[[0,0],[1,0],[1],[0,0]]"),
       "ring 0, vertex 2: a position needs a longitude and a latitude, this one has 1 numbers", "[1]", 0},
      {polygon("[[0,0],[1,0],[],[0,0]]"),
       "ring 0, vertex 2: a position needs a longitude and a latitude, this one has 0 numbers", "[]", 0},
      {polygon("[[0,0],[1,0],[1,1,0,7],[0,0]]"),
       "ring 0, vertex 2: a position has more than 3 numbers (longitude, latitude, altitude)", "7", 0},
      {polygon("[[0,0],[1,\"0\"],[1,1],[0,0]]"), "ring 0, vertex 1: a position must hold numbers only, got a string",
       "\"0\"", 0},
      {polygon("[[0,0],[1,null],[1,1],[0,0]]"), "ring 0, vertex 1: a position must hold numbers only, got null", "null",
       0},
      {polygon("[[0,0],[180.000001,0],[1,1],[0,0]]"),
       "ring 0, vertex 1: longitude 180.000001 is outside [-180, 180] (GeoJSON is longitude and latitude in degrees, "
       "RFC 7946: is this a projected file?)",
       "180", 0},
      {polygon(sq + ",[[0,0],[0,-90.5],[1,1],[0,0]]"),
       "ring 1, vertex 1: latitude -90.5 is outside [-90, 90] (GeoJSON is longitude and latitude in degrees, RFC 7946: "
       "is this a projected file?)",
       "-90.5", 0},
      {polygon("[[0,0],[500000.5,4800000],[1,1],[0,0]]"),
       "ring 0, vertex 1: longitude 500000.5 is outside [-180, 180] (GeoJSON is longitude and latitude in degrees, "
       "RFC 7946: is this a projected file?)",
       "500000.5", 0},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    CHECK(invalid_of(c.text) == "t.geojson: " + c.location + at(c.text, c.token, c.occurrence));
  }
}

TEST_CASE("the error carries the path and, for an open ring, its first and last positions") {
  try {
    madd::parse_geojson(polygon("[[0,0],[1,0],[1,1],[0,1e-300]]"));
    FAIL("an open ring was accepted");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.path() == "<memory>");
    CHECK(e.points() == std::vector<Point>{{0, 0}, {0, 1e-300}});
    CHECK(std::string(e.what()).starts_with("<memory>: ring 0, vertex 3: the ring is not closed"));
    CHECK(e.kind() == madd::ErrorKind::bad_input);
  }
}

TEST_CASE("locations name every array on the way down") {
  const std::string bad_ring = "[[0,0],[1,0],[1,1],[0,95],[0,0]]";
  // A feature's MultiPolygon.
  std::string text =
      collection({feature("null"), feature(R"({"type":"MultiPolygon","coordinates":[[)" + std::string(square) + "],[" +
                                           square + "," + hole + "," + bad_ring + "]]}")});
  CHECK(invalid_of(text) == "t.geojson: feature 1, polygon 1, ring 2, vertex 3: latitude 95 is outside [-90, 90] "
                            "(GeoJSON is longitude and latitude in degrees, RFC 7946: is this a projected file?)" +
                                at(text, "95"));
  // A GeometryCollection in a feature, a nested one in it.
  const std::string inner = R"({"type":"GeometryCollection","geometries":[{"type":"Point","coordinates":[0,0]},)" +
                            polygon(std::string(square) + "," + bad_ring) + "]}";
  text = collection({feature(R"({"type":"GeometryCollection","geometries":[)" + polygon(square) + "," + inner + "]}")});
  CHECK(invalid_of(text).starts_with("t.geojson: feature 0, geometry 1, geometry 1, ring 1, vertex 3: latitude 95 "));
  // A bare Feature has no feature index; the marker's location.
  text = feature(polygon(square), R"({"marker":2.5})");
  CHECK(invalid_of(text) ==
        "t.geojson: property \"marker\" must be an integer in the range of int, got 2.5" + at(text, "2.5"));
  text = collection({feature(polygon(square)), feature(polygon(square), R"({"name":"a","marker":"3"})")});
  CHECK(invalid_of(text) ==
        "t.geojson: feature 1: property \"marker\" must be an integer, got a string" + at(text, "\"3\""));
  for (const char* value : {"true", "[3]", "{}", "1e10", "-2147483649", "3.000001", "1e400"}) {
    text = collection({feature(polygon(square), std::string(R"({"marker":)") + value + "}")});
    CAPTURE(text);
    CHECK(invalid_of(text).starts_with("t.geojson: feature 0: property \"marker\" must be an integer"));
  }
}

TEST_CASE("line and column: of the offending value, also when it was read after a later \"type\"") {
  const std::string text = "{\"features\": [\n"
                           "  {\"geometry\": {\"coordinates\": [[[0, 0], [1, 0],\n"
                           "      [1, 1], [0, 91], [0, 0]]],\n"
                           "    \"type\": \"Polygon\"}, \"type\": \"Feature\"}\n"
                           "], \"type\": \"FeatureCollection\"}\n";
  CHECK(invalid_of(text) ==
        "t.geojson: feature 0, ring 0, vertex 3: latitude 91 is outside [-90, 90] (GeoJSON is "
        "longitude and latitude in degrees, RFC 7946: is this a projected file?) (line 3, column 19)");
  // Malformed JSON after the first GeoJSON problem is still a ParseError, deferred or not.
  const madd::ParseError e = parse_error_of(text.substr(0, text.size() - 2) + ",}");
  CHECK(e.line() == 5);
  CHECK(e.column() == 32);
  CHECK(parse_error_of(polygon("[]") + "x").column() == polygon("[]").size() + 1);
  CHECK(parse_error_of(R"({"type":"Polygon","coordinates":[[[0,0]]],"x":[1,]})").column() == 50);
}

TEST_CASE("every truncation of a valid file is a ParseError") {
  const std::string full = collection({
      feature(polygon(std::string(square) + "," + hole), "{\"marker\":3,\"n\\u00e9\":\"\xc3\xa9\\ud83c\\udf0a\"}"),
      feature("null"),
      feature(R"({"type":"MultiPolygon","coordinates":[[[[-1.5e1,2E-2,3],[0.25,-0],[1,1],[-1.5e1,2E-2]]]]})"),
      feature(R"({"type":"LineString","coordinates":[[1,2],[3,4]],"bbox":[true,false,null]})"),
  });
  REQUIRE(parse(full).polygons.size() == 2);
  for (std::size_t cut = 0; cut < full.size(); ++cut) {
    CAPTURE(cut);
    try {
      parse(full.substr(0, cut));
      FAIL("a truncated text was accepted");
    } catch (const madd::ParseError& e) {
      CHECK(e.line() == 1);
    } catch (const madd::Error& e) {
      FAIL("not a ParseError: " << e.what());
    }
  }
}

TEST_CASE("a round trip: random polygons written as GeoJSON read back exactly") {
  std::mt19937_64 rng(2024);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto coordinate = [&](double limit) {
    switch (integer(0, 5)) {
    case 0:
      return static_cast<double>(integer(-static_cast<int>(limit), static_cast<int>(limit)));
    case 1:
      return limit * (integer(0, 1) ? 1 : -1);
    case 2:
      return uniform(-1e-6, 1e-6);
    default:
      return uniform(-limit, limit);
    }
  };
  for (int trial = 0; trial < 40; ++trial) {
    PolygonSet expected;
    std::string text = R"({"type":"FeatureCollection","features":[)";
    const int n_features = integer(0, 6);
    for (int f = 0; f < n_features; ++f) {
      const int marker = integer(-3, 9);
      const int n_polygons = integer(1, 3);
      const bool multi = n_polygons > 1 || integer(0, 1);
      std::string coordinates;
      for (int p = 0; p < n_polygons; ++p) {
        std::vector<std::vector<Point>> rings(static_cast<std::size_t>(integer(1, 4)));
        std::string polygon_text;
        for (auto& ring : rings) {
          for (int v = integer(3, 12); v > 0; --v) ring.push_back({coordinate(180), coordinate(90)});
          std::string ring_text;
          for (std::size_t v = 0; v <= ring.size(); ++v) {
            const Point q = ring[v % ring.size()];
            ring_text += (v ? ", [" : "[") + shortest(q.x) + "," + shortest(q.y) +
                         (integer(0, 3) == 0 ? "," + shortest(uniform(-10, 10)) : "") + "]";
          }
          polygon_text += (polygon_text.empty() ? "[" : ",\n[") + ring_text + "]";
        }
        coordinates += (p ? ",[" : "[") + polygon_text + "]";
        expected.polygons.push_back(
            expected_polygon(rings, static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(p), marker));
      }
      const std::string geometry = multi ? R"({"type":"MultiPolygon","coordinates":[)" + coordinates + "]}"
                                         : R"({"type":"Polygon","coordinates":)" + coordinates + "}";
      text += (f ? ",\n" : "") + feature(geometry, R"({"marker":)" + std::to_string(marker) + "}");
    }
    text += "]}";
    CAPTURE(text);
    CHECK(parse(text) == expected);
  }
}

TEST_CASE("data/coast/bay.geojson: the sea with its 300 islands, the lake, two skipped features") {
  std::ifstream in(std::string(MADD_DATA_DIR) + "/coast/bay.geojson", std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  const PolygonSet set = madd::parse_geojson(s.str(), "bay.geojson");
  REQUIRE(set.polygons.size() == 2);
  const GisPolygon& sea = set.polygons[0];
  const GisPolygon& lake = set.polygons[1];
  CHECK(sea.feature == 0);
  CHECK(sea.marker == 1);
  CHECK(lake.feature == 1);
  CHECK(lake.marker == 3);
  CHECK(lake.holes.empty());
  CHECK(lake.outer.points.size() == 40);
  CHECK(sea.holes.size() == 300);
  // The outer ring: the box's bottom corners, then the coast east to west,
  // 1801 samples less those cut for the fjords, plus the fjords' banks.
  CHECK(sea.outer.points[0] == Point{-70.2, 43.3});
  CHECK(sea.outer.points[1] == Point{-69.3, 43.3});
  CHECK(sea.outer.points.back().x == -70.2);
  CHECK(signed_area(sea.outer.points) > 0.0);
  CHECK(signed_area(lake.outer.points) > 0.0);
  std::size_t clockwise = 0, duplicates = 0, specks = 0;
  std::map<std::pair<double, double>, std::set<std::size_t>> owners;  // vertex -> the islands having it
  for (std::size_t h = 0; h < sea.holes.size(); ++h) {
    const auto& ring = sea.holes[h].points;
    CHECK(sea.holes[h].source == h + 1);
    CHECK(ring.size() >= 6);
    CHECK(ring.size() <= 21);
    if (signed_area(ring) < 0.0) ++clockwise;
    double r2 = 0.0;  // the island's squared extent in metres
    for (std::size_t k = 0; k < ring.size(); ++k) {
      if (ring[k] == ring[(k + 1) % ring.size()]) ++duplicates;
      const double dx = (ring[k].x - ring[0].x) * 80500.0, dy = (ring[k].y - ring[0].y) * 111000.0;
      r2 = std::max(r2, dx * dx + dy * dy);
      CHECK(ring[k].x > -70.2);
      CHECK(ring[k].x < -69.3);
      CHECK(ring[k].y > 43.3);
      owners[{ring[k].x, ring[k].y}].insert(h);
    }
    if (r2 < 10.0 * 10.0) ++specks;
  }
  CHECK(clockwise == 294);
  CHECK(duplicates == 1);
  CHECK(specks == 5);
  std::size_t shared = 0;
  for (const auto& [vertex, islands] : owners) shared += islands.size() > 1;
  CHECK(shared == 3);  // the three touching pairs
  std::size_t on_coast = 0;
  const std::set<std::pair<double, double>> coast_vertices = [&] {
    std::set<std::pair<double, double>> out;
    for (const Point& p : sea.outer.points) out.insert({p.x, p.y});
    return out;
  }();
  for (const auto& [vertex, islands] : owners) on_coast += coast_vertices.count(vertex) * islands.size();
  CHECK(on_coast == 1);
}

}  // TEST_SUITE("geojson")
