// Tests of the ESRI shapefile reader (parse_shapefile, include/madd/polygons.hpp;
// src/gis/shapefile_reader.cpp, src/gis/ring_nesting.cpp). Inputs come from a
// small writer below, written from the technical description byte by byte,
// and from data/coast/*.shp, written by GDAL's ogr2ogr (data/coast/README-shapefile.md).
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "gis/ring_nesting.hpp"
#include "kernel/rings.hpp"
#include "madd/error.hpp"
#include "madd/polygons.hpp"
#include "madd/pslg.hpp"

namespace fs = std::filesystem;
using namespace std::string_literals;
using madd::GisPolygon;
using madd::GisRing;
using madd::Point;
using madd::PolygonSet;

namespace {

using Ring = std::vector<Point>;

// ---- A shapefile writer, from the technical description ----

struct Shape {
  std::int32_t type = 5;    // 0 (Null), 5 (Polygon), 15 (PolygonZ) or 25 (PolygonM)
  std::vector<Ring> parts;  // written as given: close them with closed() to make a valid ring
  bool measures = false;    // PolygonZ: the optional M range and values too; PolygonM: the M values
};

struct Written {
  std::string shp, shx;
  std::vector<std::size_t> offsets;  // each record header's byte in the .shp
};

void put_big(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
}
void put_little(std::string& out, std::uint32_t v) {
  for (int shift = 0; shift <= 24; shift += 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
}
void put_double(std::string& out, double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  for (int shift = 0; shift <= 56; shift += 8) out.push_back(static_cast<char>((bits >> shift) & 0xFF));
}
void set_big(std::string& s, std::size_t at, std::uint32_t v) {
  std::string b;
  put_big(b, v);
  s.replace(at, 4, b);
}
void set_little(std::string& s, std::size_t at, std::uint32_t v) {
  std::string b;
  put_little(b, v);
  s.replace(at, 4, b);
}
void set_double(std::string& s, std::size_t at, double v) {
  std::string b;
  put_double(b, v);
  s.replace(at, 8, b);
}

Ring closed(Ring r) {
  r.push_back(r.front());
  return r;
}

Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}

// An axis-aligned square ring, counter-clockwise, open.
Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

void put_box(std::string& out, const std::vector<Ring>& parts) {
  double lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;
  bool any = false;
  for (const Ring& r : parts)
    for (const Point p : r) {
      lo_x = any ? std::min(lo_x, p.x) : p.x, lo_y = any ? std::min(lo_y, p.y) : p.y;
      hi_x = any ? std::max(hi_x, p.x) : p.x, hi_y = any ? std::max(hi_y, p.y) : p.y;
      any = true;
    }
  for (const double v : {lo_x, lo_y, hi_x, hi_y}) put_double(out, v);
}

// A range and one value a point (Z = the point's index, M = minus it).
void put_values(std::string& out, std::size_t points, double sign) {
  put_double(out, points == 0 ? 0.0 : std::min(0.0, sign * static_cast<double>(points - 1)));
  put_double(out, points == 0 ? 0.0 : std::max(0.0, sign * static_cast<double>(points - 1)));
  for (std::size_t i = 0; i < points; ++i) put_double(out, sign * static_cast<double>(i));
}

std::string content_of(const Shape& s) {
  std::string c;
  put_little(c, static_cast<std::uint32_t>(s.type));
  if (s.type == 0) return c;
  put_box(c, s.parts);
  std::size_t points = 0;
  for (const Ring& r : s.parts) points += r.size();
  put_little(c, static_cast<std::uint32_t>(s.parts.size()));
  put_little(c, static_cast<std::uint32_t>(points));
  std::size_t start = 0;
  for (const Ring& r : s.parts) put_little(c, static_cast<std::uint32_t>(start)), start += r.size();
  for (const Ring& r : s.parts)
    for (const Point p : r) put_double(c, p.x), put_double(c, p.y);
  if (s.type == 15) put_values(c, points, 1.0);
  if ((s.type == 15 && s.measures) || (s.type == 25 && s.measures)) put_values(c, points, -1.0);
  return c;
}

std::string file_header(std::int32_t type, std::size_t bytes, const std::vector<Shape>& shapes) {
  std::string h;
  put_big(h, 9994);
  for (int i = 0; i < 5; ++i) put_big(h, 0);
  put_big(h, static_cast<std::uint32_t>(bytes / 2));
  put_little(h, 1000);
  put_little(h, static_cast<std::uint32_t>(type));
  std::vector<Ring> all;
  for (const Shape& s : shapes) all.insert(all.end(), s.parts.begin(), s.parts.end());
  put_box(h, all);
  for (int i = 0; i < 4; ++i) put_double(h, 0.0);  // Z and M ranges
  return h;
}

Written write_shapefile(std::int32_t type, const std::vector<Shape>& shapes) {
  Written w;
  std::string records, index;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const std::string c = content_of(shapes[k]);
    w.offsets.push_back(100 + records.size());
    put_big(index, static_cast<std::uint32_t>((100 + records.size()) / 2));
    put_big(index, static_cast<std::uint32_t>(c.size() / 2));
    put_big(records, static_cast<std::uint32_t>(k + 1));
    put_big(records, static_cast<std::uint32_t>(c.size() / 2));
    records += c;
  }
  w.shp = file_header(type, 100 + records.size(), shapes) + records;
  w.shx = file_header(type, 100 + index.size(), shapes) + index;
  return w;
}

Shape polygon(std::vector<Ring> open_rings, std::int32_t type = 5) {
  Shape s;
  s.type = type;
  for (Ring& r : open_rings) s.parts.push_back(closed(std::move(r)));
  return s;
}

Shape null_shape() {
  Shape s;
  s.type = 0;
  return s;
}

// The message parse_shapefile fails with (every failure must be an InvalidInputError).
std::string error_of(std::string_view shp, std::string_view shx = {}, std::string_view prj = {}) {
  try {
    (void)madd::parse_shapefile(shp, shx, prj, "t.shp");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == madd::InputProblem::other);
    CHECK(e.kind() == madd::ErrorKind::bad_input);
    CHECK(e.path().empty());
    return e.what();
  }
  return "no error";
}

