// `madd triangulate [-c] [-r] [-o PREFIX] FILE.poly`: constrained Delaunay
// triangulation of any PSLG, written as Triangle writes it (.node, .ele,
// .neigh, .edge). A FILE.node (points only) gives the Delaunay triangulation
// of its points.
#include <charconv>
#include <concepts>
#include <cstdio>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "input_domain.hpp"
#include "option_table.hpp"
#include "point_set.hpp"
#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "madd/poly_io.hpp"
#include "madd/polygons.hpp"
#include "madd/triangulation.hpp"

namespace madd::cli {
namespace {

constexpr const char* triangulate_intro =
    "usage: madd triangulate [options] FILE.poly|FILE.node|FILE.geojson|FILE.shp\n\n"
    "Constrained Delaunay triangulation of the planar straight line graph in\n"
    "FILE.poly: every vertex (isolated ones too) is a vertex of it, every segment\n"
    "(interior, dangling, split where a vertex lies on it) a chain of edges; the\n"
    "triangles are removed from the convex hull inwards up to the first segments\n"
    "and around every hole point, as Triangle -p does. Or the Delaunay\n"
    "triangulation of the points of FILE.node or of a FILE.poly without segments\n"
    "(covering their convex hull). Checked by verify_triangulation, then written\n"
    "in Triangle's formats: PREFIX.node, PREFIX.ele, PREFIX.neigh, PREFIX.edge.\n"
    "Ids start at the input file's first index.\n"
    "Markers follow Triangle: constrained edges carry their segment's marker, other\n"
    "edges 0 (hull edges 1 for points); vertices keep a nonzero input marker,\n"
    "else take a marker of a segment through them, else 1 on the boundary.\n\n"
    "options:\n";

constexpr const char* triangulate_exit_codes =
    "\n"
    "exit codes: 0 ok, 2 usage error, 3 bad input, 5 output not written, 70 internal error\n";

struct Args {
  CommandLine line;  // a polygon input's options (cli/input_domain.hpp)
  std::string input;
  std::string prefix;
  bool quiet = false;
  bool resolve = false;
  TriangulateOptions options;
};

// One output line: the values separated by spaces. Numbers go through
// std::to_chars (doubles as the shortest text that reads back to the same
// value): the files of a 10^6-point triangulation hold ~10^7 numbers, and
// printf-style formatting of them cost more than the triangulation itself.
void put(std::string& out, double value) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}
void put(std::string& out, std::integral auto value) {
  char buf[24];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}
void line(std::string& out, auto first, auto... rest) {
  put(out, first);
  ((out += ' ', put(out, rest)), ...);
  out += '\n';
}

// Output marker of constrained edge (t, i): the segment's marker, or 1 when the
// file gave no segment markers (every segment is then a boundary).
int edge_marker(const Pslg& pslg, const Triangulation& tri, std::uint32_t t, int i) {
  const std::uint32_t s = tri.segment_of[t][i];
  if (s == no_index) return 0;
  return pslg.has_segment_markers ? pslg.segments[s].marker : 1;
}

std::vector<int> vertex_markers(const Pslg& pslg, const Triangulation& tri) {
  std::vector<int> mark(tri.points.size(), 0);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      int m = edge_marker(pslg, tri, t, i);
      if (m == 0 && tri.neighbours[t][i] == no_index) m = 1;
      for (const int k : {(i + 1) % 3, (i + 2) % 3}) {
        if (mark[tri.triangles[t][k]] == 0) mark[tri.triangles[t][k]] = m;
      }
    }
  }
  for (std::size_t v = 0; v < pslg.point_markers.size() && v < mark.size(); ++v) {
    if (pslg.point_markers[v] != 0) mark[v] = pslg.point_markers[v];
  }
  return mark;
}

std::string node_text(const Pslg& pslg, const Triangulation& tri) {
  const std::vector<int> mark = vertex_markers(pslg, tri);
  const unsigned base = pslg.first_index;
  std::string out;
  line(out, tri.points.size(), 2, pslg.attributes_per_point, 1);
  for (std::size_t v = 0; v < tri.points.size(); ++v) {
    put(out, v + base);
    for (const double x : {tri.points[v].x, tri.points[v].y}) (out += ' ', put(out, x));
    for (std::size_t k = 0; k < pslg.attributes_per_point; ++k) (out += ' ', put(out, pslg.attribute(v, k)));
    out += ' ';
    line(out, mark[v]);
  }
  return out;
}

std::string ele_text(const Pslg& pslg, const Triangulation& tri) {
  const unsigned base = pslg.first_index;
  std::string out;
  const bool attributes = !tri.attributes.empty();
  line(out, tri.triangle_count(), 3, attributes ? 1 : 0);
  for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
    const auto& c = tri.triangles[t];
    if (attributes) {
      line(out, t + base, c[0] + base, c[1] + base, c[2] + base, tri.attributes[t]);
    } else {
      line(out, t + base, c[0] + base, c[1] + base, c[2] + base);
    }
  }
  return out;
}

