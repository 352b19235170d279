// `madd check FILE.poly|FILE.node`: read and validate a domain, a PSLG or a
// point set, print a summary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "input_domain.hpp"
#include "option_table.hpp"
#include "point_set.hpp"
#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/model_output.hpp"
#include "madd/poly_io.hpp"
#include "madd/polygons.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::cli {
namespace {

constexpr const char* check_intro = "usage: madd check [options] FILE.poly|FILE.node|FILE.geojson|FILE.shp|FILE.14\n\n"
                                    "Reads and validates a domain (Triangle .poly) and prints a summary: vertices,\n"
                                    "segments, holes, regions, area, bounding box and shortest segment, and the\n"
                                    "interior constraints it holds (interior and dangling segments, isolated\n"
                                    "vertices, vertices on segments).\n"
                                    "A PSLG that is not a domain (segments or isolated vertices outside it, open\n"
                                    "polylines, parts apart: what madd triangulate takes) is accepted too; its\n"
                                    "summary counts each kind, and says why madd decompose and madd mesh refuse it.\n"
                                    "A point set (a .node, or a .poly without segments and holes: what madd\n"
                                    "triangulate takes) is checked for coordinates, duplicates and at least one\n"
                                    "triangle; the summary gives points, bounding box, convex hull and closest pair.\n"
                                    "A GeoJSON file or shapefile of water polygons is made a domain as madd mesh\n"
                                    "makes it (clipped, projected, cleaned: docs/coastal.md) and that domain is\n"
                                    "summarised, with what cleaning did. An ADCIRC fort.14 (FILE.14) is read back\n"
                                    "and checked: counts, orientation, boundary lists, islands closed.\n\n"
                                    "options:\n";

constexpr const char* check_exit_codes =
    "\nexit codes: 0 valid, 2 usage error, 3 bad input (one line: path:line:column: message)\n";

struct CheckArgs {
  CommandLine line;
  std::string path;
  bool quiet = false;
};

struct Box {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
};

Box bounding_box(const Pslg& pslg) {
  Box b;
  for (const Point& p : pslg.points) {
    b.xmin = std::min(b.xmin, p.x);
    b.xmax = std::max(b.xmax, p.x);
    b.ymin = std::min(b.ymin, p.y);
    b.ymax = std::max(b.ymax, p.y);
  }
  return b;
}

void print_summary(const std::string& path, const Pslg& pslg) {
  const auto [xmin, ymin, xmax, ymax] = bounding_box(pslg);
  double shortest = std::numeric_limits<double>::infinity();
  std::size_t shortest_id = 0;
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const double len = distance(pslg.points[pslg.segments[s].a], pslg.points[pslg.segments[s].b]);
    if (len < shortest) {
      shortest = len;
      shortest_id = s;
    }
  }
  std::printf("%s: valid domain\n", path.c_str());
  std::printf("  vertices          %zu\n", pslg.points.size());
  std::printf("  segments          %zu\n", pslg.segments.size());
  // Interior constraints, where a vertex is not on exactly two segments (a
  // closed interior loop alone is not told apart from the rings here).
  std::vector<std::uint32_t> degree(pslg.points.size(), 0);
  for (const Segment& seg : pslg.segments) ++degree[seg.a], ++degree[seg.b];
  if (std::any_of(degree.begin(), degree.end(), [](std::uint32_t d) { return d != 2; })) {
    const PslgSummary inner = summarize_pslg(pslg);
    std::printf("  interior segments %zu (%zu dangling ends, %zu vertices on segments)\n", inner.interior_segments,
                inner.dangling_ends, inner.vertices_inside_segments);
    std::printf("  isolated vertices %zu\n", inner.isolated_vertices);
  }
  std::printf("  holes             %zu\n", pslg.holes.size());
  std::printf("  regions           %zu\n", pslg.regions.size());
  std::printf("  attributes        %u per vertex\n", pslg.attributes_per_point);
  std::printf("  area              %.17g\n", domain_area(pslg));
  std::printf("  bounding box      [%.17g, %.17g] x [%.17g, %.17g]\n", xmin, xmax, ymin, ymax);
  std::printf("  shortest segment  %.17g (segment %zu)\n", shortest, shortest_id + pslg.first_index);
}

// A point set: its Delaunay triangulation gives the hull (its boundary edges,
// and the area it covers) and the closest pair (always a Delaunay edge).
void print_point_set_summary(const std::string& path, const Pslg& pslg, const Triangulation& tri) {
  const auto [xmin, ymin, xmax, ymax] = bounding_box(pslg);
  double hull_area = 0.0, closest = std::numeric_limits<double>::infinity();
  std::size_t hull_edges = 0;
  std::uint32_t closest_a = 0, closest_b = 0;
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    const auto& v = tri.triangles[t];
    hull_area += signed_area(tri.points[v[0]], tri.points[v[1]], tri.points[v[2]]);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u == no_index) ++hull_edges;
      else if (u < t) continue;  // each inner edge once
      const std::uint32_t a = v[(i + 1) % 3], b = v[(i + 2) % 3];
      const double d = distance(tri.points[a], tri.points[b]);
      if (d < closest) {
        closest = d;
        closest_a = std::min(a, b);
        closest_b = std::max(a, b);
      }
    }
  }
  std::printf("%s: valid point set\n", path.c_str());
  std::printf("  points            %zu\n", pslg.points.size());
  std::printf("  attributes        %u per vertex\n", pslg.attributes_per_point);
  std::printf("  bounding box      [%.17g, %.17g] x [%.17g, %.17g]\n", xmin, xmax, ymin, ymax);
  std::printf("  hull              %zu vertices, area %.17g\n", hull_edges, hull_area);
  std::printf("  closest pair      %.17g (vertices %u and %u)\n", closest, closest_a + pslg.first_index,
              closest_b + pslg.first_index);
  std::printf("  no segments: madd triangulate takes it; madd decompose needs a domain\n");
}

