// `madd decompose [options] INPUT.poly` (also the default mode): read a
// domain, decompose it (paper Algorithm 4), self-check, write the outputs.
#include <getopt.h>
#include <unistd.h>

#include <chrono>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "commands.hpp"
#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/expression.hpp"
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
    "      --min-angle DEG    smallest angle a separator may make (Phi0; default 60, < 90)\n"
    "  -r, --refine R         uniform boundary refinement factor (default 3)\n"
    "  -i, --imbalance I      acceptable imbalance during a split, 0 < I <= 1 (default 0.75)\n"
    "  -j, --threads J        worker threads, 0 = all cores (default 0); the result is identical\n"
    "      --seed S           random seed (default 1)\n"
    "      --smoothing K      smoothing iterations, Sec. 5.1 (default 1; 0 = off)\n"
    "  -a, --gradation A      grade by the boundary density weights (vertex attribute 1):\n"
    "                         a subdomain weighs r * area + A * weight (default 0 = uniform)\n"
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
    "      --no-verify        skip the self-check (verify_decomposition) before writing\n\n"
    "outputs (none by default; see docs/formats.md):\n"
    "  -o FILE.poly           the whole decomposition as one .poly, one region per subdomain\n"
    "      --split DIR        one .poly per subdomain: DIR/<stem>-<k>.poly\n"
    "      --subdomains-file FILE  the paper's subdomain file\n"
    "      --svg FILE.svg     a picture\n"
    "      --svg-numbers      write subdomain numbers in the picture\n"
    "      --svg-mark-angles DEG   circle the new angles below DEG in the picture\n"
    "      --geo FILE.geo     a gmsh model: gmsh -2 FILE.geo meshes all subdomains conformingly\n"
    "      --vtk FILE.vtk     legacy VTK for ParaView: subdomains as triangles with cell data\n"
    "      --geojson FILE     GeoJSON: one Polygon feature per subdomain\n"
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

// A one-line progress note on stderr, only for a terminal (DESIGN.md).
class Progress {
public:
  explicit Progress(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO) == 1) {}
  void say(const std::string& text) {
    if (enabled_) std::fprintf(stderr, "\r\033[Kmadd: %s", text.c_str());
  }
  void done() {
    if (enabled_) std::fputs("\r\033[K", stderr);
  }

private:
  bool enabled_;
};

