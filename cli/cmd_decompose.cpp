// `madd decompose [options] INPUT.poly` (also the default mode): read a
// domain, decompose it (paper Algorithm 4), self-check, write the outputs.
#include <getopt.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <type_traits>

#include "background_mesh.hpp"
#include "commands.hpp"
#include "option_values.hpp"
#include "option_names.hpp"
#include "progress.hpp"
#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/expression.hpp"
#include "madd/mesh.hpp"
#include "madd/metrics.hpp"
#include "madd/output.hpp"
#include "madd/output_formats.hpp"
#include "madd/poly_io.hpp"

namespace madd::cli {

extern volatile std::sig_atomic_t writing_outputs;  // main.cpp: interrupts unwind instead of exiting

namespace {

constexpr const char* decompose_help =
    "usage: madd [decompose] [options] INPUT.poly\n\n"
    "Splits the domain of INPUT.poly (Triangle .poly: outer boundary and holes) into N\n"
    "subdomains with the Medial Axis Domain Decomposition: every new angle >= the minimum\n"
    "angle, short separators, balanced areas. The result is self-checked before anything\n"
    "is written.\n\n"
    "decomposition:\n"
    "  -n, --subdomains N     number of subdomains (default 2)\n"
    "      --min-angle DEG    smallest angle a separator may make (Phi0; default 60; 0 < DEG < 90)\n"
    "  -r, --refine R         uniform boundary refinement factor (default 3)\n"
    "  -i, --imbalance I      acceptable imbalance during a split, 0 < I <= 1 (default 0.75)\n"
    "  -j, --threads J        worker threads, 0 = all cores (default 0); the result is identical\n"
    "      --seed S           random seed (default 1)\n"
    "      --smoothing K      smoothing iterations, Sec. 5.1 (default 1; 0 = off)\n"
    "      --rebalance X      re-split subdomains above X x the mean area with their\n"
    "                         neighbours (default 1.2; 0 = off; uniform or --weights runs)\n"
    "  -a, --gradation A      grade by the boundary density weights (vertex attribute 1):\n"
    "                         a subdomain weighs r * area + A * weight (default 0 = uniform)\n"
    "      --adaptive-refine L  graded by boundary weights: heavier edges get up to L times\n"
    "                         more refinement points (default 4; 1 = uniform; 1 <= L <= 64)\n"
    "  -p, --interpolation P  weight of new separator points = P x the interpolated weight\n"
    "                         of the separator's ends (default 0)\n"
    "      --weight-fn EXPR   grade by a density weight function f(x, y) (Sec. 5.2 case 3)\n"
    "      --area-fn EXPR     split while a subdomain's area > bound x the required area\n"
    "                         function's minimum inside it (N is then the maximum)\n"
    "      --weights FILE     background density weights: .node, first attribute (case 2)\n"
    "      --areas FILE       background required areas: .node, first attribute (case 2)\n"
    "      --area-bound X     area / required area bound (default 1)\n"
    "      --time-limit S     give up (exit 6, nothing written) after S seconds (default 0 = none)\n"
    "      --max-memory MB    give up (exit 6, nothing written) above MB megabytes resident\n"
    "                         (default 0 = none; checked before every split)\n"
    "      --max-area A       write the outputs with every segment split for meshes of\n"
    "                         triangle area <= A (the decoupling, docs/mesh.md): --split's\n"
    "                         files, meshed one by one by `triangle -pq30Y`, join up\n"
    "      --size-fn EXPR     the same, the largest area at (x, y) given by EXPR\n"
    "      --no-verify        skip the self-check (verify_decomposition) before writing\n\n"
    "outputs (none by default; see docs/formats.md):\n"
    "  -o FILE.poly           the whole decomposition as one .poly, one region per subdomain\n"
    "                         (per face: with the input's regions, their attributes)\n"
    "      --split DIR        one .poly per subdomain: DIR/<stem>-<k>.poly\n"
    "      --subdomains-file FILE  the paper's subdomain file\n"
    "      --svg FILE.svg     a picture\n"
    "      --svg-numbers      write subdomain numbers in the picture\n"
    "      --svg-mark-angles DEG   circle the new angles below DEG in the picture (0 = none)\n"
    "      --geo FILE.geo     a gmsh model: gmsh -2 FILE.geo meshes all subdomains conformingly\n"
    "      --vtk FILE.vtk     legacy VTK for ParaView: subdomains as triangles, segments as\n"
    "                         lines, isolated vertices as vertices, with cell data\n"
    "      --geojson FILE     GeoJSON: one Polygon feature per subdomain, then interior\n"
    "                         segments (LineString) and isolated vertices (Point)\n"
    "      --report[=FILE]    the quality figures as JSON (on stdout without FILE)\n\n"
    "  -q, --quiet            print nothing on success\n"
    "  -v, --verbose          print every quality figure and the phase times\n"
    "  -h, --help             this text\n\n"
    "exit codes: 0 success, 2 usage error, 3 bad input, 4 no valid decomposition at these\n"
    "settings (names the subdomain), 5 an output could not be written, 6 --time-limit or\n"
    "--max-memory reached, 70 internal error\n"
    "(the self-check failed; nothing was written)\n";

struct DecomposeArgs {
  std::string input;
  DecomposeOptions options;
  std::string poly_out, split_dir, subdomains_out, svg_out, report_out;
  std::string geo_out, vtk_out, geojson_out;  // madd/output_formats.hpp
  bool report = false;
  SvgOptions svg;
  bool quiet = false;
  bool verbose = false;
  bool verify = true;  // --no-verify turns the self-check off
  std::string weights_file, areas_file;  // --weights, --areas: read with the domain
  MeshSizeOptions discretise;  // --max-area, --size-fn: outputs with the boundaries discretised (docs/mesh.md)
  std::map<std::string, std::string> typed;  // option field -> the value as typed, for messages
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The input's file name without directories and without .poly/.node.
std::string stem_of(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  for (const char* ext : {".poly", ".node"}) {
    const std::string e = ext;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
      return name.substr(0, name.size() - e.size());
  }
  return name;
}

// A figure for the summary; "-" when it does not exist (NaN, e.g. no new angle when N = 1).
std::string fig(double v, const char* format = "%.2f") {
  if (std::isnan(v)) return "-";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

// Split to a required area, N is a maximum: say how close the result came,
// and, when N stopped the splitting, how many subdomains are still too large.
void print_required_area(std::FILE* out, const DecomposeArgs& args, const Metrics& m) {
  if (!(m.subdomain_area_ratio > 0.0)) return;
  std::fprintf(out, "  required area: largest area / required area %s (bound %s)\n",
               fig(m.max_area_over_required, "%.4g").c_str(), fig(m.subdomain_area_ratio, "%.4g").c_str());
  if (m.subdomains_over_area_bound > 0)
    std::fprintf(out, "  note: the maximum of %u subdomains was reached with %u still above the area bound "
                 "(raise -n to split them)\n", args.options.subdomains, m.subdomains_over_area_bound);
}

void print_summary(std::FILE* out, const DecomposeArgs& args, const Decomposition& d, const Metrics& m) {
  std::fprintf(out, "%s: %zu subdomains, %zu points, %zu segments (%u separator)\n", args.input.c_str(),
               d.subdomains.size(), d.points.size(), d.segments.size(), m.separator_segments);
  std::fprintf(out, "  C1 new angles: min %s deg (bound %s), median %s, at boundary median %s\n", fig(m.angle_min).c_str(),
               fig(m.min_angle_bound_deg).c_str(), fig(m.angle_median).c_str(), fig(m.boundary_angle_median).c_str());
  std::fprintf(out, "  C2 separator length %s (%s x sqrt(area))\n", fig(m.separator_length, "%.6g").c_str(),
               fig(m.separator_length_norm, "%.4g").c_str());
  std::fprintf(out, "  C3 area max/mean %s, min/mean %s\n", fig(m.max_area_over_mean, "%.4f").c_str(),
               fig(m.min_area_over_mean, "%.4f").c_str());
  print_required_area(out, args, m);
  if (args.verbose) {
    std::fprintf(out, "  new angles %u: p10 %s, p90 %s; at boundary %u, min %s\n", m.new_angles,
                 fig(m.angle_p10, "%.4f").c_str(), fig(m.angle_p90, "%.4f").c_str(), m.boundary_angles,
                 fig(m.boundary_angle_min, "%.4f").c_str());
    std::fprintf(out, "  separator per subdomain %s, max sep/area x sqrt(mean area) %s\n",
                 fig(m.mean_separator_per_subdomain, "%.6g").c_str(), fig(m.max_separator_over_area_norm, "%.4f").c_str());
    std::fprintf(out, "  weight max/mean %s, min/mean %s; shortest new segment / sqrt(mean area) %s\n",
                 fig(m.max_weight_over_mean, "%.4f").c_str(), fig(m.min_weight_over_mean, "%.4f").c_str(),
                 fig(m.shortest_new_segment_norm, "%.4g").c_str());
    for (const PhaseTime& t : m.times) std::fprintf(out, "  time %-12s %.3f s\n", t.name.c_str(), t.seconds);
  }
  for (const std::string* file : {&args.poly_out, &args.subdomains_out, &args.svg_out, &args.geo_out, &args.vtk_out,
                                    &args.geojson_out, &args.report_out})
    if (!file->empty()) std::fprintf(out, "  wrote %s\n", file->c_str());
  if (!args.split_dir.empty()) {
    const auto n = static_cast<std::uint32_t>(d.subdomains.size());
    const std::string stem = stem_of(args.input);
    std::fprintf(out, "  wrote %s/%s ... %s (%u files)\n", args.split_dir.c_str(), split_file_name(stem, 0, n).c_str(),
                 split_file_name(stem, n - 1, n).c_str(), n);
  }
}

// Every output is formatted in memory first, then the set is written all or
// nothing (madd::OutputSet): a failure leaves no file of this run behind.
void write_outputs(const DecomposeArgs& args, const Decomposition& d, const Metrics& m) {
  OutputSet outputs;
  if (!args.poly_out.empty())
    outputs.add_file(args.poly_out, format_decomposition_poly(d, "made by madd from " + args.input));
  if (!args.subdomains_out.empty()) outputs.add_file(args.subdomains_out, format_subdomain_file(d));
  if (!args.svg_out.empty()) outputs.add_file(args.svg_out, format_svg(d, args.svg));
  if (!args.geo_out.empty()) outputs.add_file(args.geo_out, format_geo(d));
  if (!args.vtk_out.empty()) outputs.add_file(args.vtk_out, format_vtk(d));
  if (!args.geojson_out.empty()) outputs.add_file(args.geojson_out, format_geojson(d));
  if (!args.split_dir.empty()) add_split(outputs, d, args.split_dir, stem_of(args.input));
  const std::string report = args.report ? format_report_json(m) : std::string();
  if (args.report && !args.report_out.empty()) outputs.add_file(args.report_out, report);
  outputs.write();
  if (args.report && args.report_out.empty()) {
    std::fputs(report.c_str(), stdout);
    std::fflush(stdout);
  }
}

// Runs f(), restating an OptionError of the library (a domain-dependent
// check, an area function's value) with the CLI's option names.
template <class F>
auto with_cli_option_names(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const OptionError& e) {
    throw OptionError(e.option(), e.requirement(), cli_message(e));
  }
}

int decompose_body(void* context) {
  auto& args = *static_cast<DecomposeArgs*>(context);
  Progress progress(!args.quiet);
  if (progress.enabled()) args.options.progress = [&progress](std::uint32_t done, std::uint32_t target) {
    progress.count(done, target);
  };
  std::vector<PhaseTime> times;
  auto start = std::chrono::steady_clock::now();
  progress.say("reading " + args.input);
  DecomposeOptions options = args.options;
  if (!args.weights_file.empty()) options.weight_samples = read_background(args.weights_file, false);
  if (!args.areas_file.empty()) options.subdomain_area_samples = read_background(args.areas_file, true);
  // Boundary weights are only checked (finite, >= 0) when grading uses them (docs/formats.md).
  ValidateOptions validation;
  validation.check_weights = options.gradation > 0;
  const Pslg domain = read_domain(args.input, validation);
  times.push_back({"read", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("decomposing into " + std::to_string(options.subdomains) + " subdomains");
  const DecomposeRun run = with_cli_option_names([&] { return decompose_with_report(domain, options); });
  const Decomposition& d = run.decomposition;
  times.insert(times.end(), run.report.phases.begin(), run.report.phases.end());
  times.push_back({"decompose", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("verifying");
  const Verification check =
      args.verify ? verify_decomposition(d, domain, expected_subdomain_count(d, options.subdomains)) : Verification{};
  times.push_back({"verify", seconds_since(start)});
  if (!check.ok()) {
    std::string problems;
    for (const std::string& problem : check.problems) problems += "\n  " + problem;
    throw InternalError("the decomposition of " + args.input + " failed its self-check (nothing written):" + problems);
  }
  const Metrics m = metrics(d, times);
  progress.say("writing");
  writing_outputs = 1;
  // For external meshers: every segment split once to the size bound and the
  // local feature size, so that meshers keeping boundary segments join up.
  if (args.discretise.has_size_bound()) {
    write_outputs(args, discretise(d, args.discretise), m);
  } else {
    write_outputs(args, d, m);
  }
  writing_outputs = 0;
  progress.done();
  const bool report_on_stdout = args.report && args.report_out.empty();
  if (!args.quiet) print_summary(report_on_stdout ? stderr : stdout, args, d, m);
  return exit_ok;
}

enum LongOnly : int { opt_min_angle = 256, opt_seed, opt_smoothing, opt_split, opt_subdomains_file, opt_svg, opt_svg_numbers,
                      opt_svg_mark, opt_report, opt_geo, opt_vtk, opt_geojson, opt_time_limit, opt_max_memory, opt_no_verify, opt_rebalance, opt_adaptive_refine,
                      opt_weight_fn, opt_area_fn, opt_weights, opt_areas, opt_area_bound, opt_max_area, opt_size_fn };

std::string set_function(const char* text, std::function<double(double, double)>& out) {
  try {
    out = parse_expression(text, "expression").function();
    return {};
  } catch (const Error& e) {
    return e.what();
  }
}

// Parses one option into args; returns an error message when the value does
// not parse, empty on success. Ranges are the library's (check_options).
std::string apply_option(int c, const char* arg, DecomposeArgs& args) {
  double x = 0;
  unsigned long long k = 0;
  DecomposeOptions& o = args.options;
  const auto number = [&](const char* field, double& target) -> std::string {
    if (!parse_number(arg, x)) return std::string(cli_name_of(field)) + " needs a number";
    target = x;
    args.typed[field] = arg;
    return {};
  };
  const auto count = [&](const char* field, unsigned long long limit, auto& target) -> std::string {
    if (!parse_count(arg, limit, k)) return std::string(cli_name_of(field)) + " needs a whole number";
    target = static_cast<std::remove_reference_t<decltype(target)>>(k);
    args.typed[field] = arg;
    return {};
  };
  switch (c) {
  case 'n': return count("subdomains", 0xFFFFFFFFull, o.subdomains);
  case opt_min_angle: return number("separator_angle_deg", o.separator_angle_deg);
  case 'r': return number("boundary_refinement", o.boundary_refinement);
  case 'i': return number("min_split_quality", o.min_split_quality);
  case 'j': return count("threads", 0xFFFFFFFFull, o.threads);
  case opt_seed: return count("seed", ~0ull, o.seed);
  case opt_smoothing: return count("smoothing_iterations", 0x7FFFFFFFull, o.smoothing_iterations);
  case opt_rebalance: return number("repair_balance_above", o.repair_balance_above);
  case opt_adaptive_refine: return number("adaptive_boundary_refinement", o.adaptive_boundary_refinement);
  case 'a': return number("gradation", o.gradation);
  case 'p': return number("interpolation", o.interpolation);
  case opt_time_limit: return number("time_limit_seconds", o.time_limit_seconds);
  case opt_area_bound: return number("subdomain_area_ratio", o.subdomain_area_ratio);
  case opt_max_memory:
    // Megabytes to bytes: the value must be one a size_t holds.
    if (!parse_number(arg, x) || x < 0 || x > 1e12) return "--max-memory needs megabytes in [0, 1e12]";
    o.max_memory_bytes = static_cast<std::size_t>(x * 1048576.0);
    return {};
  case opt_weight_fn: return set_function(arg, o.weight_function);
  case opt_area_fn: return set_function(arg, o.subdomain_area_function);
  case opt_max_area:
    if (!parse_number(arg, x) || !(x > 0)) return "--max-area needs an area > 0";
    args.discretise.max_triangle_area = x;
    return {};
  case opt_size_fn: return set_function(arg, args.discretise.triangle_area_function);
  case opt_weights: args.weights_file = arg; return {};
  case opt_areas: args.areas_file = arg; return {};
  case 'o': args.poly_out = arg; return {};
  case opt_split: args.split_dir = arg; return {};
  case opt_subdomains_file: args.subdomains_out = arg; return {};
  case opt_svg: args.svg_out = arg; return {};
  case opt_svg_numbers: args.svg.numbers = true; return {};
  case opt_svg_mark:
    if (!parse_number(arg, x)) return "--svg-mark-angles needs degrees";
    args.svg.mark_angles_below_deg = x;
    args.typed["mark_angles_below_deg"] = arg;
    return {};
  case opt_report:
    args.report = true;
    args.report_out = arg != nullptr ? arg : "";
    return {};
  case opt_no_verify: args.verify = false; return {};
  case opt_geo: args.geo_out = arg; return {};
  case opt_vtk: args.vtk_out = arg; return {};
  case opt_geojson: args.geojson_out = arg; return {};
  case 'q': args.quiet = true; return {};
  case 'v': args.verbose = true; return {};
  default: return "unknown option";
  }
}

// An output path given to two output options, or "".
std::string output_named_twice(const DecomposeArgs& args) {
  std::vector<std::string> paths;
  for (const std::string* file : {&args.poly_out, &args.subdomains_out, &args.svg_out, &args.geo_out, &args.vtk_out,
                                  &args.geojson_out, &args.report_out, &args.split_dir}) {
    if (file->empty()) continue;
    const std::string normal = std::filesystem::path(*file).lexically_normal().string();
    if (std::find(paths.begin(), paths.end(), normal) != paths.end()) return *file;
    paths.push_back(normal);
  }
  return {};
}

// The library's check of every range and combination (check_options), said
// in the CLI's words: "--min-angle must lie strictly between 0 and 90 degrees, got '0'".
std::string option_problem(const DecomposeArgs& args) {
  try {
    DecomposeOptions options = args.options;
    // A background file is read later; its presence is what a conflict needs.
    if (!args.weights_file.empty()) options.weight_samples = {{{0, 0}, 0.0}};
    if (!args.areas_file.empty()) options.subdomain_area_samples = {{{0, 0}, 1.0}};
    check_options(options);
    check_options(args.svg);
    return {};
  } catch (const OptionError& e) {
    const auto typed = args.typed.find(e.option());
    return cli_message(e) + (typed != args.typed.end() ? ", got '" + typed->second + "'" : std::string());
  }
}

int run_decompose(int argc, char** argv) {
  static const option long_options[] = {
      {"subdomains", required_argument, nullptr, 'n'},
      {"min-angle", required_argument, nullptr, opt_min_angle},
      {"refine", required_argument, nullptr, 'r'},
      {"imbalance", required_argument, nullptr, 'i'},
      {"threads", required_argument, nullptr, 'j'},
      {"seed", required_argument, nullptr, opt_seed},
      {"smoothing", required_argument, nullptr, opt_smoothing},
      {"gradation", required_argument, nullptr, 'a'},
      {"interpolation", required_argument, nullptr, 'p'},
      {"output", required_argument, nullptr, 'o'},
      {"split", required_argument, nullptr, opt_split},
      {"subdomains-file", required_argument, nullptr, opt_subdomains_file},
      {"svg", required_argument, nullptr, opt_svg},
      {"svg-numbers", no_argument, nullptr, opt_svg_numbers},
      {"svg-mark-angles", required_argument, nullptr, opt_svg_mark},
      {"report", optional_argument, nullptr, opt_report},
      {"geo", required_argument, nullptr, opt_geo},
      {"vtk", required_argument, nullptr, opt_vtk},
      {"geojson", required_argument, nullptr, opt_geojson},
      {"time-limit", required_argument, nullptr, opt_time_limit},
      {"max-memory", required_argument, nullptr, opt_max_memory},
      {"no-verify", no_argument, nullptr, opt_no_verify},
      {"rebalance", required_argument, nullptr, opt_rebalance},
      {"adaptive-refine", required_argument, nullptr, opt_adaptive_refine},
      {"weight-fn", required_argument, nullptr, opt_weight_fn},
      {"area-fn", required_argument, nullptr, opt_area_fn},
      {"weights", required_argument, nullptr, opt_weights},
      {"areas", required_argument, nullptr, opt_areas},
      {"area-bound", required_argument, nullptr, opt_area_bound},
      {"max-area", required_argument, nullptr, opt_max_area},
      {"size-fn", required_argument, nullptr, opt_size_fn},
      {"quiet", no_argument, nullptr, 'q'},
      {"verbose", no_argument, nullptr, 'v'},
      {"help", no_argument, nullptr, 'h'},
      {nullptr, 0, nullptr, 0}};
  DecomposeArgs args;
  optind = 0;
  opterr = 0;
  int c;
  while ((c = getopt_long(argc, argv, ":n:r:i:j:a:p:o:qvh", long_options, nullptr)) != -1) {
    if (c == 'h') {
      std::fputs(decompose_help, stdout);
      return exit_ok;
    }
    if (c == '?') return usage_error("decompose", std::string("unknown option '") + argv[optind - 1] + "'");
    if (c == ':') return usage_error("decompose", std::string("option '") + argv[optind - 1] + "' needs a value");
    const std::string problem = apply_option(c, optarg, args);
    if (!problem.empty()) return usage_error("decompose", problem + (optarg ? std::string(", got '") + optarg + "'" : ""));
  }
  if (optind + 1 != argc) return usage_error("decompose", "expected exactly one input file");
  args.input = argv[optind];
  if (args.quiet && args.verbose) return usage_error("decompose", "--quiet and --verbose exclude each other");
  if (const std::string twice = output_named_twice(args); !twice.empty())
    return usage_error("decompose", "'" + twice + "' is named by two outputs");
  if (const std::string problem = option_problem(args); !problem.empty()) return usage_error("decompose", problem);
  return run_guarded("decompose", decompose_body, &args);
}

const CommandRegistration registration({"decompose", "split a domain into N subdomains (the default mode)",
                                        run_decompose});

} // namespace
} // namespace madd::cli
