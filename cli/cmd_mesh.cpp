// `madd mesh DOMAIN.poly -n N -q DEG -a AREA -j T -o PREFIX`: decompose,
// decouple, refine every subdomain on its own thread, verify, write the one
// conforming mesh (docs/mesh.md, docs/cli.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>

#include "commands.hpp"
#include "input_domain.hpp"
#include "model_files.hpp"
#include "mesh_arguments.hpp"
#include "progress.hpp"
#include "seconds.hpp"
#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_output.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/poly_io.hpp"

namespace madd::cli {

extern volatile std::sig_atomic_t writing_outputs;  // main.cpp: interrupts unwind instead of exiting

namespace {

constexpr const char* mesh_intro = "usage: madd mesh [options] INPUT.poly|INPUT.geojson|INPUT.shp\n\n"
                                   "Decomposes the domain into N subdomains, splits every separator and boundary\n"
                                   "piece once to the local size (the Delaunay decoupling), refines every subdomain\n"
                                   "on its own thread with our Delaunay refinement (off-centres, small-angle rules)\n"
                                   "and writes one conforming mesh, self-checked (verify_mesh) before anything is\n"
                                   "written. The mesh is identical for any thread count.\n\n";

constexpr const char* mesh_exit_codes =
    "\nexit codes: 0 ok, 2 usage error, 3 bad input, 4 no decomposition, 5 output not written,\n"
    "6 limit, 70 internal error\n";

int write_mesh_outputs(const MeshArgs& args, const MeshOptions& options, const CoastDomain& input,
                       const std::optional<DepthField>& depth, const MeshPieces& m, const MeshReport& report,
                       std::chrono::steady_clock::time_point start, Progress& progress);

int mesh_body(void* context) {
  const auto& args = *static_cast<const MeshArgs*>(context);
  const CommandLine& line = args.line;
  const auto start = std::chrono::steady_clock::now();
  Progress progress(!line.quiet);
  progress.say("reading " + args.input);
  MeshOptions options = with_background_files(line);
  if (progress.enabled()) {
    options.decomposition.progress = [&progress](std::uint32_t done, std::uint32_t target) {
      progress.count(done, target);
    };
    options.progress = [&progress](std::uint32_t done, std::uint32_t total) { progress.count(done, total, "meshing"); };
  }
  const CoastDomain input = read_input_domain(args.input, line, line.quiet ? nullptr : stderr);
  const Pslg& domain = input.domain;
  default_coast_markers(options.size, args.input, input, line);
  const std::optional<DepthField> depth = read_depth(line);
  if (depth) set_depth(options.size, *depth, input.projection);
  progress.say("meshing " + std::to_string(options.decomposition.subdomains) + " subdomains");
  const auto meshed = [&](auto make) {
    try {
      return make(domain, options);
    } catch (const OptionError& e) {  // a check that needs the domain (the coast markers), said with the flags
      throw OptionError(e.option(), e.requirement(), cli_message(e, mesh_options(), line));
    }
  };
  // Every file is written from the subdomains' meshes as they were made
  // (docs/mesh.md, "Meshes in pieces"): the mesh is never merged.
  const MeshPiecesRun run = meshed([](const Pslg& d, const MeshOptions& o) { return mesh_pieces_with_report(d, o); });
  return write_mesh_outputs(args, options, input, depth, run.mesh, run.report, start, progress);
}

// The outputs of a mesh in pieces, all or nothing, then the summary line.
int write_mesh_outputs(const MeshArgs& args, const MeshOptions& options, const CoastDomain& input,
                       const std::optional<DepthField>& depth, const MeshPieces& m, const MeshReport& report,
                       std::chrono::steady_clock::time_point start, Progress& progress) {
  const CommandLine& line = args.line;
  progress.say("writing");
  OutputSet outputs;
  ModelFiles model_files;
  bool model = false;
  model = add_model_files(outputs, model_files, m, line, args.prefix, input.projection, depth,
                          options.decomposition.threads);
  if (!model) add_mesh(outputs, m, args.prefix, line.formats, options.decomposition.threads);
  if (!line.split_mesh_dir.empty()) {
    const std::string stem = std::filesystem::path(args.prefix).filename().string();
    add_split_mesh(outputs, m, line.split_mesh_dir, stem, line.formats.first_index, options.decomposition.threads);
  }
  const MeshMetrics figures =
      line.report || !line.quiet ? mesh_metrics(m, options.size, options.decomposition.threads) : MeshMetrics{};
  std::string json;
  if (line.report) {
    std::vector<RunFigure> figures_of_run = run_figures(report);
    std::vector<double> triangles_per_subdomain;
    for (std::uint32_t k = 0; k < m.subdomain_count(); ++k)
      triangles_per_subdomain.push_back(static_cast<double>(m.subdomain_triangle_count(k)));
    figures_of_run.push_back({"subdomain_triangles", triangles_per_subdomain});
    figures_of_run.push_back({"seconds", seconds_since(start)});
    json = format_mesh_report_json(figures, figures_of_run);
  }
  if (line.report && !line.report_file.empty()) outputs.add_file(line.report_file, json);
  writing_outputs = 1;
  outputs.write();
  writing_outputs = 0;
  progress.done();
  if (line.report && line.report_file.empty()) std::fputs(json.c_str(), stdout);
  if (!line.quiet) {
    std::fprintf(line.report && line.report_file.empty() ? stderr : stdout,
                 "%s: %u subdomains, %llu triangles, %llu vertices, smallest angle %.2f deg (%llu below %.4g: %zu at "
                 "small input angles, %zu at separators), %.2f s -> %s.{node,ele}\n",
                 args.input.c_str(), figures.subdomains, static_cast<unsigned long long>(figures.triangles),
                 static_cast<unsigned long long>(figures.vertices), figures.smallest_angle_deg,
                 static_cast<unsigned long long>(figures.below_bound), figures.min_angle_bound_deg,
                 figures.shortfall.input_angle, figures.shortfall.separator, seconds_since(start), args.prefix.c_str());
  }
  return exit_ok;
}

int run_mesh(int argc, char** argv) {
  MeshArgs args;
  const std::string problem = parse_mesh_arguments(argc, argv, args, false, true);
  if (!problem.empty()) return usage_error("mesh", problem);
  if (args.line.help) {
    std::fputs((mesh_intro + options_help(mesh_options()) + mesh_exit_codes).c_str(), stdout);
    return exit_ok;
  }
  return run_guarded("mesh", mesh_body, &args);
}

const CommandRegistration registration{
    {"mesh", "decompose and mesh every subdomain into one conforming quality mesh", run_mesh}};

}  // namespace
}  // namespace madd::cli
