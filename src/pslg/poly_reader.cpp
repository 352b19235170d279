// Strict reader for Triangle's .poly and .node files (docs/formats.md, "Input").
//
// Accepted as Triangle accepts it: '#' comments anywhere, blank lines, CRLF,
// 0- or 1-based ids (the first id read decides), optional header fields
// (dimension 2, no attributes, no markers by default), a missing regions
// section, a region line without its max-area field (Triangle then uses the
// attribute for both), and a vertex count of 0 meaning "read <stem>.node".
// Stricter than Triangle, on purpose (docs/formats.md, "Bad input"): every field
// must be a whole number token (no "1.5abc", no commas), ids must run
// consecutively from the base, extra fields on a line and any text after the
// last section are errors, and coordinates must be finite.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "pslg/poly_reader_lexer.hpp"

namespace madd {
namespace {

using detail::PolyLexer;

// The id base (0 or 1) is decided by the first id of the file.
struct IdBase {
  bool known = false;
  std::uint32_t first = 1;
  std::uint32_t decided_on_line = 0;
};

// n item lines of `fields` fields each need at least 2*fields*n - 1 bytes (one
// byte per field plus a separator). Rejecting larger counts up front means a
// lying header fails fast and never allocates (docs/formats.md, "Bad input").
void check_count_fits(const PolyLexer& lx, std::uint32_t n, std::uint64_t fields, std::size_t column,
                      const char* what) {
  if (n == 0) return;
  const std::uint64_t avail = static_cast<std::uint64_t>(lx.remaining_bytes()) + 1;
  const std::uint64_t per_item = 2 * fields;
  if (per_item > avail || n > avail / per_item) {
    lx.fail_column(column, "header declares " + std::to_string(n) + " " + what + ", but the remaining " +
                               std::to_string(avail - 1) + " bytes of the file cannot hold them");
  }
}

// Checks that item `i` of a section of `count` items carries the id base+i.
void expect_id(PolyLexer& lx, IdBase& base, std::int64_t id, std::uint32_t i, std::uint32_t count, const char* what) {
  if (!base.known) {
    if (id != 0 && id != 1)
      lx.fail_token(std::string("the first ") + what + " id must be 0 or 1, got " + std::to_string(id));
    base = {true, static_cast<std::uint32_t>(id), lx.line()};
  }
  const std::int64_t expected = std::int64_t{base.first} + i;
  if (id == expected) return;
  const std::int64_t last = std::int64_t{base.first} + count - 1;
  std::string msg = std::string(what) + " id " + std::to_string(id);
  if (id < base.first || id > last) {
    msg += " is out of range " + std::to_string(base.first) + ".." + std::to_string(last);
  } else if (id < expected) {
    msg += " is repeated";
  } else {
    msg += " is out of order";
  }
  lx.fail_token(msg + ": expected " + std::to_string(expected) + " (ids are " + std::to_string(base.first) +
                "-based, as decided on line " + std::to_string(base.decided_on_line) + ")");
}

std::uint32_t read_endpoint(PolyLexer& lx, const IdBase& base, std::uint32_t n_points) {
  const std::int64_t id = lx.id("segment endpoint");
  const std::int64_t first = base.known ? base.first : 1;
  if (id < first || id >= first + n_points) {
    lx.fail_token("segment endpoint " + std::to_string(id) + " is not a vertex id (vertices are " +
                  std::to_string(first) + ".." + std::to_string(first + n_points - 1) + ")");
  }
  return static_cast<std::uint32_t>(id - first);
}

struct VertexHeader {
  std::uint32_t count = 0;
  std::size_t count_column = 1;
  std::uint32_t attributes = 0;
  bool markers = false;
};

VertexHeader read_vertex_header(PolyLexer& lx) {
  lx.require_line("the vertex header '<#vertices> 2 <#attributes> <#markers>'");
  VertexHeader h;
  h.count = lx.count("vertex count");
  h.count_column = lx.token_column();
  if (lx.has_token() && lx.count("dimension") != 2) lx.fail_token("dimension must be 2");
  if (lx.has_token()) h.attributes = lx.count("attribute count");
  if (lx.has_token()) {
    const std::uint32_t m = lx.count("boundary marker count");
    if (m > 1) lx.fail_token("boundary marker count must be 0 or 1");
    h.markers = m == 1;
  }
  lx.end_of_line("the vertex header");
  return h;
}

// The start of item line i of a section of n: the line exists and carries
// the id the numbering expects.
void start_item(PolyLexer& lx, IdBase& base, std::uint32_t i, std::uint32_t n, const char* what, const char* id_label) {
  lx.require_item(what, i + (base.known ? base.first : 1), n);
  expect_id(lx, base, lx.id(id_label), i, n, what);
}

// A section header that holds only its count (holes, regions), checked to
// fit in what is left of the file, `fields` fields per item.
std::uint32_t read_section_count(PolyLexer& lx, const char* count_label, const char* header_label, std::uint64_t fields,
                                 const char* what) {
  const std::uint32_t n = lx.count(count_label);
  const std::size_t column = lx.token_column();
  lx.end_of_line(header_label);
  check_count_fits(lx, n, fields, column, what);
  return n;
}

void read_vertices(PolyLexer& lx, const VertexHeader& h, IdBase& base, PolyFile& out) {
  Pslg& p = out.pslg;
  check_count_fits(lx, h.count, 3ULL + h.attributes + (h.markers ? 1 : 0), h.count_column, "vertices");
  p.points.reserve(h.count);
  p.attributes_per_point = h.attributes;
  p.attributes.reserve(std::size_t{h.count} * h.attributes);
  if (h.markers) p.point_markers.reserve(h.count);
  out.source.point_lines.reserve(h.count);
  for (std::uint32_t i = 0; i < h.count; ++i) {
    start_item(lx, base, i, h.count, "vertex", "vertex id");
    const double x = lx.coordinate("x coordinate");
    const double y = lx.coordinate("y coordinate");
    p.points.push_back({x, y});
    for (std::uint32_t k = 0; k < h.attributes; ++k) p.attributes.push_back(lx.real("vertex attribute"));
    if (h.markers) p.point_markers.push_back(lx.marker("vertex boundary marker"));
    lx.end_of_line("the vertex");
    out.source.point_lines.push_back(lx.line());
  }
}

std::string companion_node_path(const std::string& poly_path) {
  const std::string ext = ".poly";
  if (poly_path.size() >= ext.size() && poly_path.compare(poly_path.size() - ext.size(), ext.size(), ext) == 0)
    return poly_path.substr(0, poly_path.size() - ext.size()) + ".node";
  return poly_path + ".node";
}

// One read of the whole file: the lexer then works on memory (fast, and the
// file size bounds every count before allocation).
bool read_whole_file(const std::string& path, std::string& text) {
  // A directory opens, and tellg then gives a size no file has (bad_alloc, exit 70, once).
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return false;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  if (size < 0) return false;
  text.resize(static_cast<std::size_t>(size));
  in.seekg(0);
  if (size > 0 && !in.read(text.data(), size)) return false;
  return true;
}

// Vertex count 0 in a .poly: the vertices live in the .node of the same stem.
void load_companion_node(PolyLexer& lx, std::size_t column, IdBase& base, PolyFile& out) {
  const std::string node_path = companion_node_path(lx.path());
  std::string text;
  if (!read_whole_file(node_path, text))
    lx.fail_column(column, "vertex count is 0 but the companion file '" + node_path + "' cannot be read");
  PolyFile node = parse_node(text, node_path);
  out.pslg.points = std::move(node.pslg.points);
  out.pslg.attributes_per_point = node.pslg.attributes_per_point;
  out.pslg.attributes = std::move(node.pslg.attributes);
  out.pslg.point_markers = std::move(node.pslg.point_markers);
  out.pslg.first_index = node.pslg.first_index;
  out.source.point_path = node_path;
  out.source.point_lines = std::move(node.source.point_lines);
  if (!out.pslg.points.empty()) base = {true, out.pslg.first_index, 0};
}

void read_segments(PolyLexer& lx, IdBase& base, PolyFile& out) {
  lx.require_line("the segment header '<#segments> <#markers>'");
  const std::uint32_t n = lx.count("segment count");
  const std::size_t column = lx.token_column();
  bool markers = false;
  if (lx.has_token()) {
    const std::uint32_t m = lx.count("segment marker count");
    if (m > 1) lx.fail_token("segment marker count must be 0 or 1");
    markers = m == 1;
  }
  lx.end_of_line("the segment header");
  check_count_fits(lx, n, markers ? 4 : 3, column, "segments");
  Pslg& p = out.pslg;
  p.has_segment_markers = markers;
  p.segments.reserve(n);
  out.source.segment_lines.reserve(n);
  const auto n_points = static_cast<std::uint32_t>(p.points.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    start_item(lx, base, i, n, "segment", "segment id");
    Segment s;
    s.a = read_endpoint(lx, base, n_points);
    s.b = read_endpoint(lx, base, n_points);
    if (markers) s.marker = lx.marker("segment boundary marker");
    lx.end_of_line("the segment");
    p.segments.push_back(s);
    out.source.segment_lines.push_back(lx.line());
  }
}

void read_holes(PolyLexer& lx, IdBase& base, PolyFile& out) {
  lx.require_line("the hole count");
  const std::uint32_t n = read_section_count(lx, "hole count", "the hole count", 3, "holes");
  out.pslg.holes.reserve(n);
  out.source.hole_lines.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    start_item(lx, base, i, n, "hole", "hole id");
    const double x = lx.coordinate("hole x coordinate");
    const double y = lx.coordinate("hole y coordinate");
    lx.end_of_line("the hole");
    out.pslg.holes.push_back({x, y});
    out.source.hole_lines.push_back(lx.line());
  }
}

// The regions section is optional, as in Triangle.
void read_regions(PolyLexer& lx, IdBase& base, PolyFile& out) {
  if (!lx.next_line()) return;
  const std::uint32_t n = read_section_count(lx, "region count", "the region count", 4, "regions");
  out.pslg.regions.reserve(n);
  out.source.region_lines.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    start_item(lx, base, i, n, "region", "region id");
    Region r;
    r.at.x = lx.coordinate("region x coordinate");
    r.at.y = lx.coordinate("region y coordinate");
    r.attribute = lx.real("region attribute");
    r.max_area = lx.has_token() ? lx.real("region maximum area") : r.attribute;
    lx.end_of_line("the region");
    out.pslg.regions.push_back(r);
    out.source.region_lines.push_back(lx.line());
  }
}

