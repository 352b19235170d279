// The rows of the option table (cli/option_table.hpp): each option once, with
// the field it sets and how its value is read. A setter only parses; ranges
// and conflicts are the library's check_options, said in the command's words
// by cli_message (cli/option_parse.cpp).
#include "option_table.hpp"

#include <algorithm>
#include <charconv>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "option_values.hpp"
#include "madd/expression.hpp"

namespace madd::cli {

namespace {

using Text = const char*;
using Flag = const std::string&;

// "--seed needs a whole number, got 'x'".
std::string refused(Flag flag, const char* what, Text value) { return flag + " " + what + ", got '" + value + "'"; }

std::string number(Text value, Flag flag, double& target) {
  double x = 0;
  if (!parse_number(value, x)) return refused(flag, "needs a number", value);
  target = x;
  return {};
}

// A whole number the target's type holds.
template <class T>
std::string count(Text value, Flag flag, T& target) {
  unsigned long long k = 0;
  if (!parse_count(value, std::numeric_limits<T>::max(), k)) return refused(flag, "needs a whole number", value);
  target = static_cast<T>(k);
  return {};
}

// A whole number in [low, high], for the options the library has no check of
// (partition's, gpmetis's ranges).
template <class T>
std::string count_in(Text value, Flag flag, unsigned long long low, unsigned long long high, T& target) {
  unsigned long long k = 0;
  if (!parse_count(value, high, k) || k < low) {
    std::string what = "needs a whole number in [";  // appended piece by piece: GCC 12 warns on a + chain here
    what += std::to_string(low);
    what += ", ";
    what += std::to_string(high);
    what += "]";
    return refused(flag, what.c_str(), value);
  }
  target = static_cast<T>(k);
  return {};
}

// An expression of x and y; its errors are located in the flag's value ("--size-fn:1:3: ...").
std::string function(Text value, Flag flag, std::function<double(double, double)>& target) {
  try {
    target = parse_expression(value, flag).function();
    return {};
  } catch (const Error& e) {
    return std::string(e.what()) + ", got '" + value + "'";
  }
}

// An option without a value: it turns a switch on (or off).
std::string switch_on(bool& target) {
  target = true;
  return {};
}
std::string switch_off(bool& target) {
  target = false;
  return {};
}

std::string text(Text value, std::string& target) {
  target = value;
  return {};
}

// A size bound: a positive area (0, the library's "none", is what leaving the option out says).
std::string area(Text value, Flag flag, double& target) {
  double x = 0;
  if (!parse_number(value, x) || !(x > 0)) return refused(flag, "needs an area > 0", value);
  target = x;
  return {};
}

// A comma-separated list of whole numbers, signs allowed ("1,-2,3"), each
// one an int holds; the list replaces an earlier one.
std::string markers(Text value, Flag flag, std::vector<int>& target) {
  std::vector<int> list;
  const std::string_view all = value;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = std::min(all.find(',', from), all.size());
    const std::string_view item = all.substr(from, comma - from);
    int marker = 0;
    const char* begin = item.data();
    const char* end = begin + item.size();
    const auto [stop, error] = std::from_chars(begin, end, marker);
    if (item.empty() || error != std::errc() || stop != end)
      return refused(flag, "needs whole numbers separated by commas", value);
    list.push_back(marker);
    if (comma == all.size()) break;
    from = comma + 1;
  }
  target = std::move(list);
  return {};
}

// Megabytes to bytes: a value a size_t holds.
std::string megabytes(Text value, Flag flag, std::size_t& target) {
  double x = 0;
  if (!parse_number(value, x) || x < 0 || x > 1e12) return refused(flag, "needs megabytes in [0, 1e12]", value);
  target = static_cast<std::size_t>(x * 1048576.0);
  return {};
}

// gpmetis's option `name` with the one value that names what madd does anyway.
std::string only(Text value, const char* name, const char* only_value, const char* why) {
  if (std::string(value) == only_value) return {};
  return std::string("-") + name + "=" + value + " is not supported: " + why;
}

std::string balance(Text value, Flag flag, bool& by_work) {
  const std::string v = value;
  if (v != "work" && v != "area") return flag + " takes 'work' or 'area', got '" + v + "'";
  by_work = v == "work";
  return {};
}

// K numbers separated by commas ("-70,43.5,-69.5,43.9").
std::string numbers(Text value, Flag flag, std::size_t k, std::vector<double>& target) {
  std::vector<double> list;
  const std::string all = value;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = std::min(all.find(',', from), all.size());
    double x = 0;
    if (!parse_number(all.substr(from, comma - from).c_str(), x)) break;
    list.push_back(x);
    if (comma == all.size()) break;
    from = comma + 1;
  }
  if (list.size() != k)
    return refused(flag, k == 4 ? "needs four numbers X0,Y0,X1,Y1" : "needs two numbers X,Y", value);
  target = std::move(list);
  return {};
}

