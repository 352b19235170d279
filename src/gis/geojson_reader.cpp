// Reader for GeoJSON water polygons (RFC 7946; include/madd/polygons.hpp).
//
// One pass over the text with the JSON pull lexer: coordinates go straight
// into the rings' vectors, nothing else is kept. What is accepted: a
// FeatureCollection, a Feature or a bare geometry at the top; Polygon and
// MultiPolygon geometries, also inside GeometryCollections; other geometry
// types, null geometries and empty polygons are skipped; "bbox", "id" and
// foreign members are read as JSON and ignored. A feature's "properties"
// may be missing (as null); its "geometry" may not (RFC 7946, 3.2).
//
// Numbering (GisPolygon, 0-based): feature is the index in "features" (or,
// for a bare GeometryCollection, in its "geometries"; 0 for a bare Feature
// or geometry); polygon counts the polygons of that feature in file order
// (its index in a MultiPolygon, 0 for a Polygon, counting on through a
// GeometryCollection's members); GisRing::source is the ring's index in its
// polygon. Messages instead name every array index on the way down
// ("feature 3, geometry 1, polygon 0, ring 2, vertex 7"), as in the file.
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "gis/json_lexer.hpp"
#include "madd/error.hpp"
#include "madd/polygons.hpp"

namespace madd {
namespace {

using detail::JsonLexer;
using detail::JsonMark;
using detail::JsonPosition;
using detail::JsonType;

enum class GeoType : std::uint8_t {
  feature_collection,
  feature,
  point,
  multi_point,
  line_string,
  multi_line_string,
  polygon,
  multi_polygon,
  geometry_collection,
};

std::optional<GeoType> geo_type_of(std::string_view name) {
  static constexpr std::pair<std::string_view, GeoType> types[] = {
      {"FeatureCollection", GeoType::feature_collection},
      {"Feature", GeoType::feature},
      {"Point", GeoType::point},
      {"MultiPoint", GeoType::multi_point},
      {"LineString", GeoType::line_string},
      {"MultiLineString", GeoType::multi_line_string},
      {"Polygon", GeoType::polygon},
      {"MultiPolygon", GeoType::multi_polygon},
      {"GeometryCollection", GeoType::geometry_collection},
  };
  for (const auto& [spelling, type] : types)
    if (spelling == name) return type;
  return std::nullopt;
}

bool is_geometry(GeoType type) noexcept { return type >= GeoType::point; }

// The members the reader gives a meaning to; any other is a foreign member
// (RFC 7946, 6.1) or one it has no use for ("bbox", "id"), read and ignored.
enum class Member : std::uint8_t { type, features, geometry, properties, coordinates, geometries, other };

Member member_of(std::string_view name) {
  if (name == "type") return Member::type;
  if (name == "coordinates") return Member::coordinates;
  if (name == "geometry") return Member::geometry;
  if (name == "properties") return Member::properties;
  if (name == "features") return Member::features;
  if (name == "geometries") return Member::geometries;
  return Member::other;
}

constexpr unsigned bit(Member m) noexcept { return 1u << static_cast<unsigned>(m); }

// What an object may be where it stands.
enum class Context : std::uint8_t { document, feature, geometry };

// Text from the file echoed in a message: short and printable.
std::string printable(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  if (text.size() > 40) out += "...";
  return out;
}

// One step of the way down to what is being read: "ring 2".
struct Part {
  const char* label;
  std::uint32_t index;
};

class GeoJsonReader {
public:
  GeoJsonReader(std::string_view text, const std::string& path) : json_(text, path) {}
  PolygonSet read();

private:
  void read_object(Context context);
  GeoType read_type(Context context);
  void read_member(GeoType type, Member member);
  void check_required(GeoType type, unsigned seen, JsonPosition at);
  void read_features();
  void read_geometry_member();
  void read_geometries();
  void read_multi_polygon();
  void read_polygon(std::uint32_t polygon);
  GisRing read_ring();
  Point read_position();
  void check_coordinate(std::size_t k, double value, JsonPosition at);
  void read_properties();
  void read_marker();
  void expect(JsonType wanted, const char* what);
  [[noreturn]] void fail_at(JsonPosition at, const std::string& message, std::vector<Point> points = {});