void expect_end(PolyLexer& lx, const char* after) {
  if (lx.next_line()) lx.fail_column(1, std::string("unexpected text after ") + after);
}

}  // namespace

PolyFile parse_node(std::string_view text, const std::string& path) {
  PolyLexer lx(text, path);
  PolyFile out;
  out.source.path = path;
  IdBase base;
  read_vertices(lx, read_vertex_header(lx), base, out);
  if (base.known) out.pslg.first_index = base.first;
  expect_end(lx, "the last vertex");
  return out;
}

PolyFile parse_poly(std::string_view text, const std::string& path) {
  PolyLexer lx(text, path);
  PolyFile out;
  out.source.path = path;
  IdBase base;
  const VertexHeader header = read_vertex_header(lx);
  if (header.count == 0) {
    load_companion_node(lx, header.count_column, base, out);
  } else {
    read_vertices(lx, header, base, out);
  }
  read_segments(lx, base, out);
  read_holes(lx, base, out);
  read_regions(lx, base, out);
  expect_end(lx, "the regions section");
  out.pslg.first_index = base.known ? base.first : 1;
  return out;
}

PolyFile read_poly_file(const std::string& path) {
  std::string text;
  if (!read_whole_file(path, text)) throw InputFileError(path + ": cannot read file");
  const std::string ext = ".node";
  const bool is_node = path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  return is_node ? parse_node(text, path) : parse_poly(text, path);
}

Pslg read_domain(const std::string& path, const ValidateOptions& options) {
  PolyFile file = read_poly_file(path);
  validate(file.pslg, file.source, options);
  return std::move(file.pslg);
}

}  // namespace madd
