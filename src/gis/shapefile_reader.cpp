// Strict reader for ESRI shapefiles (ESRI Shapefile Technical Description,
// July 1998), polygons only (include/madd/polygons.hpp).
//
// The .shp is a 100-byte header (file code 9994 and the file length in 16-bit
// words, big-endian; version 1000, shape type and bounding box, little-
// endian), then records: a big-endian header (record number from 1, content
// length in 16-bit words) and the content, little-endian (shape type; for a
// polygon its box, NumParts, NumPoints, Parts[], Points[], and for PolygonZ
// the Z range and values, then optionally the M range and values; for
// PolygonM optionally the M range and values). The .shx has the same header,
// then one (offset, content length) pair per record, big-endian, in words.
//
// Strict on purpose: the header's file length must be the file's size (GDAL
// and ESRI write it exactly; a mismatch means a truncated or padded file),
// record numbers run 1, 2, ..., every record's content has exactly the size
// its counts give, part starts increase from 0 below NumPoints, every non-
// Null record has the header's shape type, and the .shx, when given, agrees
// with the .shp entry for entry. Every count is checked against the bytes
// that hold it before anything is allocated for it. Not checked: the unused
// header words, the header's and the records' bounding boxes (the points are
// the truth), the Z and M values (dropped unread).
#include <bit>
#include <cmath>
#include <optional>

#include "kernel/coordinate_range.hpp"
#include "gis/ring_nesting.hpp"
#include "kernel/number_format.hpp"
#include "madd/error.hpp"
#include "madd/polygons.hpp"
#include "madd/pslg.hpp"