GisRing ring_of(Ring points, std::uint32_t source) { return GisRing{std::move(points), source}; }

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The same cycle of points, whatever its first vertex and direction.
bool same_cycle(const Ring& a, const Ring& b) {
  if (a.size() != b.size()) return false;
  for (const Ring& c : {b, reversed(b)}) {
    for (std::size_t shift = 0; shift < c.size(); ++shift) {
      bool all = true;
      for (std::size_t i = 0; i < a.size() && all; ++i) all = a[i] == c[(i + shift) % c.size()];
      if (all) return true;
    }
  }
  return false;
}

// ---- References for the nesting: every pair, no grid, no order ----

// The header's rule for ring a lying in ring b, point by point.
bool lies_in_reference(const Ring& a, const Ring& b) {
  using madd::detail::RingLocation;
  const madd::detail::RingView view(b);
  for (const Point p : a) {
    const RingLocation at = madd::detail::locate_in_ring(view, p);
    if (at != RingLocation::on_ring) return at == RingLocation::inside;
  }
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Point u = a[k], v = a[(k + 1) % a.size()];
    const RingLocation at = madd::detail::locate_in_ring(view, Point{0.5 * u.x + 0.5 * v.x, 0.5 * u.y + 0.5 * v.y});
    if (at != RingLocation::on_ring) return at == RingLocation::inside;
  }
  return false;
}

bool box_within(const Ring& a, const Ring& b) {
  const auto box = [](const Ring& r) {
    Point lo = r[0], hi = r[0];
    for (const Point p : r)
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = box(a);
  const auto [blo, bhi] = box(b);
  return blo.x <= alo.x && blo.y <= alo.y && ahi.x <= bhi.x && ahi.y <= bhi.y;
}

// Depth = how many other rings hold the ring; parent = the deepest of them.
madd::detail::RingNesting nesting_reference(const std::vector<Ring>& rings) {
  const std::size_t n = rings.size();
  std::vector<std::vector<std::uint32_t>> holders(n);
  madd::detail::RingNesting out{std::vector<std::uint32_t>(n, madd::no_index), std::vector<std::uint32_t>(n, 0)};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && box_within(rings[i], rings[j]) && lies_in_reference(rings[i], rings[j]))
        holders[i].push_back(static_cast<std::uint32_t>(j));
  for (std::size_t i = 0; i < n; ++i) out.depth[i] = static_cast<std::uint32_t>(holders[i].size());
  for (std::size_t i = 0; i < n; ++i)
    for (const std::uint32_t j : holders[i])
      if (out.parent[i] == madd::no_index || out.depth[j] > out.depth[out.parent[i]]) out.parent[i] = j;
  return out;
}

// A star-shaped ring of n vertices around c (radii in [0.7, 1] r, so that it
// holds the disc of radius 0.64 r for n >= 8), in a random direction; then,
// with some chance, children in disjoint discs inside that disc.
void add_nested(std::vector<Ring>& rings, std::mt19937& random, Point c, double r, int levels, std::size_t n) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * 3.14159265358979 * static_cast<double>(k) / static_cast<double>(n);
    const double radius = r * (0.7 + 0.3 * unit(random));
    ring.push_back({c.x + radius * std::cos(angle), c.y + radius * std::sin(angle)});
  }
  if (unit(random) < 0.5) ring = reversed(ring);
  rings.push_back(ring);
  if (levels == 0 || unit(random) < 0.3) return;
  // Children on a g x g lattice inside the square of half side 0.44 r.
  const int g = 1 + static_cast<int>(unit(random) * 3);
  const double cell = 0.88 * r / g;
  for (int a = 0; a < g; ++a)
    for (int b = 0; b < g; ++b)
      if (unit(random) < 0.8)
        add_nested(rings, random, {c.x - 0.44 * r + (a + 0.5) * cell, c.y - 0.44 * r + (b + 0.5) * cell}, 0.45 * cell,
                   levels - 1, 8 + static_cast<std::size_t>(unit(random) * 60));
}

// Per part of a one-record file: the part of the outer ring it belongs to (itself for an outer ring).
std::vector<std::uint32_t> outer_ring_of_parts(const PolygonSet& set, std::size_t parts) {
  std::vector<std::uint32_t> outer_of(parts, madd::no_index);
  for (const GisPolygon& p : set.polygons) {
    outer_of[p.outer.source] = p.outer.source;
    for (const GisRing& h : p.holes) outer_of[h.source] = p.outer.source;
  }
  return outer_of;
}

// Counts rings and positions in GeoJSON text without parsing it: a position
// is '[' then a number, a ring '[' then a position ('[' and white space skipped).
std::pair<std::size_t, std::size_t> loose_counts(std::string_view text) {
  const auto skip = [&](std::size_t i) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\n' || text[i] == '\r' || text[i] == '\t')) ++i;
    return i;
  };
  const auto number_at = [&](std::size_t i) {
    return i < text.size() && (text[i] == '-' || (text[i] >= '0' && text[i] <= '9'));
  };
  std::size_t rings = 0, positions = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '[') continue;
    const std::size_t j = skip(i + 1);
    if (number_at(j)) ++positions;
    if (j < text.size() && text[j] == '[' && number_at(skip(j + 1))) ++rings;
  }
  return {rings, positions};
}

std::pair<std::size_t, std::size_t> rings_and_points(const PolygonSet& set) {
  std::size_t rings = 0, points = 0;
  for (const GisPolygon& p : set.polygons) {
    rings += 1 + p.holes.size();
    points += p.outer.points.size();
    for (const GisRing& h : p.holes) points += h.points.size();
  }
  return {rings, points};
}

