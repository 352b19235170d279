// `madd decompose [options] INPUT.poly` (also the default mode): read a
// domain, decompose it (paper Algorithm 4), self-check, write the outputs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "input_domain.hpp"
#include "command_line.hpp"
#include "option_table.hpp"
#include "progress.hpp"
#include "seconds.hpp"
#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/metrics.hpp"
#include "madd/output.hpp"
#include "madd/output_formats.hpp"
#include "madd/poly_io.hpp"

namespace madd::cli {

extern volatile std::sig_atomic_t writing_outputs;  // main.cpp: interrupts unwind instead of exiting

namespace {

constexpr const char* decompose_intro =
    "usage: madd [decompose] [options] INPUT.poly|INPUT.geojson|INPUT.shp\n\n"
    "Splits the domain of INPUT.poly (Triangle .poly: outer boundary and holes) into N\n"
    "subdomains with the Medial Axis Domain Decomposition: every new angle >= the minimum\n"
    "angle, short separators, balanced areas. The result is self-checked before anything\n"
    "is written.\n\n";

constexpr const char* decompose_exit_codes =
    "\nexit codes: 0 success, 2 usage error, 3 bad input, 4 no valid decomposition at these\n"
    "settings (names the subdomain), 5 an output could not be written, 6 --time-limit or\n"
    "--max-memory reached, 70 internal error\n"
    "(the self-check failed; nothing was written)\n";

const CommandOptions& decompose_options = options_of("decompose");

// The command line; its decomposition options are line.mesh.decomposition,
// the discretisation of the outputs (--max-area, --size-fn, --sizes, the
// size field) line.mesh.size.
struct DecomposeArgs {
  std::string input;
  CommandLine line;
};

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
    std::fprintf(out,
                 "  note: the maximum of %u subdomains was reached with %u still above the area bound "
                 "(raise -n to split them)\n",
                 args.line.mesh.decomposition.subdomains, m.subdomains_over_area_bound);
}

void print_summary(std::FILE* out, const DecomposeArgs& args, const Decomposition& d, const Metrics& m) {
  const CommandLine& line = args.line;
  std::fprintf(out, "%s: %zu subdomains, %zu points, %zu segments (%u separator)\n", args.input.c_str(),
               d.subdomains.size(), d.points.size(), d.segments.size(), m.separator_segments);
  std::fprintf(out, "  C1 new angles: min %s deg (bound %s), median %s, at boundary median %s\n",
               fig(m.angle_min).c_str(), fig(m.min_angle_bound_deg).c_str(), fig(m.angle_median).c_str(),
               fig(m.boundary_angle_median).c_str());
  std::fprintf(out, "  C2 separator length %s (%s x sqrt(area))\n", fig(m.separator_length, "%.6g").c_str(),
               fig(m.separator_length_norm, "%.4g").c_str());
  std::fprintf(out, "  C3 area max/mean %s, min/mean %s\n", fig(m.max_area_over_mean, "%.4f").c_str(),
               fig(m.min_area_over_mean, "%.4f").c_str());
  print_required_area(out, args, m);
  if (line.verbose) {
    std::fprintf(out, "  new angles %u: p10 %s, p90 %s; at boundary %u, min %s\n", m.new_angles,
                 fig(m.angle_p10, "%.4f").c_str(), fig(m.angle_p90, "%.4f").c_str(), m.boundary_angles,
                 fig(m.boundary_angle_min, "%.4f").c_str());
    std::fprintf(out, "  separator per subdomain %s, max sep/area x sqrt(mean area) %s\n",
                 fig(m.mean_separator_per_subdomain, "%.6g").c_str(),
                 fig(m.max_separator_over_area_norm, "%.4f").c_str());
    std::fprintf(out, "  weight max/mean %s, min/mean %s; shortest new segment / sqrt(mean area) %s\n",
                 fig(m.max_weight_over_mean, "%.4f").c_str(), fig(m.min_weight_over_mean, "%.4f").c_str(),
                 fig(m.shortest_new_segment_norm, "%.4g").c_str());
    for (const PhaseTime& t : m.times) std::fprintf(out, "  time %-12s %.3f s\n", t.name.c_str(), t.seconds);
  }
  for (const std::string* file : {&line.output, &line.subdomains_file, &line.svg_file, &line.geo_file, &line.vtk_file,
                                  &line.geojson_file, &line.report_file})
    if (!file->empty()) std::fprintf(out, "  wrote %s\n", file->c_str());
  if (!line.split_dir.empty()) {
    const auto n = static_cast<std::uint32_t>(d.subdomains.size());
    const std::string stem = stem_of(args.input);
    std::fprintf(out, "  wrote %s/%s ... %s (%u files)\n", line.split_dir.c_str(), split_file_name(stem, 0, n).c_str(),
                 split_file_name(stem, n - 1, n).c_str(), n);
  }
}

// Every output is formatted in memory first, then the set is written all or
// nothing (madd::OutputSet): a failure leaves no file of this run behind.
void write_outputs(const DecomposeArgs& args, const Decomposition& d, const Metrics& m) {
  const CommandLine& line = args.line;
  OutputSet outputs;
  if (!line.output.empty())
    outputs.add_file(line.output, format_decomposition_poly(d, "made by madd from " + args.input));
  if (!line.subdomains_file.empty()) outputs.add_file(line.subdomains_file, format_subdomain_file(d));
  if (!line.svg_file.empty()) outputs.add_file(line.svg_file, format_svg(d, line.svg));
  if (!line.geo_file.empty()) outputs.add_file(line.geo_file, format_geo(d));
  if (!line.vtk_file.empty()) outputs.add_file(line.vtk_file, format_vtk(d));
  if (!line.geojson_file.empty()) outputs.add_file(line.geojson_file, format_geojson(d));
  if (!line.split_dir.empty()) add_split(outputs, d, line.split_dir, stem_of(args.input));
  const std::string report = line.report ? format_report_json(m) : std::string();
  if (line.report && !line.report_file.empty()) outputs.add_file(line.report_file, report);
  outputs.write();
  if (line.report && line.report_file.empty()) {
    std::fputs(report.c_str(), stdout);
    std::fflush(stdout);
  }
}

// Runs f(), restating an OptionError of the library (a domain-dependent
// check: an area function's value, the coast markers) with the CLI's option names.
template <class F>
auto with_cli_option_names(const CommandLine& line, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const OptionError& e) {
    throw OptionError(e.option(), e.requirement(), cli_message(e, decompose_options, line));
  }
}