std::string neigh_text(const Pslg& pslg, const Triangulation& tri) {
  const long long base = pslg.first_index;
  std::string out;
  line(out, tri.triangle_count(), 3);
  for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
    long long n[3];
    for (int i = 0; i < 3; ++i) n[i] = tri.neighbours[t][i] == no_index ? -1 : tri.neighbours[t][i] + base;
    line(out, static_cast<long long>(t) + base, n[0], n[1], n[2]);
  }
  return out;
}

// Each edge once: from the triangle with the smaller index, or the only one.
std::string edge_text(const Pslg& pslg, const Triangulation& tri) {
  const unsigned base = pslg.first_index;
  std::string body;
  std::size_t count = 0;
  const bool hull_marks = pslg.segments.empty();
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u != no_index && u < t) continue;
      int m = edge_marker(pslg, tri, t, i);
      if (hull_marks && u == no_index) m = 1;
      ++count;
      line(body, count - 1 + base, tri.triangles[t][(i + 1) % 3] + base, tri.triangles[t][(i + 2) % 3] + base, m);
    }
  }
  std::string out;
  line(out, count, 1);
  return out + body;
}

bool ends_with(const std::string& s, const char* suffix) {
  const std::string tail = suffix;
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A point set (a .node, or a .poly without segments, as Triangle takes it)
// is triangulated over its convex hull (cli/point_set.hpp); anything else is
// a PSLG, its crossings resolved first when asked.
struct Triangulated {
  Pslg pslg;
  Triangulation tri;
  std::string note;
};

Triangulated triangulate_input(const Args& args) {
  PolyFile file = is_polygon_file(args.input)
                      ? PolyFile{read_input_domain(args.input, args.line, args.quiet ? nullptr : stderr).domain, {}}
                      : read_poly_file(args.input);
  Triangulated out;
  if (file.pslg.segments.empty()) {
    validate_pslg(file.pslg, file.source);
    out.tri = triangulate_points(file.pslg, args.input);
    if (args.options.region_attributes) out.tri = triangulate(file.pslg, args.options);  // the same triangles
    out.pslg = std::move(file.pslg);
    return out;
  }
  ValidatePslgOptions validation;
  validation.allow_intersections = args.resolve;
  validate_pslg(file.pslg, file.source, validation);
  if (args.resolve) {
    ResolvedPslg resolved = resolve_intersections(file.pslg);
    if (resolved.crossings + resolved.overlaps > 0)
      out.note = " (resolved " + std::to_string(resolved.crossings) + " crossing(s), " +
                 std::to_string(resolved.overlaps) + " overlap(s): " + std::to_string(resolved.new_vertices) +
                 " new vertices)";
    file.pslg = std::move(resolved.pslg);
  }
  out.pslg = std::move(file.pslg);
  out.tri = triangulate(out.pslg, args.options);
  return out;
}

int triangulate_body(void* context) {
  const auto& args = *static_cast<Args*>(context);
  const Triangulated result = triangulate_input(args);
  const Pslg& pslg = result.pslg;
  const Triangulation& tri = result.tri;
  const bool points_only = pslg.segments.empty();
  const Verification check = verify_triangulation(tri, points_only ? nullptr : &pslg, args.options);
  if (!check.ok()) throw InternalError("the triangulation failed its check: " + check.problems.front());
  write_file_atomically(args.prefix + ".node", node_text(pslg, tri));
  write_file_atomically(args.prefix + ".ele", ele_text(pslg, tri));
  write_file_atomically(args.prefix + ".neigh", neigh_text(pslg, tri));
  write_file_atomically(args.prefix + ".edge", edge_text(pslg, tri));
  if (!args.quiet) {
    std::printf("%s: %zu vertices, %zu triangles%s -> %s.{node,ele,neigh,edge}\n", args.input.c_str(),
                tri.points.size(), tri.triangle_count(), result.note.c_str(), args.prefix.c_str());
  }
  return exit_ok;
}

int run_triangulate(int argc, char** argv) {
  const CommandOptions& options = options_of("triangulate");
  CommandLine line;
  const std::string help = triangulate_intro + options_help(options) + triangulate_exit_codes;
  if (const auto done = read_one_operand(options, argc, argv, line, help)) return *done;
  Args args;
  args.line = line;
  args.input = line.operands.front();
  args.prefix = line.output;
  args.quiet = line.quiet;
  args.resolve = line.resolve_crossings;
  args.options = line.triangulate;
  if (args.prefix.empty()) {
    std::string stem = args.input;
    for (const char* ext : {".poly", ".node", ".geojson", ".json", ".shp"}) {
      const std::size_t n = std::string_view(ext).size();
      if (stem.size() > n && ends_with(stem, ext)) {
        stem.resize(stem.size() - n);
        break;
      }
    }
    args.prefix = stem + ".1";
  }
  return run_guarded("triangulate", triangulate_body, &args);
}

const CommandRegistration registration({"triangulate", "constrained Delaunay triangulation, Triangle's outputs",
                                        run_triangulate});

}  // namespace
}  // namespace madd::cli