PolygonSet read_coast_shapefile(const std::string& stem) {
  const fs::path dir = fs::path(MADD_DATA_DIR) / "coast";
  return madd::parse_shapefile(slurp(dir / (stem + ".shp")), slurp(dir / (stem + ".shx")), slurp(dir / (stem + ".prj")),
                               stem + ".shp");
}

}  // namespace

TEST_SUITE("shapefile") {

TEST_CASE("a polygon with holes: outer and holes by nesting, in either direction, in file order") {
  const Ring outer = square(0, 0, 10), hole_a = square(1, 1, 2), hole_b = square(6, 6, 3);
  // The description's direction (outer clockwise, holes counter-clockwise),
  // its opposite, and a hole written before its outer ring.
  for (const bool esri : {true, false}) {
    CAPTURE(esri);
    const Ring o = esri ? reversed(outer) : outer;
    const Ring a = esri ? hole_a : reversed(hole_a);
    const Ring b = esri ? hole_b : reversed(hole_b);
    const Written w = write_shapefile(5, {polygon({a, o, b})});
    const PolygonSet set = madd::parse_shapefile(w.shp, w.shx, "", "t.shp");
    REQUIRE(set.polygons.size() == 1);
    const GisPolygon& p = set.polygons[0];
    CHECK(p.outer == ring_of(o, 1));  // open, the file's direction, source = part index
    REQUIRE(p.holes.size() == 2);
    CHECK(p.holes[0] == ring_of(a, 0));
    CHECK(p.holes[1] == ring_of(b, 2));
    CHECK(p.marker == 1);
    CHECK(p.feature == 0);
    CHECK(p.polygon == 0);
    CHECK(set.coordinates == madd::Coordinates::lonlat);  // no .prj, all within [-180, 180] x [-90, 90]
  }
}

TEST_CASE("islands in lakes in islands: even depth an outer ring, odd a hole of the smallest ring holding it") {
  // Depths: 0 (0..100), 1 (10..90), 2 (20..80), 3 (30..70), 4 (40..60);
  // a second land 200..210 with a lake; parts shuffled.
  const Ring d0 = square(0, 0, 100), d1 = square(10, 10, 80), d2 = square(20, 20, 60), d3 = square(30, 30, 40),
             d4 = square(40, 40, 20), e0 = square(200, 0, 10), e1 = reversed(square(202, 2, 2));
  const Written w = write_shapefile(5, {polygon({d3, e1, d0, d4, d1, e0, d2})});
  const PolygonSet set = madd::parse_shapefile(w.shp, w.shx, "", "t.shp");
  // Outer rings in part order: d0 (part 2), d4 (3), e0 (5), d2 (6).
  REQUIRE(set.polygons.size() == 4);
  CHECK(set.polygons[0] == GisPolygon{ring_of(d0, 2), {ring_of(d1, 4)}, 1, 0, 0});
  CHECK(set.polygons[1] == GisPolygon{ring_of(d4, 3), {}, 1, 0, 1});
  CHECK(set.polygons[2] == GisPolygon{ring_of(e0, 5), {ring_of(e1, 1)}, 1, 0, 2});
  CHECK(set.polygons[3] == GisPolygon{ring_of(d2, 6), {ring_of(d3, 0)}, 1, 0, 3});
  CHECK(set.coordinates == madd::Coordinates::projected);  // x = 210 is no longitude
}

TEST_CASE("touching rings: a vertex on the other ring does not decide, the next one does") {
  const Ring outer = square(0, 0, 4);
  // A hole with one vertex on the outer ring, listed first.
  const Ring touching = {{0, 2}, {1, 1}, {2, 2}, {1, 3}};
  // A diamond with every vertex on the outer ring: its edge midpoints decide.
  const Ring diamond = {{2, 0}, {4, 2}, {2, 4}, {0, 2}};
  // An outer ring around the square sharing its corner (0, 0): not inside the square.
  const Ring around = {{0, 0}, {-1, -3}, {6, -3}, {6, 6}, {-3, 6}, {-3, -1}};
  Written w = write_shapefile(5, {polygon({outer, touching}), polygon({outer, diamond}), polygon({outer, outer})});
  PolygonSet set = madd::parse_shapefile(w.shp, w.shx, "", "t.shp");
  REQUIRE(set.polygons.size() == 4);
  CHECK(set.polygons[0] == GisPolygon{ring_of(outer, 0), {ring_of(touching, 1)}, 1, 0, 0});
  CHECK(set.polygons[1] == GisPolygon{ring_of(outer, 0), {ring_of(diamond, 1)}, 1, 1, 0});
  // A duplicate ring lies wholly on the other: neither holds the other.
  CHECK(set.polygons[2] == GisPolygon{ring_of(outer, 0), {}, 1, 2, 0});
  CHECK(set.polygons[3] == GisPolygon{ring_of(outer, 1), {}, 1, 2, 1});
  // The square inside `around` (sharing a vertex) is its hole.
  w = write_shapefile(5, {polygon({outer, around})});
  set = madd::parse_shapefile(w.shp, w.shx, "", "t.shp");
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0] == GisPolygon{ring_of(around, 1), {ring_of(outer, 0)}, 1, 0, 0});
}

TEST_CASE("several records: Null shapes skipped, feature = record index, polygon = outer index in the record") {
  const Written w = write_shapefile(5, {null_shape(), polygon({square(0, 0, 1)}), null_shape(),
                                        polygon({square(5, 5, 1), square(2, 2, 1), square(3, 3, 0.5)}), null_shape()});
  const PolygonSet set = madd::parse_shapefile(w.shp, w.shx, "", "t.shp");
  REQUIRE(set.polygons.size() == 4);
  CHECK(set.polygons[0] == GisPolygon{ring_of(square(0, 0, 1), 0), {}, 1, 1, 0});
  CHECK(set.polygons[1] == GisPolygon{ring_of(square(5, 5, 1), 0), {}, 1, 3, 0});
  CHECK(set.polygons[2] == GisPolygon{ring_of(square(2, 2, 1), 1), {}, 1, 3, 1});
  // square(3, 3, 0.5) touches square(2, 2, 1) only at (3, 3): outside it, an outer ring of its own.
  CHECK(set.polygons[3] == GisPolygon{ring_of(square(3, 3, 0.5), 2), {}, 1, 3, 2});
  CHECK(madd::parse_shapefile(w.shp, "", "", "t.shp") == set);
  // A file of Null shapes only, and one of no records.
  CHECK(madd::parse_shapefile(write_shapefile(5, {null_shape(), null_shape()}).shp, "", "").polygons.empty());
  const Written empty = write_shapefile(25, {});
  CHECK(empty.shp.size() == 100);
  CHECK(madd::parse_shapefile(empty.shp, empty.shx, "") == PolygonSet{});
}