int decompose_body(void* context) {
  const auto& args = *static_cast<const DecomposeArgs*>(context);
  const CommandLine& line = args.line;
  Progress progress(!line.quiet);
  std::vector<PhaseTime> times;
  auto start = std::chrono::steady_clock::now();
  progress.say("reading " + args.input);
  const MeshOptions read = with_background_files(line);
  DecomposeOptions options = read.decomposition;
  if (progress.enabled())
    options.progress = [&progress](std::uint32_t done, std::uint32_t target) { progress.count(done, target); };
  // Boundary weights are only checked (finite, >= 0) when grading uses them (docs/formats.md).
  ValidateOptions validation;
  validation.check_weights = options.gradation > 0;
  const CoastDomain input = read_input_domain(args.input, line, line.quiet ? nullptr : stderr, validation);
  const Pslg& domain = input.domain;
  times.push_back({"read", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("decomposing into " + std::to_string(options.subdomains) + " subdomains");
  const DecomposeRun run = with_cli_option_names(line, [&] { return decompose_with_report(domain, options); });
  const Decomposition& d = run.decomposition;
  times.insert(times.end(), run.report.phases.begin(), run.report.phases.end());
  times.push_back({"decompose", seconds_since(start)});

  start = std::chrono::steady_clock::now();
  progress.say("verifying");
  const std::uint32_t expected = expected_subdomain_count(d, options.subdomains);
  const Verification check = line.mesh.verify ? verify_decomposition(d, domain, expected) : Verification{};
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
  if (read.size.has_size_bound()) {
    MeshSizeOptions size = read.size;
    default_coast_markers(size, args.input, input, line);
    write_outputs(args, with_cli_option_names(line, [&] { return discretise(d, domain, size, options); }), m);
  } else {
    write_outputs(args, d, m);
  }
  writing_outputs = 0;
  progress.done();
  const bool report_on_stdout = line.report && line.report_file.empty();
  if (!line.quiet) print_summary(report_on_stdout ? stderr : stdout, args, d, m);
  return exit_ok;
}

// An output path given to two output options, or "".
std::string output_named_twice(const CommandLine& line) {
  std::vector<std::string> paths;
  for (const std::string* file : {&line.output, &line.subdomains_file, &line.svg_file, &line.geo_file, &line.vtk_file,
                                  &line.geojson_file, &line.report_file, &line.split_dir}) {
    if (file->empty()) continue;
    const std::string normal = std::filesystem::path(*file).lexically_normal().string();
    if (std::find(paths.begin(), paths.end(), normal) != paths.end()) return *file;
    paths.push_back(normal);
  }
  return {};
}

// The library's check of every range and combination (check_options), said
// in the CLI's words: "--min-angle must lie strictly between 0 and 90 degrees, got '0'".
std::string option_problem(const CommandLine& line) {
  DecomposeOptions options = line.mesh.decomposition;
  // A background file is read later; its presence is what a conflict needs.
  if (!line.weights_file.empty()) options.weight_samples = {{{0, 0}, 0.0}};
  if (!line.areas_file.empty()) options.subdomain_area_samples = {{{0, 0}, 1.0}};
  try {
    check_options(options);
  } catch (const OptionError& e) {
    return cli_message(e, Scope::decomposition, decompose_options, line);
  }
  try {
    check_options(line.svg);
  } catch (const OptionError& e) {
    return cli_message(e, Scope::svg, decompose_options, line);
  }
  MeshOptions mesh = line.mesh;  // the discretisation of the outputs
  if (!line.sizes_file.empty()) mesh.size.triangle_area_samples = {{{0, 0}, 1.0}};
  try {
    check_options(mesh);
  } catch (const OptionError& e) {
    std::string message = cli_message(e, Scope::mesh_size, decompose_options, line);
    // --gradation was the grading factor here until it became the size field's.
    if (e.option() == "size_gradation") message += " (grading by weights is --weight-gradation)";
    return message;
  }
  return {};
}

int run_decompose(int argc, char** argv) {
  DecomposeArgs args;
  CommandLine& line = args.line;
  line.mesh.decomposition = DecomposeOptions{};  // a bare decomposition's defaults, not meshing's
  const std::string help = decompose_intro + options_help(decompose_options) + decompose_exit_codes;
  if (const auto done = read_one_operand(decompose_options, argc, argv, line, help)) return *done;
  args.input = line.operands.front();
  if (line.quiet && line.verbose) return usage_error("decompose", "--quiet and --verbose exclude each other");
  if (const std::string twice = output_named_twice(line); !twice.empty())
    return usage_error("decompose", "'" + twice + "' is named by two outputs");
  if (const std::string problem = option_problem(line); !problem.empty()) return usage_error("decompose", problem);
  return run_guarded("decompose", decompose_body, &args);
}

const CommandRegistration registration({"decompose", "split a domain into N subdomains (the default mode)",
                                        run_decompose});

}  // namespace
}  // namespace madd::cli