  JsonLexer json_;
  PolygonSet out_;
  std::vector<Part> where_;
  std::optional<JsonMark> resume_;  // the end of the object whose deferred members are being read
  std::uint32_t feature_ = 0;       // GisPolygon::feature of what is read now
  std::uint32_t polygon_ = 0;       // GisPolygon::polygon of the next polygon of this feature
  int marker_ = 1;
  bool in_feature_ = false;
  std::uint32_t collections_ = 0;  // GeometryCollections open
  std::string scratch_;
};

PolygonSet GeoJsonReader::read() {
  expect(JsonType::object, "a GeoJSON text must be an object");
  read_object(Context::document);
  json_.finish();
  out_.coordinates = Coordinates::lonlat;
  return std::move(out_);
}

// One GeoJSON object. Its "type" may come after the members it gives a
// meaning to (JSON objects are unordered): those are then skipped, their
// places kept, and read once the type is known. Writers put "type" first,
// and then every member is read once, as it comes; otherwise a value is
// read once more for each enclosing object whose "type" came late.
void GeoJsonReader::read_object(Context context) {
  const JsonPosition at = json_.position();
  const std::size_t first_polygon = out_.polygons.size();
  json_.begin_object();
  std::optional<GeoType> type;
  std::array<std::pair<Member, JsonMark>, 5> deferred;  // at most one of each (names are distinct)
  std::size_t n_deferred = 0;
  unsigned seen = 0;
  std::string name;
  while (json_.next_member(name)) {
    const Member member = member_of(name);
    seen |= bit(member);
    if (member == Member::type) {
      type = read_type(context);
    } else if (member == Member::other) {
      json_.skip_value();
    } else if (type) {
      read_member(*type, member);
    } else {
      deferred[n_deferred++] = {member, json_.mark()};
      json_.skip_value();
    }
  }
  if (!type) fail_at(at, "the object has no \"type\" member");
  if (n_deferred > 0) {
    const JsonMark end = json_.mark();
    const bool outermost = !resume_;
    if (outermost) resume_ = end;
    for (std::size_t i = 0; i < n_deferred; ++i) {
      json_.restore(deferred[i].second);
      read_member(*type, deferred[i].first);
    }
    json_.restore(end);
    if (outermost) resume_.reset();
  }
  check_required(*type, seen, at);
  if (*type == GeoType::feature) {
    for (std::size_t i = first_polygon; i < out_.polygons.size(); ++i) out_.polygons[i].marker = marker_;
    in_feature_ = false;
  }
}

GeoType GeoJsonReader::read_type(Context context) {
  const JsonPosition at = json_.position();
  expect(JsonType::string, "\"type\" must be a string");
  json_.string(scratch_);
  const std::optional<GeoType> type = geo_type_of(scratch_);
  if (!type) fail_at(at, "unknown GeoJSON type \"" + printable(scratch_) + "\"");
  if (context == Context::feature && *type != GeoType::feature)
    fail_at(at, "a member of \"features\" must be a Feature, got type \"" + scratch_ + "\"");
  if (context == Context::geometry && !is_geometry(*type))
    fail_at(at, "expected a geometry, got type \"" + scratch_ + "\"");
  if (*type == GeoType::feature) {
    marker_ = 1;
    polygon_ = 0;
    in_feature_ = true;
  }
  return *type;
}

void GeoJsonReader::read_member(GeoType type, Member member) {
  switch (member) {
  case Member::features:
    if (type == GeoType::feature_collection) return read_features();
    break;
  case Member::geometry:
    if (type == GeoType::feature) return read_geometry_member();
    break;
  case Member::properties:
    if (type == GeoType::feature) return read_properties();
    break;
  case Member::coordinates:
    if (type == GeoType::polygon) {
      read_polygon(polygon_);
      ++polygon_;
      return;
    }
    if (type == GeoType::multi_polygon) return read_multi_polygon();
    break;
  case Member::geometries:
    if (type == GeoType::geometry_collection) return read_geometries();
    break;
  default:
    break;
  }
  json_.skip_value();  // a foreign member here, or the coordinates of points and lines
}

void GeoJsonReader::check_required(GeoType type, unsigned seen, JsonPosition at) {
  Member required = Member::coordinates;
  const char* label = "a geometry";
  if (type == GeoType::feature_collection) {
    required = Member::features;
    label = "a FeatureCollection";
  } else if (type == GeoType::feature) {
    required = Member::geometry;
    label = "a Feature";
  } else if (type == GeoType::geometry_collection) {
    required = Member::geometries;
    label = "a GeometryCollection";
  }
  static constexpr const char* names[] = {"type", "features", "geometry", "properties", "coordinates", "geometries"};
  if (!(seen & bit(required)))
    fail_at(at, std::string(label) + " must have a \"" + names[static_cast<unsigned>(required)] + "\" member");
}

void GeoJsonReader::read_features() {
  expect(JsonType::array, "\"features\" must be an array");
  json_.begin_array();
  where_.push_back({"feature", 0});
  for (std::uint32_t i = 0; json_.next_element(); ++i) {
    where_.back().index = i;
    feature_ = i;
    expect(JsonType::object, "a feature must be an object");
    read_object(Context::feature);
  }
  where_.pop_back();
}

void GeoJsonReader::read_geometry_member() {
  if (json_.peek() == JsonType::null) return json_.null();
  expect(JsonType::object, "\"geometry\" must be an object or null");
  read_object(Context::geometry);
}

void GeoJsonReader::read_geometries() {
  expect(JsonType::array, "\"geometries\" must be an array");
  json_.begin_array();
  // A bare GeometryCollection's members stand for features.
  const bool as_features = !in_feature_ && collections_ == 0;
  ++collections_;
  where_.push_back({"geometry", 0});
  for (std::uint32_t i = 0; json_.next_element(); ++i) {
    where_.back().index = i;
    if (as_features) {
      feature_ = i;
      polygon_ = 0;
    }
    expect(JsonType::object, "a member of \"geometries\" must be an object");
    read_object(Context::geometry);
  }
  where_.pop_back();
  --collections_;
}

void GeoJsonReader::read_multi_polygon() {
  expect(JsonType::array, "the coordinates of a MultiPolygon must be an array of polygons");
  json_.begin_array();
  where_.push_back({"polygon", 0});
  std::uint32_t i = 0;
  for (; json_.next_element(); ++i) {
    where_.back().index = i;
    read_polygon(polygon_ + i);
  }
  where_.pop_back();
  polygon_ += i;
}

void GeoJsonReader::read_polygon(std::uint32_t polygon) {
  expect(JsonType::array, "the coordinates of a polygon must be an array of rings");
  json_.begin_array();
  GisPolygon p;
  p.feature = feature_;
  p.polygon = polygon;
  where_.push_back({"ring", 0});
  std::uint32_t r = 0;
  for (; json_.next_element(); ++r) {
    where_.back().index = r;
    GisRing ring = read_ring();
    ring.source = r;
    if (r == 0) {
      p.outer = std::move(ring);
    } else {
      p.holes.push_back(std::move(ring));
    }
  }
  where_.pop_back();
  if (r > 0) out_.polygons.push_back(std::move(p));  // no rings: empty, skipped (RFC 7946, 3.1)
}

GisRing GeoJsonReader::read_ring() {
  const JsonPosition at = json_.position();
  expect(JsonType::array, "a ring must be an array of positions");
  json_.begin_array();
  GisRing ring;
  where_.push_back({"vertex", 0});
  JsonPosition last = at;
  std::uint32_t v = 0;
  for (; json_.next_element(); ++v) {
    where_.back().index = v;
    last = json_.position();
    ring.points.push_back(read_position());
  }
  where_.pop_back();
  if (v < 4)
    fail_at(at, "a ring needs at least 4 positions (the last repeating the first), this one has " + std::to_string(v));
  if (ring.points.back() != ring.points.front()) {
    where_.push_back({"vertex", v - 1});
    fail_at(last, "the ring is not closed: its last position differs from its first (vertex 0)",
            {ring.points.front(), ring.points.back()});
  }
  ring.points.pop_back();
  return ring;
}

// [longitude, latitude] or [longitude, latitude, altitude] (the altitude is
// checked and dropped). RFC 7946 allows more numbers but says not to write
// them; what they would mean is unknown, so they are refused.
Point GeoJsonReader::read_position() {
  const JsonPosition at = json_.position();
  expect(JsonType::array, "a position must be an array of 2 or 3 numbers");
  json_.begin_array();
  double xy[2] = {0.0, 0.0};
  std::size_t n = 0;
  while (json_.next_element()) {
    const JsonPosition number_at = json_.position();
    if (n == 3) fail_at(number_at, "a position has more than 3 numbers (longitude, latitude, altitude)");
    expect(JsonType::number, "a position must hold numbers only");
    const double value = json_.number();
    check_coordinate(n, value, number_at);
    if (n < 2) xy[n] = value;
    ++n;
  }
  if (n < 2) fail_at(at, "a position needs a longitude and a latitude, this one has " + std::to_string(n) + " numbers");
  return {xy[0], xy[1]};
}

void GeoJsonReader::check_coordinate(std::size_t k, double value, JsonPosition at) {
  static constexpr double limits[] = {180.0, 90.0, std::numeric_limits<double>::max()};
  if (std::abs(value) <= limits[k]) return;
  static constexpr const char* names[] = {"longitude", "latitude", "altitude"};
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on a + chain here.
  std::string message = names[k];
  message += ' ';
  message += printable(json_.number_text());
  if (!std::isfinite(value)) {
    message += " is beyond the range of a double";
    fail_at(at, message);
  }
  message += k == 0 ? " is outside [-180, 180]" : " is outside [-90, 90]";
  message += " (GeoJSON is longitude and latitude in degrees, RFC 7946: is this a projected file?)";
  fail_at(at, message);
}

void GeoJsonReader::read_properties() {
  if (json_.peek() == JsonType::null) return json_.null();
  expect(JsonType::object, "\"properties\" must be an object or null");
  json_.begin_object();
  while (json_.next_member(scratch_)) {
    if (scratch_ == "marker") {
      read_marker();
    } else {
      json_.skip_value();
    }
  }
}

// An integer in the range of int (3 and 3.0 alike: JSON has one kind of
// number); null, as GIS tools write a missing value, keeps the default 1.
void GeoJsonReader::read_marker() {
  const JsonPosition at = json_.position();
  const JsonType type = json_.peek();
  if (type == JsonType::null) return json_.null();
  if (type != JsonType::number)
    fail_at(at, std::string("property \"marker\" must be an integer, got ") + detail::json_type_name(type));
  const double value = json_.number();
  if (!(value == std::floor(value) && value >= std::numeric_limits<int>::min() &&
        value <= std::numeric_limits<int>::max()))
    fail_at(at, "property \"marker\" must be an integer in the range of int, got " + printable(json_.number_text()));
  marker_ = static_cast<int>(value);
}

void GeoJsonReader::expect(JsonType wanted, const char* what) {
  const JsonType got = json_.peek();
  if (got != wanted) fail_at(json_.position(), std::string(what) + ", got " + detail::json_type_name(got));
}

// "path: feature 3, ring 2, vertex 7: message (line L, column C)". Malformed
// JSON anywhere in the text comes first: the rest is read before throwing.
void GeoJsonReader::fail_at(JsonPosition at, const std::string& message, std::vector<Point> points) {
  if (resume_) json_.restore(*resume_);  // what lies before was read once already
  json_.skip_rest();
  std::string text;
  for (const Part& part : where_) {
    if (!text.empty()) text += ", ";
    text += part.label;
    text += ' ';
    text += std::to_string(part.index);
  }
  if (!text.empty()) text += ": ";
  text += message + " (line " + std::to_string(at.line) + ", column " + std::to_string(at.column) + ")";
  throw InvalidInputError(InputProblem::other, text, {}, std::move(points), json_.path());
}

}  // namespace

PolygonSet parse_geojson(std::string_view text, const std::string& path) { return GeoJsonReader(text, path).read(); }

}  // namespace madd