TEST_CASE("PolygonZ and PolygonM, with and without measures, read as the Polygon of their points") {
  const std::vector<Ring> rings = {square(0, 0, 10), reversed(square(2, 2, 2)), square(20, 0, 5)};
  const Written plain = write_shapefile(5, {polygon(rings), null_shape(), polygon({square(0, 0, 1)})});
  const PolygonSet expected = madd::parse_shapefile(plain.shp, plain.shx, "");
  REQUIRE(expected.polygons.size() == 3);
  for (const std::int32_t type : {15, 25}) {
    for (const bool measures : {false, true}) {
      CAPTURE(type);
      CAPTURE(measures);
      Shape a = polygon(rings, type), b = polygon({square(0, 0, 1)}, type);
      a.measures = b.measures = measures;
      const Written w = write_shapefile(type, {a, null_shape(), b});
      CHECK(w.shp.size() > plain.shp.size() - (type == 25 && !measures ? 1 : 0));
      CHECK(madd::parse_shapefile(w.shp, w.shx, "") == expected);
    }
  }
}

TEST_CASE(".prj: PROJCS projected, GEOGCS lon/lat, nothing by the coordinates' range, anything else refused") {
  const Written lonlat = write_shapefile(5, {polygon({square(-180, -90, 180)})});
  const Written metres = write_shapefile(5, {polygon({square(400000, 4800000, 1000)})});
  const auto coordinates = [](const Written& w, std::string_view prj) {
    return madd::parse_shapefile(w.shp, w.shx, prj).coordinates;
  };
  using madd::Coordinates;
  CHECK(coordinates(lonlat, "") == Coordinates::lonlat);
  CHECK(coordinates(lonlat, " \r\n\t") == Coordinates::lonlat);  // blank: as no .prj
  CHECK(coordinates(metres, "") == Coordinates::projected);
  CHECK(coordinates(metres, "\n") == Coordinates::projected);
  const std::string geogcs =
      R"(GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID["WGS_1984",6378137.0,298.257223563]],)"
      R"(PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]])";
  const std::string projcs = R"(PROJCS["WGS_1984_UTM_Zone_19N",GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",)"
                             R"(SPHEROID["WGS_1984",6378137.0,298.257223563]]],PROJECTION["Transverse_Mercator"]])";
  // The .prj is believed over the coordinates' range.
  CHECK(coordinates(metres, geogcs) == Coordinates::lonlat);
  CHECK(coordinates(lonlat, projcs) == Coordinates::projected);
  CHECK(coordinates(lonlat, "\xEF\xBB\xBF  " + projcs) == Coordinates::projected);  // a UTF-8 byte order mark
  CHECK(coordinates(metres, "  geogcs[\"x\"]") == Coordinates::lonlat);             // keywords in any case
  CHECK(coordinates(metres, "GEOGCRS[\"WGS 84\"]") == Coordinates::lonlat);         // WKT 2
  CHECK(coordinates(lonlat, "PROJCRS[\"UTM\"]") == Coordinates::projected);
  CHECK(error_of(lonlat.shp, lonlat.shx, "VERT_CS[\"depth\"]") ==
        "t.shp: .prj: the coordinate system 'VERT_CS' is neither projected (PROJCS) nor geographic (GEOGCS)");
  CHECK(error_of(lonlat.shp, lonlat.shx, "\n GEOCCS[\"x\"]") ==
        "t.shp: .prj: the coordinate system 'GEOCCS' is neither projected (PROJCS) nor geographic (GEOGCS)");
  CHECK(error_of(lonlat.shp, lonlat.shx, "PROJCSX[") ==
        "t.shp: .prj: the coordinate system 'PROJCSX' is neither projected (PROJCS) nor geographic (GEOGCS)");
  CHECK(error_of(lonlat.shp, lonlat.shx, "{\"type\": 1}") ==
        "t.shp: .prj: the coordinate system '{' is neither projected (PROJCS) nor geographic (GEOGCS)");
  CHECK(error_of(lonlat.shp, lonlat.shx, std::string("\x01PROJCS", 7)) ==
        "t.shp: .prj: the coordinate system '\\x01' is neither projected (PROJCS) nor geographic (GEOGCS)");
  CHECK(error_of(lonlat.shp, lonlat.shx, std::string(60, 'A')) ==
        "t.shp: .prj: the coordinate system '" + std::string(40, 'A') +
            "...' is neither projected (PROJCS) nor geographic (GEOGCS)");
}