// A PSLG that validate() refuses as a domain: what it holds, and the
// domain error (located) that decompose and mesh give for it.
void print_pslg_summary(const std::string& path, const Pslg& pslg, const InvalidInputError& not_a_domain) {
  const PslgSummary s = summarize_pslg(pslg);
  const auto [xmin, ymin, xmax, ymax] = bounding_box(pslg);
  std::printf("%s: valid PSLG, not a domain\n", path.c_str());
  std::printf("  vertices          %zu\n", pslg.points.size());
  std::printf("  segments          %zu (%zu boundary, %zu interior, %zu outside)\n", pslg.segments.size(),
              s.boundary_segments, s.interior_segments, s.outside_segments);
  std::printf("  isolated vertices %zu (%zu inside)\n", s.isolated_vertices, s.isolated_inside);
  std::printf("  vertices on segments %zu\n", s.vertices_inside_segments);
  std::printf("  dangling ends     %zu\n", s.dangling_ends);
  std::printf("  holes             %zu\n", pslg.holes.size());
  std::printf("  regions           %zu\n", pslg.regions.size());
  std::printf("  parts             %zu\n", s.parts);
  std::printf("  area              %.17g\n", s.area);
  std::printf("  bounding box      [%.17g, %.17g] x [%.17g, %.17g]\n", xmin, xmax, ymin, ymax);
  std::printf("  madd triangulate takes it; madd decompose and madd mesh refuse it:\n  %s\n", not_a_domain.what());
}

// A GeoJSON file or shapefile: the domain its water makes (clipped,
// projected, cleaned), what cleaning did, and the domain written on request.
int check_polygon_file(const CheckArgs& args) {
  const CoastDomain coast = read_input_domain(args.path, args.line, nullptr);
  if (!args.line.write_poly_file.empty())
    write_file_atomically(args.line.write_poly_file,
                          format_poly(coast.domain, "the domain of " + args.path + " as madd cleaned it, in metres"));
  if (!args.quiet) {
    std::printf("%s\n", coast_report_line(args.path, coast).c_str());
    print_summary(args.path, coast.domain);
  }
  return exit_ok;
}

// An ADCIRC fort.14 (FILE.14): read strictly, then checked (counts,
// orientation, every boundary edge in exactly one list, islands closed).
bool is_fort14(const std::string& path) { return std::filesystem::path(path).extension() == ".14"; }

int check_fort14_file(const CheckArgs& args) {
  const Fort14 grid = read_fort14_file(args.path);
  const Verification check = check_fort14(grid);
  if (!check.ok()) {
    std::string message = args.path + ": not a valid fort.14: " + check.problems.front();
    if (check.problems.size() > 1) message += " (and " + std::to_string(check.problems.size() - 1) + " more problems)";
    throw InvalidInputError(InputProblem::other, message);
  }
  if (args.quiet) return exit_ok;
  std::size_t islands = 0, nodes = 0;
  for (const Fort14Boundary& b : grid.land_boundaries) islands += b.type % 10 == 1 ? 1 : 0;
  for (const Fort14Boundary& b : grid.open_boundaries) nodes += b.nodes.size();
  std::printf("%s: valid fort.14\n", args.path.c_str());
  std::printf("  title             %s\n", grid.title.c_str());
  std::printf("  nodes             %zu\n", grid.points.size());
  std::printf("  elements          %zu\n", grid.elements.size());
  std::printf("  open boundaries   %zu (%zu nodes)\n", grid.open_boundaries.size(), nodes);
  std::printf("  land boundaries   %zu (%zu islands, %llu nodes)\n", grid.land_boundaries.size(), islands,
              static_cast<unsigned long long>(grid.declared_land_nodes));
  return exit_ok;
}

int check_body(void* context) {
  const auto& args = *static_cast<CheckArgs*>(context);
  if (is_polygon_file(args.path)) return check_polygon_file(args);
  if (is_fort14(args.path)) return check_fort14_file(args);
  PolyFile file = read_poly_file(args.path);
  if (file.pslg.segments.empty() && file.pslg.holes.empty()) {
    ValidateOptions options;
    options.allow_point_set = true;
    validate(file.pslg, file.source, options);
    const Triangulation tri = triangulate_points(file.pslg, args.path);
    if (!args.quiet) print_point_set_summary(args.path, file.pslg, tri);
    return exit_ok;
  }
  try {
    validate(file.pslg, file.source);
  } catch (const InvalidInputError& not_a_domain) {
    validate_pslg(file.pslg, file.source);  // not even a PSLG: that error is the one to report
    if (!args.quiet) print_pslg_summary(args.path, file.pslg, not_a_domain);
    return exit_ok;
  }
  if (!args.quiet) print_summary(args.path, file.pslg);
  return exit_ok;
}

int run_check(int argc, char** argv) {
  const CommandOptions& options = options_of("check");
  CommandLine line;
  if (const auto done =
          read_one_operand(options, argc, argv, line, check_intro + options_help(options) + check_exit_codes))
    return *done;
  CheckArgs args;
  args.line = line;
  args.path = line.operands.front();
  args.quiet = line.quiet;
  return run_guarded("check", check_body, &args);
}

const CommandRegistration registration({"check", "validate a domain, a PSLG or a point set and print a summary",
                                        run_check});

}  // namespace
}  // namespace madd::cli