namespace madd {
namespace {

constexpr std::size_t header_size = 100;
constexpr std::uint32_t file_code = 9994;
constexpr std::int32_t file_version = 1000;
constexpr std::int32_t null_shape = 0, polygon = 5, polygon_z = 15, polygon_m = 25;

std::string shape_name(std::int32_t type) {
  const char* name = "not a shape type";
  switch (type) {
  case 0:
    name = "Null";
    break;
  case 1:
    name = "Point";
    break;
  case 3:
    name = "PolyLine";
    break;
  case 5:
    name = "Polygon";
    break;
  case 8:
    name = "MultiPoint";
    break;
  case 11:
    name = "PointZ";
    break;
  case 13:
    name = "PolyLineZ";
    break;
  case 15:
    name = "PolygonZ";
    break;
  case 18:
    name = "MultiPointZ";
    break;
  case 21:
    name = "PointM";
    break;
  case 23:
    name = "PolyLineM";
    break;
  case 25:
    name = "PolygonM";
    break;
  case 28:
    name = "MultiPointM";
    break;
  case 31:
    name = "MultiPatch";
    break;
  default:
    break;
  }
  return "shape type " + std::to_string(type) + " (" + name + ")";
}

std::string record_text(std::uint32_t k) { return "record " + std::to_string(k) + ": "; }

std::string point_text(Point p) {
  std::string text = "(";  // appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on a + chain
  text += detail::number_text(p.x);
  text += ", ";
  text += detail::number_text(p.y);
  text += ')';
  return text;
}

// The bytes of a .shp or .shx in the description's two byte orders. Every
// read is at an offset the caller has checked; a failure names the byte.
class ShapeBytes {
public:
  ShapeBytes(std::string_view bytes, std::string where) : bytes_(bytes), where_(std::move(where)) {}
  std::size_t size() const noexcept { return bytes_.size(); }
  std::uint32_t big32(std::size_t at) const noexcept {
    return std::uint32_t{byte(at)} << 24 | std::uint32_t{byte(at + 1)} << 16 | std::uint32_t{byte(at + 2)} << 8 |
           byte(at + 3);
  }
  std::int32_t little32(std::size_t at) const noexcept {
    return static_cast<std::int32_t>(std::uint32_t{byte(at + 3)} << 24 | std::uint32_t{byte(at + 2)} << 16 |
                                     std::uint32_t{byte(at + 1)} << 8 | byte(at));
  }
  double little_double(std::size_t at) const noexcept {
    std::uint64_t bits = 0;
    for (std::size_t i = 8; i-- > 0;) bits = bits << 8 | byte(at + i);
    return std::bit_cast<double>(bits);
  }
  Point point(std::size_t at) const noexcept { return {little_double(at), little_double(at + 8)}; }
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw InvalidInputError(InputProblem::other, where_ + "byte " + std::to_string(at) + ": " + message);
  }

private:
  std::uint8_t byte(std::size_t at) const noexcept { return static_cast<std::uint8_t>(bytes_[at]); }
  std::string_view bytes_;
  std::string where_;  // "path: " or "path: .shx "
};

[[noreturn]] void fail_geometry(const std::string& path, std::uint32_t k, std::uint32_t part,
                                std::optional<std::size_t> vertex, const std::string& message) {
  std::string where = path + ": record " + std::to_string(k) + ", part " + std::to_string(part);
  if (vertex) where += ", vertex " + std::to_string(*vertex);
  throw InvalidInputError(InputProblem::other, where + ": " + message);
}

// The 100-byte header of a .shp or .shx; returns its shape type, a polygon type.
std::int32_t read_file_header(const ShapeBytes& f) {
  if (f.size() >= 4 && f.big32(0) != file_code)
    f.fail(0, "file code " + std::to_string(f.big32(0)) + ", expected 9994: not a shapefile");
  if (f.size() < header_size) f.fail(f.size(), "the file ends inside its 100-byte header");
  const std::uint64_t words = f.big32(24);
  if (2 * words != f.size())
    f.fail(24, "the header gives the file length as " + std::to_string(words) + " 16-bit words (" +
                   std::to_string(2 * words) + " bytes), but the file has " + std::to_string(f.size()) + " bytes");
  if (f.little32(28) != file_version)
    f.fail(28, "version " + std::to_string(f.little32(28)) + ", expected " + std::to_string(file_version));
  const std::int32_t type = f.little32(32);
  if (type != polygon && type != polygon_z && type != polygon_m)
    f.fail(32, shape_name(type) + " is not a polygon type (5 Polygon, 15 PolygonZ or 25 PolygonM)");
  return type;
}

// The .shx, when given: its header agrees with the .shp's, and entry k holds
// record k's offset and content length (16-bit words, big-endian).
class ShapeIndex {
public:
  ShapeIndex(std::string_view shx, const std::string& path, std::int32_t shp_type) : bytes_(shx, path + ": .shx ") {
    if (shx.empty()) return;
    const std::int32_t type = read_file_header(bytes_);
    if (type != shp_type) bytes_.fail(32, shape_name(type) + " differs from the .shp's " + shape_name(shp_type));
    entries_ = (shx.size() - header_size) / 8;
    if ((shx.size() - header_size) % 8 != 0)
      bytes_.fail(header_size + 8 * entries_, "the index ends inside an entry (8 bytes each)");
  }
  void check(std::uint32_t k, std::size_t offset, std::uint64_t content_words) const {
    if (bytes_.size() == 0) return;
    if (k >= entries_)
      bytes_.fail(bytes_.size(), "the index ends after " + std::to_string(entries_) +
                                     " entries, but the .shp has record " + std::to_string(k) + " at byte " +
                                     std::to_string(offset));
    const std::size_t at = header_size + 8 * std::size_t{k};
    const std::uint64_t words = bytes_.big32(at);
    if (2 * words != offset)
      bytes_.fail(at, "entry " + std::to_string(k) + " gives record " + std::to_string(k) + "'s offset as " +
                          std::to_string(words) + " words (byte " + std::to_string(2 * words) +
                          "), but it starts at byte " + std::to_string(offset) + " of the .shp");
    if (bytes_.big32(at + 4) != content_words)
      bytes_.fail(at + 4, "entry " + std::to_string(k) + " gives record " + std::to_string(k) +
                              "'s content length as " + std::to_string(bytes_.big32(at + 4)) +
                              " words, but the .shp gives " + std::to_string(content_words));
  }
  void check_count(std::uint32_t records) const {
    if (bytes_.size() != 0 && entries_ > records)
      bytes_.fail(header_size + 8 * std::size_t{records}, "the index has " + std::to_string(entries_) +
                                                              " entries, but the .shp has " + std::to_string(records) +
                                                              " records");
  }

private:
  ShapeBytes bytes_;
  std::size_t entries_ = 0;
};

// Record k's header at byte `at`; returns its content length in bytes,
// checked to fit in the file and to hold a shape type.
std::size_t read_record_header(const ShapeBytes& f, std::size_t at, std::uint32_t k) {
  const std::size_t left = f.size() - at;
  if (left < 8)
    f.fail(at, record_text(k) + "the file ends inside the 8-byte record header (" + std::to_string(left) + " left)");
  const auto number = static_cast<std::int32_t>(f.big32(at));
  if (number != std::int64_t{k} + 1)
    f.fail(at, record_text(k) + "record number " + std::to_string(number) + ", expected " + std::to_string(k + 1) +
                   " (records are numbered from 1)");
  const std::uint64_t words = f.big32(at + 4);
  if (2 * words < 4)
    f.fail(at + 4, record_text(k) + "content length " + std::to_string(words) +
                       " words is too short for a shape type (4 bytes)");
  if (2 * words > left - 8)
    f.fail(at + 4, record_text(k) + "content length " + std::to_string(words) + " words (" + std::to_string(2 * words) +
                       " bytes) runs past the end of the file (" + std::to_string(left - 8) + " bytes left)");
  return static_cast<std::size_t>(2 * words);
}

// Where a polygon record's arrays lie; the part starts are checked.
struct RecordLayout {
  std::size_t parts_at = 0, points_at = 0;
  std::uint32_t parts = 0, points = 0;
  std::uint32_t start(const ShapeBytes& f, std::uint32_t r) const noexcept {
    return r < parts ? static_cast<std::uint32_t>(f.little32(parts_at + 4 * std::size_t{r})) : points;
  }
};

// The content sizes a record of these counts may have: Polygon exactly its
// points; PolygonZ with its Z values, measures optional; PolygonM with
// measures optional.
void check_content_size(const ShapeBytes& f, std::size_t c, std::size_t n, std::int32_t type, std::uint32_t k,
                        const RecordLayout& l) {
  const std::uint64_t base = 44 + 4 * std::uint64_t{l.parts} + 16 * std::uint64_t{l.points};
  const std::uint64_t values = 16 + 8 * std::uint64_t{l.points};  // a range and one value a point
  std::uint64_t plain = base, extra = base;
  std::string sizes = std::to_string(base) + " bytes of Polygon content";
  if (type == polygon_z) {
    plain = base + values, extra = base + 2 * values;
    sizes = std::to_string(plain) + " bytes of PolygonZ content (" + std::to_string(extra) + " with measures)";
  } else if (type == polygon_m) {
    extra = base + values;
    sizes =
        std::to_string(plain) + " bytes of PolygonM content without measures (" + std::to_string(extra) + " with them)";
  }
  if (n != plain && n != extra)
    f.fail(c + 36, record_text(k) + std::to_string(l.parts) + " parts and " + std::to_string(l.points) +
                       " points make " + sizes + ", but the record has " + std::to_string(n));
}

RecordLayout read_layout(const ShapeBytes& f, std::size_t c, std::size_t n, std::int32_t type, std::uint32_t k) {
  if (n < 44)
    f.fail(c, record_text(k) + std::to_string(n) +
                  " bytes of content cannot hold a polygon's shape type, box and counts (44 bytes)");
  const std::int32_t parts = f.little32(c + 36), points = f.little32(c + 40);
  if (parts < 0) f.fail(c + 36, record_text(k) + "negative part count " + std::to_string(parts));
  if (points < 0) f.fail(c + 40, record_text(k) + "negative point count " + std::to_string(points));
  if (parts == 0) f.fail(c + 36, record_text(k) + "a polygon of no parts (an empty shape is a Null shape)");
  RecordLayout l{c + 44, c + 44 + 4 * static_cast<std::size_t>(parts), static_cast<std::uint32_t>(parts),
                 static_cast<std::uint32_t>(points)};
  check_content_size(f, c, n, type, k, l);
  std::int64_t previous = -1;
  for (std::uint32_t r = 0; r < l.parts; ++r) {
    const std::size_t at = l.parts_at + 4 * std::size_t{r};
    const std::int64_t s = f.little32(at);
    const std::string part = record_text(k) + "part " + std::to_string(r) + " starts at point " + std::to_string(s);
    if (r == 0 && s != 0) f.fail(at, part + ", expected 0");
    if (r > 0 && s <= previous)
      f.fail(at, part + ", not after part " + std::to_string(r - 1) + " (point " + std::to_string(previous) + ")");
    if (s >= points) f.fail(at, part + ", beyond the record's " + std::to_string(points) + " points");
    previous = s;
  }
  return l;
}

bool in_lonlat_range(Point p) noexcept { return p.x >= -180.0 && p.x <= 180.0 && p.y >= -90.0 && p.y <= 90.0; }

// madd's supported range (kernel/coordinate_range.hpp), where the exact
// predicates that nest the rings are exact.
bool supported(double v) noexcept { return detail::in_exact_range(v); }

// Part r of record k: closed, at least 4 points, finite and in range; returned open.
std::vector<Point> read_ring(const ShapeBytes& f, const RecordLayout& l, std::uint32_t k, std::uint32_t r,
                             const std::string& path, bool& lonlat_range) {
  const std::uint32_t first = l.start(f, r), end = l.start(f, r + 1);
  std::vector<Point> ring;
  ring.reserve(end - first);  // backed by the content, whose size was checked
  for (std::uint32_t i = first; i < end; ++i) {
    const Point p = f.point(l.points_at + 16 * std::size_t{i});
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      fail_geometry(path, k, r, i - first, "coordinate " + point_text(p) + " is not finite");
    if (!supported(p.x) || !supported(p.y))
      fail_geometry(path, k, r, i - first,
                    "coordinate " + point_text(p) +
                        " is outside the supported range: every coordinate must be 0 or of magnitude within "
                        "[1e-40, 1e70]");
    lonlat_range = lonlat_range && in_lonlat_range(p);
    ring.push_back(p);
  }
  if (ring.size() < 4)
    fail_geometry(path, k, r, std::nullopt,
                  "a ring needs at least 4 points (its last equal to its first); this part has " +
                      std::to_string(ring.size()));
  if (ring.back() != ring.front())
    fail_geometry(path, k, r, ring.size() - 1,
                  "the ring is not closed: its last point " + point_text(ring.back()) + " differs from its first " +
                      point_text(ring.front()));
  ring.pop_back();
  return ring;
}

// A record's rings become polygons: each outer ring (even depth) in part
// order, with the holes (odd depth) whose smallest holder it is.
void add_polygons(std::vector<std::vector<Point>> rings, std::uint32_t k, std::vector<GisPolygon>& out) {
  const detail::RingNesting nesting = detail::nest_rings(rings);
  std::vector<std::size_t> slot(rings.size(), 0);
  std::uint32_t outers = 0;
  for (std::uint32_t r = 0; r < rings.size(); ++r) {
    if (nesting.depth[r] % 2 != 0) continue;
    slot[r] = out.size();
    out.push_back(GisPolygon{GisRing{std::move(rings[r]), r}, {}, 1, k, outers++});
  }
  for (std::uint32_t r = 0; r < rings.size(); ++r) {
    if (nesting.depth[r] % 2 == 0) continue;  // a hole's parent is one depth up: an outer ring
    out[slot[nesting.parent[r]]].holes.push_back(GisRing{std::move(rings[r]), r});
  }
}

struct RecordContext {
  const ShapeBytes& f;
  std::int32_t type;
  const std::string& path;
};

// Record k's content, n bytes at byte c: a Null shape, or a polygon of the file's type.
void read_record(const RecordContext& ctx, std::size_t c, std::size_t n, std::uint32_t k, std::vector<GisPolygon>& out,
                 bool& lonlat_range) {
  const ShapeBytes& f = ctx.f;
  const std::int32_t type = f.little32(c);
  if (type == null_shape) {
    if (n != 4)
      f.fail(c, record_text(k) + "a Null shape's content is 4 bytes, but the record has " + std::to_string(n));
    return;
  }
  if (type != ctx.type) f.fail(c, record_text(k) + shape_name(type) + " in a file of " + shape_name(ctx.type));
  const RecordLayout l = read_layout(f, c, n, type, k);
  std::vector<std::vector<Point>> rings;
  rings.reserve(l.parts);
  for (std::uint32_t r = 0; r < l.parts; ++r) rings.push_back(read_ring(f, l, k, r, ctx.path, lonlat_range));
  add_polygons(std::move(rings), k, out);
}

bool is_wkt_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool is_word_char(char c) noexcept {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

// What a .prj's WKT says by its first keyword (case-insensitive, after a
// UTF-8 byte order mark and white space): projected or geographic; nothing
// for an empty or blank .prj.
std::optional<Coordinates> prj_coordinates(std::string_view prj, const std::string& path) {
  if (prj.starts_with("\xEF\xBB\xBF")) prj.remove_prefix(3);
  std::size_t i = 0;
  while (i < prj.size() && is_wkt_space(prj[i])) ++i;
  if (i == prj.size()) return std::nullopt;
  std::size_t end = i;
  while (end < prj.size() && is_word_char(prj[end])) ++end;
  std::string word(prj.substr(i, end - i));
  for (char& c : word) c = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  if (word == "PROJCS" || word == "PROJCRS" || word == "PROJECTEDCRS") return Coordinates::projected;
  if (word == "GEOGCS" || word == "GEOGCRS" || word == "GEOGRAPHICCRS") return Coordinates::lonlat;
  std::string named = word.size() > 40 ? std::string(prj.substr(i, 40)) + "..." : std::string(prj.substr(i, end - i));
  if (word.empty()) {
    const auto c = static_cast<unsigned char>(prj[i]);
    static constexpr char hex[] = "0123456789ABCDEF";
    named = c >= 0x20 && c < 0x7F ? std::string(1, prj[i]) : std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  throw InvalidInputError(InputProblem::other, path + ": .prj: the coordinate system '" + named +
                                                   "' is neither projected (PROJCS) nor geographic (GEOGCS)");
}

}  // namespace

PolygonSet parse_shapefile(std::string_view shp, std::string_view shx, std::string_view prj, const std::string& path) {
  const ShapeBytes f(shp, path + ": ");
  const std::int32_t type = read_file_header(f);
  const ShapeIndex index(shx, path, type);
  const std::optional<Coordinates> declared = prj_coordinates(prj, path);
  PolygonSet out;
  bool lonlat_range = true;
  std::uint32_t k = 0;
  for (std::size_t at = header_size; at < f.size(); ++k) {
    const std::size_t n = read_record_header(f, at, k);
    index.check(k, at, n / 2);
    read_record(RecordContext{f, type, path}, at + 8, n, k, out.polygons, lonlat_range);
    at += 8 + n;
  }
  index.check_count(k);
  out.coordinates = declared ? *declared : lonlat_range ? Coordinates::lonlat : Coordinates::projected;
  return out;
}

}  // namespace madd