TEST_CASE("the file header: size, file code, file length, version, shape type") {
  const Written w = write_shapefile(5, {polygon({square(0, 0, 1)})});
  const std::string& shp = w.shp;  // one record at byte 100, content at 108, 128 bytes
  REQUIRE(shp.size() == 100 + 8 + 44 + 4 + 16 * 5);
  CHECK(error_of("") == "t.shp: byte 0: the file ends inside its 100-byte header");
  CHECK(error_of(shp.substr(0, 99)) == "t.shp: byte 99: the file ends inside its 100-byte header");
  std::string bad = shp;
  set_big(bad, 0, 9995);
  CHECK(error_of(bad) == "t.shp: byte 0: file code 9995, expected 9994: not a shapefile");
  CHECK(error_of("{\"type\": \"FeatureCollection\"}") ==
        "t.shp: byte 0: file code 2065855609, expected 9994: not a shapefile");
  bad = shp;
  set_big(bad, 24, 119);
  CHECK(error_of(bad) ==
        "t.shp: byte 24: the header gives the file length as 119 16-bit words (238 bytes), but the file has 236 bytes");
  CHECK(error_of(shp + "\0\0"s) ==
        "t.shp: byte 24: the header gives the file length as 118 16-bit words (236 bytes), but the file has 238 bytes");
  bad = shp;
  set_little(bad, 28, 1001);
  CHECK(error_of(bad) == "t.shp: byte 28: version 1001, expected 1000");
  bad = shp;
  set_little(bad, 32, 3);
  CHECK(error_of(bad) ==
        "t.shp: byte 32: shape type 3 (PolyLine) is not a polygon type (5 Polygon, 15 PolygonZ or 25 PolygonM)");
  set_little(bad, 32, 0);
  CHECK(error_of(bad) ==
        "t.shp: byte 32: shape type 0 (Null) is not a polygon type (5 Polygon, 15 PolygonZ or 25 PolygonM)");
  set_little(bad, 32, 7);
  CHECK(
      error_of(bad) ==
      "t.shp: byte 32: shape type 7 (not a shape type) is not a polygon type (5 Polygon, 15 PolygonZ or 25 PolygonM)");
}

TEST_CASE("record framing: numbers, content lengths, shape types, counts and part starts") {
  const Written w =
      write_shapefile(5, {null_shape(), polygon({square(0, 0, 4), square(1, 1, 1)}), polygon({square(9, 9, 1)})});
  const std::size_t r1 = w.offsets[1], c1 = r1 + 8;  // record 1: 2 parts, 10 points, 44 + 8 + 160 = 212 bytes
  REQUIRE(r1 == 112);
  const auto with = [&](auto&& change) {
    std::string s = w.shp;
    change(s);
    return error_of(s);
  };
  CHECK(with([&](std::string& s) { set_big(s, r1, 3); }) ==
        "t.shp: byte 112: record 1: record number 3, expected 2 (records are numbered from 1)");
  CHECK(with([&](std::string& s) { set_big(s, 100, 0xFFFFFFFF); }) ==
        "t.shp: byte 100: record 0: record number -1, expected 1 (records are numbered from 1)");
  CHECK(with([&](std::string& s) { set_big(s, r1 + 4, 1); }) ==
        "t.shp: byte 116: record 1: content length 1 words is too short for a shape type (4 bytes)");
  CHECK(with([&](std::string& s) { set_big(s, r1 + 4, 0x7FFFFFFF); }) ==
        "t.shp: byte 116: record 1: content length 2147483647 words (4294967294 bytes) runs past the end of the file "
        "(348 bytes left)");
  // A lying content length that still fits.
  CHECK(with([&](std::string& s) { set_big(s, r1 + 4, 108); }) ==
        "t.shp: byte 156: record 1: 2 parts and 10 points make 212 bytes of Polygon content, but the record has 216");
  CHECK(with([&](std::string& s) { set_big(s, 100 + 4, 4); }) ==
        "t.shp: byte 108: record 0: a Null shape's content is 4 bytes, but the record has 8");
  CHECK(with([&](std::string& s) { set_little(s, c1, 15); }) ==
        "t.shp: byte 120: record 1: shape type 15 (PolygonZ) in a file of shape type 5 (Polygon)");
  CHECK(with([&](std::string& s) { set_little(s, c1, 1); }) ==
        "t.shp: byte 120: record 1: shape type 1 (Point) in a file of shape type 5 (Polygon)");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 36, 3); }) ==
        "t.shp: byte 156: record 1: 3 parts and 10 points make 216 bytes of Polygon content, but the record has 212");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 40, 0x10000000); }) ==
        "t.shp: byte 156: record 1: 2 parts and 268435456 points make 4294967348 bytes of Polygon content, but the "
        "record has 212");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 36, 0xFFFFFFFF); }) ==
        "t.shp: byte 156: record 1: negative part count -1");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 40, 0x80000000); }) ==
        "t.shp: byte 160: record 1: negative point count -2147483648");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 44, 1); }) ==
        "t.shp: byte 164: record 1: part 0 starts at point 1, expected 0");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 48, 0); }) ==
        "t.shp: byte 168: record 1: part 1 starts at point 0, not after part 0 (point 0)");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 48, 0xFFFFFFFF); }) ==
        "t.shp: byte 168: record 1: part 1 starts at point -1, not after part 0 (point 0)");
  CHECK(with([&](std::string& s) { set_little(s, c1 + 48, 10); }) ==
        "t.shp: byte 168: record 1: part 1 starts at point 10, beyond the record's 10 points");
  // A polygon of no parts (and no points) in 44 bytes; content too short for the counts.
  std::string none;
  put_little(none, 5);
  none.append(32, '\0');
  put_little(none, 0);
  put_little(none, 0);
  const auto record = [](const std::string& content) {
    std::string r;
    put_big(r, 1);
    put_big(r, static_cast<std::uint32_t>(content.size() / 2));
    return r + content;
  };
  std::string s = file_header(5, 100 + 8 + 44, {}) + record(none);
  CHECK(error_of(s) == "t.shp: byte 144: record 0: a polygon of no parts (an empty shape is a Null shape)");
  s = file_header(5, 100 + 8 + 40, {}) + record(none.substr(0, 40));
  CHECK(error_of(s) ==
        "t.shp: byte 108: record 0: 40 bytes of content cannot hold a polygon's shape type, box and counts (44 bytes)");
  // Each type's sizes: PolygonZ must carry its Z values.
  Shape z = polygon({square(0, 0, 1)}, 15);
  const Written wz = write_shapefile(15, {z});
  s = wz.shp.substr(0, wz.shp.size() - 8 * 5 - 16);
  set_big(s, 24, static_cast<std::uint32_t>(s.size() / 2));
  set_big(s, 104, static_cast<std::uint32_t>((s.size() - 108) / 2));
  CHECK(error_of(s) == "t.shp: byte 144: record 0: 1 parts and 5 points make 184 bytes of PolygonZ content (240 "
                       "with measures), but the record has 128");
  const Written wm = write_shapefile(25, {polygon({square(0, 0, 1)}, 25)});
  s = wm.shp + std::string(8, '\0');
  set_big(s, 24, static_cast<std::uint32_t>(s.size() / 2));
  set_big(s, 104, static_cast<std::uint32_t>((s.size() - 108) / 2));
  CHECK(error_of(s) == "t.shp: byte 144: record 0: 1 parts and 5 points make 128 bytes of PolygonM content without "
                       "measures (184 with them), but the record has 136");
}