// A figure for the summary; "-" when it does not exist (NaN, e.g. no new angle when N = 1).
std::string fig(double v, const char* format = "%.2f") {
  if (std::isnan(v)) return "-";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
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

// Every output is formatted in memory first, then written file by file
// (each atomically); the split directory is staged as a whole.
void write_outputs(const DecomposeArgs& args, const Decomposition& d, const Metrics& m) {
  const std::string poly = args.poly_out.empty() ? std::string() : format_decomposition_poly(d, "made by madd from " + args.input);
  const std::string table = args.subdomains_out.empty() ? std::string() : format_subdomain_file(d);
  const std::string svg = args.svg_out.empty() ? std::string() : format_svg(d, args.svg);
  const std::string report = args.report ? format_report_json(m) : std::string();
  const std::string geo = args.geo_out.empty() ? std::string() : format_geo(d);
  const std::string vtk = args.vtk_out.empty() ? std::string() : format_vtk(d);
  const std::string geojson = args.geojson_out.empty() ? std::string() : format_geojson(d);
  if (!args.poly_out.empty()) write_file_atomically(args.poly_out, poly);
  if (!args.subdomains_out.empty()) write_file_atomically(args.subdomains_out, table);
  if (!args.svg_out.empty()) write_file_atomically(args.svg_out, svg);
  if (!args.geo_out.empty()) write_file_atomically(args.geo_out, geo);
  if (!args.vtk_out.empty()) write_file_atomically(args.vtk_out, vtk);
  if (!args.geojson_out.empty()) write_file_atomically(args.geojson_out, geojson);
  if (!args.split_dir.empty()) write_split(d, args.split_dir, stem_of(args.input));
  if (args.report && !args.report_out.empty()) write_file_atomically(args.report_out, report);
  if (args.report && args.report_out.empty()) {
    std::fputs(report.c_str(), stdout);
    std::fflush(stdout);
  }
}

int decompose_body(void* context) {
  const auto& args = *static_cast<DecomposeArgs*>(context);
  Progress progress(!args.quiet);
  std::vector<PhaseTime> times;
  auto start = std::chrono::steady_clock::now();
  progress.say("reading " + args.input);
  Pslg domain;
  try {
    // Boundary weights are only checked (finite, >= 0) when grading uses them (FORMATS.md).
    ValidateOptions validation;
    validation.check_weights = args.options.gradation > 0;
    domain = read_domain(args.input, validation);
  } catch (const ParseError&) {
    throw;
  } catch (const InvalidInputError&) {
    throw;
  } catch (const Error& e) {  // unreadable input is bad input (exit 3), not an output failure
    progress.done();
    std::fprintf(stderr, "madd decompose: error: %s\n", e.what());
    return exit_bad_input;
  }
  times.push_back({"read", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("decomposing into " + std::to_string(args.options.subdomains) + " subdomains");
  const Decomposition d = decompose(domain, args.options, times);
  times.push_back({"decompose", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("verifying");
  // With a required area (Sec. 5.2) N is a maximum: fewer subdomains is a correct result.
  const bool area_graded = args.options.area_function || !args.options.background_areas.empty();
  const auto made = static_cast<std::uint32_t>(d.subdomains.size());
  const std::uint32_t expected = area_graded && made <= args.options.subdomains ? made : args.options.subdomains;
  const Verification check = args.verify ? verify_decomposition(d, domain, expected) : Verification{};
  times.push_back({"verify", seconds_since(start)});
  if (!check.ok()) {
    progress.done();
    std::fprintf(stderr, "madd decompose: internal error: the decomposition of %s failed its self-check "
                 "(nothing written):\n", args.input.c_str());
    for (const std::string& problem : check.problems) std::fprintf(stderr, "  %s\n", problem.c_str());
    return exit_internal;
  }
  const Metrics m = metrics(d, times);
  progress.say("writing");
  writing_outputs = 1;
  write_outputs(args, d, m);
  writing_outputs = 0;
  progress.done();
  const bool report_on_stdout = args.report && args.report_out.empty();
  if (!args.quiet) print_summary(report_on_stdout ? stderr : stdout, args, d, m);
  return exit_ok;
}

bool parse_number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

bool parse_count(const char* text, unsigned long long limit, unsigned long long& value) {
  if (text[0] < '0' || text[0] > '9') return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoull(text, &end, 10);
  return *end == '\0' && errno == 0 && value <= limit;
}

enum LongOnly : int { opt_min_angle = 256, opt_seed, opt_smoothing, opt_split, opt_subdomains_file, opt_svg, opt_svg_numbers,
                      opt_svg_mark, opt_report, opt_geo, opt_vtk, opt_geojson, opt_time_limit, opt_max_memory, opt_no_verify,
                      opt_weight_fn, opt_area_fn, opt_weights, opt_areas, opt_area_bound };

// A background mesh (Sec. 5.2 case 2): the nodes of a .node file, value = first attribute.
std::string read_values(const char* path, bool areas, std::vector<ValuedPoint>& out) {
  try {
    const Pslg p = read_poly_file(path).pslg;
    if (p.attributes_per_point == 0) return std::string(path) + ": a background mesh needs one attribute per node";
    out.clear();
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const double v = p.attribute(i, 0);
      if (!std::isfinite(v) || v < 0 || (areas && v == 0)) return std::string(path) + ": bad value at node " + std::to_string(i);
      out.push_back({p.points[i], v});
    }
    return {};
  } catch (const Error& e) {
    return e.what();
  }
}

std::string set_function(const char* text, std::function<double(double, double)>& out) {
  try {
    out = parse_expression(text, "expression").function();
    return {};
  } catch (const Error& e) {
    return e.what();
  }
}

// Applies one option to args; returns an error message, or empty on success.
std::string apply_option(int c, const char* arg, DecomposeArgs& args) {
  double x = 0;
  unsigned long long k = 0;
  switch (c) {
  case 'n':
    if (!parse_count(arg, 0xFFFFFFFFull, k) || k == 0) return "--subdomains needs a whole number >= 1";
    args.options.subdomains = static_cast<std::uint32_t>(k);
    return {};
  case opt_min_angle:
    if (!parse_number(arg, x) || x < 0 || x >= 90) return "--min-angle needs degrees in [0, 90)";
    args.options.min_angle_deg = x;
    return {};
  case 'r':
    if (!parse_number(arg, x) || x <= 0) return "--refine needs a number > 0";
    args.options.refine = x;
    return {};
  case 'i':
    if (!parse_number(arg, x) || x <= 0 || x > 1) return "--imbalance needs a number in (0, 1]";
    args.options.min_balance_quality = x;
    return {};
  case 'j':
    if (!parse_count(arg, 4096, k)) return "--threads needs a whole number in [0, 4096]";
    args.options.threads = static_cast<unsigned>(k);
    return {};
  case opt_seed:
    if (!parse_count(arg, ~0ull, k)) return "--seed needs a whole number";
    args.options.seed = k;
    return {};
  case opt_smoothing:
    if (!parse_count(arg, 1000, k)) return "--smoothing needs a whole number in [0, 1000]";
    args.options.smoothing_iterations = static_cast<int>(k);
    return {};
  case 'a':
    if (!parse_number(arg, x) || x < 0) return "--gradation needs a number >= 0";
    args.options.gradation = x;
    return {};
  case 'p':
    if (!parse_number(arg, x) || x < 0) return "--interpolation needs a number >= 0";
    args.options.interpolation = x;
    return {};
  case 'o': args.poly_out = arg; return {};
  case opt_split: args.split_dir = arg; return {};
  case opt_subdomains_file: args.subdomains_out = arg; return {};
  case opt_svg: args.svg_out = arg; return {};
  case opt_svg_numbers: args.svg.numbers = true; return {};
  case opt_svg_mark:
    if (!parse_number(arg, x) || x <= 0 || x > 180) return "--svg-mark-angles needs degrees in (0, 180]";
    args.svg.mark_angles_below_deg = x;
    return {};
  case opt_report:
    args.report = true;
    args.report_out = arg != nullptr ? arg : "";
    return {};
  case opt_time_limit:
    if (!parse_number(arg, x) || x < 0) return "--time-limit needs seconds >= 0";
    args.options.time_limit_seconds = x;
    return {};
  case opt_max_memory:
    if (!parse_number(arg, x) || x < 0 || x > 1e12) return "--max-memory needs megabytes >= 0";
    args.options.max_memory_bytes = static_cast<std::size_t>(x * 1048576.0);
    return {};
  case opt_no_verify: args.verify = false; return {};
  case opt_weight_fn: return set_function(arg, args.options.weight_function);
  case opt_area_fn: return set_function(arg, args.options.area_function);
  case opt_weights: return read_values(arg, false, args.options.background_weights);
  case opt_areas: return read_values(arg, true, args.options.background_areas);
  case opt_area_bound:
    if (!parse_number(arg, x) || x <= 0) return "--area-bound needs a number > 0";
    args.options.area_ratio_bound = x;
    return {};
  case opt_geo: args.geo_out = arg; return {};
  case opt_vtk: args.vtk_out = arg; return {};
  case opt_geojson: args.geojson_out = arg; return {};
  case 'q': args.quiet = true; return {};
  case 'v': args.verbose = true; return {};
  default: return "unknown option";
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
      {"weight-fn", required_argument, nullptr, opt_weight_fn},
      {"area-fn", required_argument, nullptr, opt_area_fn},
      {"weights", required_argument, nullptr, opt_weights},
      {"areas", required_argument, nullptr, opt_areas},
      {"area-bound", required_argument, nullptr, opt_area_bound},
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
  return run_guarded("decompose", decompose_body, &args);
}

const CommandRegistration registration({"decompose", "split a domain into N subdomains (the default mode)",
                                        run_decompose});

} // namespace
} // namespace madd::cli