std::string clip_box(Text value, Flag flag, std::optional<ClipBox>& target) {
  std::vector<double> v;
  std::string problem = numbers(value, flag, 4, v);
  if (problem.empty()) target = ClipBox{v[0], v[1], v[2], v[3]};
  return problem;
}

std::string point(Text value, Flag flag, std::optional<Point>& target) {
  std::vector<double> v;
  std::string problem = numbers(value, flag, 2, v);
  if (problem.empty()) target = Point{v[0], v[1]};
  return problem;
}

using enum Arity;
using enum Scope;

// Every option, once. The field names are those check_options puts in its
// OptionError (and may be renamed with the fields).
constexpr Option rows[] = {
    // The decomposition (DecomposeOptions).
    {"subdomains", 'n', required, "N", decomposition, "subdomains",
     [](CommandLine& l, Text v, Flag f) {
       l.subdomains_given = true;
       return count(v, f, l.mesh.decomposition.subdomains);
     }},
    {"min-angle", 0, required, "DEG", decomposition, "separator_angle_deg",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.separator_angle_deg); }},
    {"refine", 'r', required, "R", decomposition, "boundary_refinement",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.boundary_refinement); }},
    {"imbalance", 'i', required, "I", decomposition, "min_split_quality",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.min_split_quality); }},
    {"threads", 'j', required, "T", decomposition, "threads",
     [](CommandLine& l, Text v, Flag f) { return count(v, f, l.mesh.decomposition.threads); }},
    // The seed of whatever the command runs: the decomposition, or partition's bisections.
    {"seed", 's', required, "S", decomposition, "seed",
     [](CommandLine& l, Text v, Flag f) {
       const std::string problem = count(v, f, l.mesh.decomposition.seed);
       l.partition.seed = l.mesh.decomposition.seed;
       return problem;
     }},
    {"smoothing", 0, required, "K", decomposition, "smoothing_iterations",
     [](CommandLine& l, Text v, Flag f) { return count(v, f, l.mesh.decomposition.smoothing_iterations); }},
    {"rebalance", 0, required, "X", decomposition, "repair_balance_above",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.repair_balance_above); }},
    // The paper's grading factor a; --gradation is the size field's (below).
    {"weight-gradation", 'a', required, "A", decomposition, "gradation",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.gradation); }},
    {"adaptive-refine", 0, required, "L", decomposition, "adaptive_boundary_refinement",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.adaptive_boundary_refinement); }},
    {"interpolation", 'p', required, "P", decomposition, "interpolation",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.interpolation); }},
    {"weight-fn", 0, required, "EXPR", decomposition, "weight_function",
     [](CommandLine& l, Text v, Flag f) { return function(v, f, l.mesh.decomposition.weight_function); }},
    {"area-fn", 0, required, "EXPR", decomposition, "subdomain_area_function",
     [](CommandLine& l, Text v, Flag f) { return function(v, f, l.mesh.decomposition.subdomain_area_function); }},
    {"weights", 0, required, "FILE", decomposition, "weight_samples",
     [](CommandLine& l, Text v, Flag) { return text(v, l.weights_file); }},
    {"areas", 0, required, "FILE", decomposition, "subdomain_area_samples",
     [](CommandLine& l, Text v, Flag) { return text(v, l.areas_file); }},
    {"area-bound", 0, required, "X", decomposition, "subdomain_area_ratio",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.subdomain_area_ratio); }},
    {"time-limit", 0, required, "S", decomposition, "time_limit_seconds",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.decomposition.time_limit_seconds); }},
    {"max-memory", 0, required, "MB", decomposition, "max_memory_bytes",
     [](CommandLine& l, Text v, Flag f) { return megabytes(v, f, l.mesh.decomposition.max_memory_bytes); }},

    // The mesh (MeshSizeOptions, MeshOptions).
    {"quality", 'q', required, "DEG", mesh_size, "min_triangle_angle_deg",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.min_triangle_angle_deg); }},
    {"max-area", 'a', required, "A", mesh_size, "max_triangle_area",
     [](CommandLine& l, Text v, Flag f) { return area(v, f, l.mesh.size.max_triangle_area); }},
    {"size-fn", 0, required, "EXPR", mesh_size, "triangle_area_function",
     [](CommandLine& l, Text v, Flag f) { return function(v, f, l.mesh.size.triangle_area_function); }},
    {"sizes", 0, required, "FILE", mesh_size, "triangle_area_samples",
     [](CommandLine& l, Text v, Flag) { return text(v, l.sizes_file); }},
    {"sizes-nearest", 0, none, nullptr, mesh_size, "sample_interpolation",
     [](CommandLine& l, Text, Flag) {
       l.mesh.size.sample_interpolation = MeshSizeOptions::SampleInterpolation::nearest;
       return std::string();
     }},
    // The size field (docs/mesh.md), in edge lengths.
    {"hmin", 0, required, "LEN", mesh_size, "min_edge_length",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.min_edge_length); }},
    {"hmax", 0, required, "LEN", mesh_size, "max_edge_length",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.max_edge_length); }},
    {"distance-rate", 0, required, "G", mesh_size, "distance_rate",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.distance_rate); }},
    {"cells-across", 0, required, "R", mesh_size, "cells_across",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.cells_across); }},
    {"gradation", 0, required, "G", mesh_size, "size_gradation",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.size_gradation); }},
    {"wavelength-cells", 0, required, "K", mesh_size, "wavelength_cells",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.wavelength_cells); }},
    {"slope-cells", 0, required, "K", mesh_size, "slope_cells",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.mesh.size.slope_cells); }},
    {"coast-markers", 0, required, "M,...", mesh_size, "coast_markers",
     [](CommandLine& l, Text v, Flag f) { return markers(v, f, l.mesh.size.coast_markers); }},
    {"balance", 0, required, "area|work", front_end, nullptr,
     [](CommandLine& l, Text v, Flag f) { return balance(v, f, l.mesh.balance_by_work); }},
    {"no-off-centres", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_off(l.mesh.off_centres); }},
    {"no-verify", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_off(l.mesh.verify); }},

    // A GIS polygon input (CoastOptions, docs/coastal.md).
    {"clip", 0, required, "BOX", coast, "clip",
     [](CommandLine& l, Text v, Flag f) { return clip_box(v, f, l.coast.clip); }},
    {"water-at", 0, required, "X,Y", coast, "water_at",
     [](CommandLine& l, Text v, Flag f) { return point(v, f, l.coast.water_at); }},
    {"min-island-area", 0, required, "A", coast, "min_island_area",
     [](CommandLine& l, Text v, Flag f) {
       l.min_island_area_given = true;
       return number(v, f, l.coast.min_island_area);
     }},
    {"write-poly", 0, required, "FILE.poly", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.write_poly_file); }},
    {"depth", 0, required, "FILE", front_end, nullptr, [](CommandLine& l, Text v, Flag) { return text(v, l.depth_file); }},
    {"depth-up", 0, none, nullptr, front_end, nullptr, [](CommandLine& l, Text, Flag) { return switch_on(l.depth_up); }},
    {"fort14", 0, required, "FILE", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.fort14_file); }},
    {"gr3", 0, required, "FILE", front_end, nullptr, [](CommandLine& l, Text v, Flag) { return text(v, l.gr3_file); }},
    {"2dm", 0, required, "FILE", front_end, nullptr, [](CommandLine& l, Text v, Flag) { return text(v, l.sms_file); }},
    {"lonlat", 0, none, nullptr, front_end, nullptr, [](CommandLine& l, Text, Flag) { return switch_on(l.lonlat); }},

    // Outputs.
    {"output", 'o', required, "FILE", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.output); }},
    {"split", 0, required, "DIR", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.split_dir); }},
    {"subdomains-file", 0, required, "FILE", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.subdomains_file); }},
    {"svg", 0, required, "FILE.svg", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.svg_file); }},
    {"svg-numbers", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.svg.numbers); }},
    {"svg-mark-angles", 0, required, "DEG", svg, "mark_angles_below_deg",
     [](CommandLine& l, Text v, Flag f) { return number(v, f, l.svg.mark_angles_below_deg); }},
    {"geo", 0, required, "FILE.geo", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.geo_file); }},
    {"vtk", 0, required, "FILE.vtk", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.vtk_file); }},
    {"geojson", 0, required, "FILE", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.geojson_file); }},
    {"msh", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.formats.msh); }},
    {"neigh", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.formats.neigh); }},
    {"edge", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.formats.edge); }},
    {"vtu", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.formats.vtu); }},
    {"split-mesh", 0, required, "DIR", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) { return text(v, l.split_mesh_dir); }},
    {"report", 0, optional, "FILE", front_end, nullptr,
     [](CommandLine& l, Text v, Flag) {
       l.report = true;
       l.report_file = v != nullptr ? v : "";
       return std::string();
     }},

    // Triangulate (TriangulateOptions).
    {"convex-hull", 'c', none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.triangulate.convex_hull); }},
    {"region-attributes", 'A', none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.triangulate.region_attributes); }},
    {"resolve-crossings", 'r', none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.resolve_crossings); }},

    // Partition (PartitionOptions), and gpmetis's spellings of what madd does anyway.
    {"parts", 'k', required, "K", front_end, nullptr,
     [](CommandLine& l, Text v, Flag f) { return count_in(v, f, 1, 1u << 30, l.parts); }},
    {"ufactor", 'u', required, "U", front_end, nullptr,
     [](CommandLine& l, Text v, Flag f) { return count_in(v, f, 0, 1000000, l.ufactor); }},
    {"contig", 'c', none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.partition.connected); }},
    {"niter", 0, required, "N", front_end, nullptr,
     [](CommandLine& l, Text v, Flag f) { return count_in(v, f, 0, 1000, l.partition.refinement_passes); }},
    {"nooutput", 0, none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_off(l.write_output); }},
    {"ptype", 0, required, "rb", front_end, nullptr,
     [](CommandLine&, Text v, Flag) {
       return only(v, "ptype", "rb", "madd partitions by recursive bisection only (-ptype=rb)");
     }},
    {"objtype", 0, required, "cut", front_end, nullptr,
     [](CommandLine&, Text v, Flag) {
       return only(v, "objtype", "cut", "madd minimises the edge cut only (-objtype=cut)");
     }},
    {"ctype", 0, required, "shem", front_end, nullptr,
     [](CommandLine&, Text v, Flag) {
       return only(v, "ctype", "shem", "madd coarsens by heavy-edge matching only (-ctype=shem)");
     }},
    {"iptype", 0, required, "grow", front_end, nullptr,
     [](CommandLine&, Text v, Flag) {
       return only(v, "iptype", "grow", "madd's initial bisection is greedy graph growing only (-iptype=grow)");
     }},
    {"no2hop", 0, none, nullptr, front_end, nullptr, [](CommandLine&, Text, Flag) { return std::string(); }},

    // Every command's.
    {"quiet", 'q', none, nullptr, front_end, nullptr, [](CommandLine& l, Text, Flag) { return switch_on(l.quiet); }},
    {"verbose", 'v', none, nullptr, front_end, nullptr,
     [](CommandLine& l, Text, Flag) { return switch_on(l.verbose); }},
    {"help", 'h', none, nullptr, front_end, nullptr, [](CommandLine& l, Text, Flag) { return switch_on(l.help); }},
};

}  // namespace

std::span<const Option> option_table() { return rows; }

const Option* find_option(std::string_view name) {
  for (const Option& row : rows)
    if (name == row.name) return &row;
  return nullptr;
}

}  // namespace madd::cli