TEST_CASE("ring geometry: closed, at least 4 points, coordinates finite and in madd's range") {
  const Ring ok = closed(square(0, 0, 4));
  const auto error_with = [](const Ring& part) {
    return error_of(write_shapefile(5, {null_shape(), Shape{5, {closed(square(10, 10, 1)), part}}}).shp);
  };
  CHECK(error_with(ok) == "no error");
  Ring open = ok;
  open.back() = Point{0, 0.1};
  CHECK(error_with(open) == "t.shp: record 1, part 1, vertex 4: the ring is not closed: its last point (0, "
                            "0.10000000000000001) differs from its first (0, 0)");
  CHECK(
      error_with(square(0, 0, 4)) ==
      "t.shp: record 1, part 1, vertex 3: the ring is not closed: its last point (0, 4) differs from its first (0, 0)");
  CHECK(error_with(Ring{{0, 0}, {1, 0}, {0, 0}}) ==
        "t.shp: record 1, part 1: a ring needs at least 4 points (its last equal to its first); this part has 3");
  Ring nan = ok;
  nan[2].y = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_with(nan) == "t.shp: record 1, part 1, vertex 2: coordinate (4, nan) is not finite");
  Ring inf = ok;
  inf[0].x = -HUGE_VAL;
  inf[4].x = -HUGE_VAL;
  CHECK(error_with(inf) == "t.shp: record 1, part 1, vertex 0: coordinate (-inf, 0) is not finite");
  // madd's supported range (docs/formats.md), where the nesting's predicates are exact.
  Ring tiny = ok;
  tiny[1].x = 1e-300;
  CHECK(error_with(tiny) == "t.shp: record 1, part 1, vertex 1: coordinate (1e-300, 0) is outside the "
                            "supported range: every coordinate must be 0 or of magnitude within [1e-40, 1e70]");
  Ring huge = ok;
  huge[3].y = -2e70;
  CHECK(error_with(huge) ==
        "t.shp: record 1, part 1, vertex 3: coordinate (0, -2.0000000000000001e+70) is outside the supported "
        "range: every coordinate must be 0 or of magnitude within [1e-40, 1e70]");
  const Ring edges = {{-0.0, 0}, {1e70, 0}, {1e70, 1e-40}, {-1e-40, -1e70}, {-0.0, 0}};
  CHECK(error_with(edges) == "no error");
  // Rings kept as they are otherwise: repeated points, spikes, three distinct vertices.
  const Ring repeated = {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 0}};
  const PolygonSet set = madd::parse_shapefile(write_shapefile(5, {Shape{5, {repeated}}}).shp, "", "");
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0].outer.points == Ring(repeated.begin(), repeated.end() - 1));
}

TEST_CASE("the .shx must agree with the .shp") {
  const Written w = write_shapefile(5, {polygon({square(0, 0, 1)}), null_shape(), polygon({square(3, 3, 1)})});
  REQUIRE(w.shx.size() == 100 + 3 * 8);
  CHECK(madd::parse_shapefile(w.shp, w.shx, "") == madd::parse_shapefile(w.shp, "", ""));
  const auto with = [&](auto&& change) {
    std::string s = w.shx;
    change(s);
    return error_of(w.shp, s);
  };
  CHECK(with([](std::string& s) { set_big(s, 0, 1); }) ==
        "t.shp: .shx byte 0: file code 1, expected 9994: not a shapefile");
  CHECK(with([](std::string& s) { s.resize(50); }) == "t.shp: .shx byte 50: the file ends inside its 100-byte header");
  CHECK(with([](std::string& s) { set_big(s, 24, 63); }) ==
        "t.shp: .shx byte 24: the header gives the file length as 63 16-bit words (126 bytes), but the file has 124 "
        "bytes");
  CHECK(with([](std::string& s) { set_little(s, 32, 25); }) ==
        "t.shp: .shx byte 32: shape type 25 (PolygonM) differs from the .shp's shape type 5 (Polygon)");
  CHECK(with([](std::string& s) { set_big(s, 100 + 8, 51); }) ==
        "t.shp: .shx byte 108: entry 1 gives record 1's offset as 51 words (byte 102), but it starts at byte 236 of "
        "the .shp");
  CHECK(with([](std::string& s) { set_big(s, 100 + 12, 4); }) ==
        "t.shp: .shx byte 112: entry 1 gives record 1's content length as 4 words, but the .shp gives 2");
  CHECK(with([](std::string& s) {
          s.resize(100 + 2 * 8);
          set_big(s, 24, 58);
        }) == "t.shp: .shx byte 116: the index ends after 2 entries, but the .shp has record 2 at byte 248");
  CHECK(with([](std::string& s) {
          s += std::string(8, '\0');
          set_big(s, 24, 66);
        }) == "t.shp: .shx byte 124: the index has 4 entries, but the .shp has 3 records");
  CHECK(with([](std::string& s) {
          s += std::string(4, '\0');
          set_big(s, 24, 64);
        }) == "t.shp: .shx byte 124: the index ends inside an entry (8 bytes each)");
}

