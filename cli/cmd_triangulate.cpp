// `madd triangulate [-c] [-r] [-o PREFIX] FILE.poly`: constrained Delaunay
// triangulation of any PSLG, written as Triangle writes it (.node, .ele,
// .neigh, .edge). A FILE.node (points only) gives the Delaunay triangulation
// of its points.
#include <cstdio>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "input_domain.hpp"
#include "option_table.hpp"
#include "point_set.hpp"
#include "triangulation_files.hpp"
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
  write_file_atomically(args.prefix + ".node", triangulation_node_text(pslg, tri));
  write_file_atomically(args.prefix + ".ele", triangulation_ele_text(pslg, tri));
  write_file_atomically(args.prefix + ".neigh", triangulation_neigh_text(pslg, tri));
  write_file_atomically(args.prefix + ".edge", triangulation_edge_text(pslg, tri));
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