TEST_CASE("truncated at every byte, or any byte changed: only madd::Error, never a crash or another exception") {
  std::vector<Shape> shapes = {polygon({square(0, 0, 4), square(1, 1, 1)}), null_shape(), polygon({square(9, 9, 1)})};
  for (const std::int32_t type : {5, 15, 25}) {
    for (Shape& s : shapes)
      if (s.type != 0) s.type = type, s.measures = type == 15;
    const Written w = write_shapefile(type, shapes);
    const PolygonSet whole = madd::parse_shapefile(w.shp, w.shx, "");
    REQUIRE(whole.polygons.size() == 2);
    for (std::size_t n = 0; n < w.shp.size(); ++n) {
      CAPTURE(n);
      CHECK_THROWS_AS(madd::parse_shapefile(std::string_view(w.shp).substr(0, n), w.shx, ""), madd::Error);
      // With the header's length made to match, the records themselves are cut.
      std::string cut = w.shp.substr(0, n);
      if (n >= 100 && n % 2 == 0) set_big(cut, 24, static_cast<std::uint32_t>(n / 2));
      // Cut between records, it is a shorter valid file: the records before the cut.
      const bool between = n == 100 || std::find(w.offsets.begin(), w.offsets.end(), n) != w.offsets.end();
      if (!between) CHECK_THROWS_AS(madd::parse_shapefile(cut, "", ""), madd::Error);
      if (between) CHECK(madd::parse_shapefile(cut, "", "").polygons.size() == (n == 100 ? 0U : 1U));
    }
    for (std::size_t n = 1; n < w.shx.size(); ++n)
      CHECK_THROWS_AS(madd::parse_shapefile(w.shp, std::string_view(w.shx).substr(0, n), ""), madd::Error);
    std::mt19937 random(static_cast<unsigned>(type));
    for (int trial = 0; trial < 3000; ++trial) {
      std::string shp = w.shp, shx = w.shx;
      std::string& target = trial % 4 == 0 ? shx : shp;
      for (int k = 0; k < 1 + trial % 3; ++k)
        target[std::uniform_int_distribution<std::size_t>(0, target.size() - 1)(random)] =
            static_cast<char>(std::uniform_int_distribution<int>(0, 255)(random));
      try {
        (void)madd::parse_shapefile(shp, shx, "");
      } catch (const madd::Error&) {}
    }
  }
}

TEST_CASE("nesting against every pair: random islands in lakes in islands, directions random") {
  std::mt19937 random(7);
  std::uint32_t deepest = 0;
  std::size_t most = 0;
  for (int trial = 0; trial < 40; ++trial) {
    CAPTURE(trial);
    std::vector<Ring> rings;
    const int roots = 1 + trial % 4;
    for (int k = 0; k < roots; ++k) add_nested(rings, random, {100.0 * k, 50.0 * (k % 2)}, 40.0, 1 + trial % 5, 40);
    std::shuffle(rings.begin(), rings.end(), random);
    const madd::detail::RingNesting expected = nesting_reference(rings);
    const madd::detail::RingNesting got = madd::detail::nest_rings(rings);
    CHECK(got.depth == expected.depth);
    CHECK(got.parent == expected.parent);
    deepest = std::max(deepest, *std::max_element(expected.depth.begin(), expected.depth.end()));
    most = std::max(most, rings.size());
    // Through the file: even depth an outer ring, odd a hole of its parent.
    std::vector<Ring> parts;
    for (const Ring& r : rings) parts.push_back(closed(r));
    const PolygonSet set = madd::parse_shapefile(write_shapefile(5, {Shape{5, parts}}).shp, "", "");
    const std::vector<std::uint32_t> outer_of = outer_ring_of_parts(set, rings.size());
    for (std::size_t i = 0; i < rings.size(); ++i) {
      CAPTURE(i);
      CHECK(outer_of[i] == (expected.depth[i] % 2 == 0 ? i : expected.parent[i]));
    }
  }
  CHECK(deepest >= 4);  // islands in lakes in islands in lakes
  CHECK(most >= 50);
}

TEST_CASE("a record of 1000+ rings: an ocean, 900 islands, lakes and islets, nested as every pair says") {
  // The ocean: a square with 4000 wiggly vertices; islands of 12-60 vertices
  // on a 30 x 30 lattice, some with lakes, some lakes with islets.
  std::mt19937 random(11);
  std::vector<Ring> rings;
  Ring ocean;
  for (int k = 0; k < 4000; ++k) {
    const double t = k / 1000.0, w = 0.3 * std::sin(k * 0.7);
    const int side = k / 1000;
    const double u = t - side;
    ocean.push_back(side == 0   ? Point{-2 + 34 * u, -2 + w}
                    : side == 1 ? Point{32 + w, -2 + 34 * u}
                    : side == 2 ? Point{32 - 34 * u, 32 + w}
                                : Point{-2 + w, 32 - 34 * u});
  }
  rings.push_back(ocean);
  for (int a = 0; a < 30; ++a)
    for (int b = 0; b < 30; ++b)
      add_nested(rings, random, {a + 0.5, b + 0.5}, 0.45, (a * 30 + b) % 7 == 0 ? 2 : 0,
                 12 + static_cast<std::size_t>((a * 31 + b * 17) % 49));
  CHECK(rings.size() > 1000);
  const madd::detail::RingNesting expected = nesting_reference(rings);
  CHECK(madd::detail::nest_rings(rings).depth == expected.depth);
  CHECK(madd::detail::nest_rings(rings).parent == expected.parent);
  std::size_t holes_of_ocean = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) holes_of_ocean += expected.parent[i] == 0 ? 1 : 0;
  CHECK(holes_of_ocean == 900);
}

TEST_CASE("bounding boxes and Z/M values are not checked: the points are the truth") {
  Shape z = polygon({square(0, 0, 10), square(2, 2, 2)}, 15);
  z.measures = true;
  const Written w = write_shapefile(15, {z});
  std::string shp = w.shp;
  for (std::size_t at = 36; at < 100; at += 8) set_double(shp, at, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t at = 112; at < 144; at += 8) set_double(shp, at, -1e300);  // the record's box
  // Z and M values: NaN and "no data" (< -1e38).
  const std::size_t values = 108 + 44 + 8 + 16 * 10;
  for (std::size_t at = values; at < shp.size(); at += 8) set_double(shp, at, at % 16 == 0 ? NAN : -1e39);
  const PolygonSet set = madd::parse_shapefile(shp, w.shx, "");
  REQUIRE(set.polygons.size() == 1);
  CHECK(set.polygons[0] == GisPolygon{ring_of(square(0, 0, 10), 0), {ring_of(square(2, 2, 2), 1)}, 1, 0, 0});
}

TEST_CASE("data/coast/lagoon.shp, written by ogr2ogr from lagoon.geojson: rings, holes and exact coordinates") {
  const PolygonSet set = read_coast_shapefile("lagoon");
  CHECK(set.coordinates == madd::Coordinates::lonlat);  // GDAL's .prj: GEOGCS["GCS_WGS_1984", ...]
  // The GeoJSON's rings (open), as written there (RFC 7946: outer rings counter-clockwise).
  const Ring lagoon = {{-70.5, 43.0}, {-70.0, 43.0}, {-70.0, 43.25}, {-70.125, 43.375}, {-70.25, 43.5}, {-70.5, 43.5}};
  const Ring island = {
      {-70.4375, 43.0625}, {-70.4375, 43.3125}, {-70.3125, 43.375}, {-70.1875, 43.3125}, {-70.1875, 43.0625}};
  const Ring islet = {{-70.125, 43.0625}, {-70.125, 43.125}, {-70.0625, 43.125}, {-70.0625, 43.0625}};
  const Ring pond = {{-70.375, 43.125}, {-70.25, 43.125}, {-70.25, 43.25}, {-70.375, 43.25}};
  const Ring pond_islet = {{-70.34375, 43.15625}, {-70.34375, 43.21875}, {-70.28125, 43.21875}, {-70.28125, 43.15625}};
  const Ring inlet = {{-69.9375, 43.0}, {-69.8125, 43.0}, {-69.8125, 43.125}, {-69.9375, 43.125}};
  const Ring marsh = {{-69.75, 43.0}, {-69.5, 43.0}, {-69.5, 43.25}, {-69.75, 43.25}};
  const Ring marsh_hole = {{-69.75, 43.125}, {-69.625, 43.1875}, {-69.5625, 43.125}, {-69.625, 43.0625}};
  struct Expected {
    Ring outer;
    std::vector<Ring> holes;
    std::uint32_t feature, polygon, outer_source;
  };
  // Feature 2 has a null geometry: a Null shape record.
  const std::vector<Expected> expected = {{lagoon, {island, islet}, 0, 0, 0},
                                          {pond, {pond_islet}, 0, 1, 3},
                                          {inlet, {}, 1, 0, 0},
                                          {marsh, {marsh_hole}, 3, 0, 0}};
  REQUIRE(set.polygons.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    CAPTURE(k);
    const GisPolygon& p = set.polygons[k];
    CHECK(same_cycle(p.outer.points, expected[k].outer));
    CHECK(p.outer.source == expected[k].outer_source);
    CHECK(p.feature == expected[k].feature);
    CHECK(p.polygon == expected[k].polygon);
    CHECK(p.marker == 1);
    // GDAL writes the description's directions: outer rings clockwise, holes counter-clockwise.
    CHECK(madd::detail::ring_orientation(madd::detail::RingView(p.outer.points)) ==
          madd::detail::Orientation::clockwise);
    REQUIRE(p.holes.size() == expected[k].holes.size());
    for (std::size_t h = 0; h < p.holes.size(); ++h) {
      CHECK(same_cycle(p.holes[h].points, expected[k].holes[h]));
      CHECK(p.holes[h].source == expected[k].outer_source + 1 + h);
      CHECK(madd::detail::ring_orientation(madd::detail::RingView(p.holes[h].points)) ==
            madd::detail::Orientation::counter_clockwise);
    }
  }
  const auto [rings, positions] = loose_counts(slurp(fs::path(MADD_DATA_DIR) / "coast" / "lagoon.geojson"));
  CHECK(rings == 8);
  CHECK(rings_and_points(set) == std::pair{rings, positions - rings});  // the closing positions dropped
  // The .shx ogr2ogr wrote agrees; without it and without the .prj the same polygons.
  const PolygonSet bare = madd::parse_shapefile(slurp(fs::path(MADD_DATA_DIR) / "coast" / "lagoon.shp"), "", "");
  CHECK(bare == set);
}

TEST_CASE("data/coast/bay.shp, written by ogr2ogr from bay.geojson: as many rings and points as the GeoJSON") {
  const fs::path shp = fs::path(MADD_DATA_DIR) / "coast" / "bay.shp";
  if (!fs::exists(shp)) return;
  const PolygonSet set = read_coast_shapefile("bay");
  CHECK(set.coordinates == madd::Coordinates::lonlat);
  // The counts of bay.geojson (data/coast/README.md; ogrinfo -al reads the
  // same from bay.shp: 301 + 1 rings of 6272 + 41 positions, closing ones
  // included): the sea, an outer ring of 2037 vertices with 300 islands as
  // holes (some touching each other or the coast at a vertex), and the lake
  // of 40 vertices. The LineString was left out, so the null geometry is
  // record 2.
  REQUIRE(set.polygons.size() == 2);
  const GisPolygon& sea = set.polygons[0];
  const GisPolygon& lake = set.polygons[1];
  CHECK(sea.feature == 0);
  CHECK(sea.outer.points.size() == 2037);
  CHECK(sea.holes.size() == 300);
  CHECK(lake.feature == 1);
  CHECK(lake.outer.points.size() == 40);
  CHECK(lake.holes.empty());
  CHECK(rings_and_points(set) == std::pair<std::size_t, std::size_t>{302, 6272 + 41 - 302});
  for (std::size_t h = 0; h < sea.holes.size(); ++h) CHECK(sea.holes[h].source == h + 1);
}

}  // TEST_SUITE
