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

#include "background_mesh.hpp"
#include "commands.hpp"
#include "mesh_arguments.hpp"
#include "mesh_figures.hpp"
#include "progress.hpp"
#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_output.hpp"
#include "madd/poly_io.hpp"

namespace madd::cli {

extern volatile std::sig_atomic_t writing_outputs;  // main.cpp: interrupts unwind instead of exiting

namespace {

constexpr const char* mesh_help =
    "usage: madd mesh [options] INPUT.poly\n\n"
    "Decomposes the domain into N subdomains, splits every separator and boundary\n"
    "piece once to the local size (the Delaunay decoupling), refines every subdomain\n"
    "on its own thread with our Delaunay refinement (off-centres, small-angle rules)\n"
    "and writes one conforming mesh, self-checked (verify_mesh) before anything is\n"
    "written. The mesh is identical for any thread count.\n\n"
    "mesh:\n"
    "  -q, --quality DEG      smallest angle of every triangle, away from smaller input\n"
    "                         angles (default 30; 0 <= DEG < 60; the guarantee holds to 20.7,\n"
    "                         in practice to about 34)\n"
    "  -a, --max-area A       largest triangle area (default none)\n"
    "      --size-fn EXPR     largest triangle area at (x, y), an expression in x and y\n"
    "      --sizes FILE       largest triangle area at background nodes (.node, attribute 1;\n"
    "                         the nearest node's value applies)\n"
    "      --balance area|work  what the decomposition balances: the expected triangle\n"
    "                         count of each subdomain (work, default) or its area\n"
    "      --no-off-centres   insert circumcentres only (more triangles)\n"
    "      --no-verify        skip the self-check (verify_mesh) before writing\n"
    "decomposition:\n"
    "  -n, --subdomains N     number of subdomains (default: the thread count x 4)\n"
    "      --min-angle DEG    Phi0, the smallest angle a separator makes (default 60)\n"
    "  -j, --threads T        threads, 0 = all cores (default 0); the mesh is identical\n"
    "      --seed S           random seed of the decomposition (default 1)\n"
    "      --rebalance X      repair subdomains above X x the mean work (default 1.1; 0 = off)\n"
    "      --time-limit S     give up (exit 6, nothing written) after S seconds (default none)\n"
    "      --max-memory MB    give up (exit 6, nothing written) above MB megabytes resident\n"
    "outputs:\n"
    "  -o, --output PREFIX    PREFIX.node and PREFIX.ele (default: INPUT without .poly)\n"
    "      --neigh, --edge    also PREFIX.neigh, PREFIX.edge (Triangle's -n, -e)\n"
    "      --msh              also PREFIX.msh (gmsh 4.1: a physical surface per subdomain)\n"
    "      --vtu              also PREFIX.vtu (VTK; subdomain as cell data)\n"
    "      --split-mesh DIR   also one .node/.ele per subdomain in DIR, with global vertex ids\n"
    "      --report[=FILE]    the mesh figures as JSON on stdout (or in FILE)\n"
    "      --quiet            print nothing on success\n"
    "  -h, --help             this text\n\n"
    "exit codes: 0 ok, 2 usage error, 3 bad input, 4 no decomposition, 5 output not written,\n"
    "6 limit, 70 internal error\n";

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string report_json(const MeshArgs& args, const Mesh& m, const MeshReport& r, double total_seconds) {
  const AngleFigures a = angle_figures(m);
  std::string out = "{\n";
  char buf[256];
  const auto add = [&](const char* key, double v, bool last = false) {
    std::snprintf(buf, sizeof buf, "  \"%s\": %.17g%s\n", key, v, last ? "" : ",");
    out += buf;
  };
  add("subdomains", m.subdomain_count());
  add("triangles", static_cast<double>(m.triangles.size()));
  add("vertices", static_cast<double>(m.points.size()));
  add("min_angle_bound_deg", m.min_triangle_angle_deg);
  add("max_area_bound", args.options.size.max_triangle_area);
  add("min_angle_deg", a.min_deg);
  add("median_smallest_angle_deg", a.median_deg);
  add("share_below_bound", m.triangles.empty() ? 0.0 : static_cast<double>(a.below) / static_cast<double>(m.triangles.size()));
  add("below_bound_input_angle", static_cast<double>(m.shortfall.input_angle));
  add("below_bound_separator", static_cast<double>(m.shortfall.separator));
  add("below_bound_precision", static_cast<double>(m.shortfall.precision));
  add("below_bound_limit", static_cast<double>(m.shortfall.limit));
  out += "  \"smallest_angle_histogram_10deg\": [";
  for (int i = 0; i < 6; ++i) out += std::to_string(a.bins[i]) + (i < 5 ? ", " : "],\n");
  // Triangle-count balance: the work balance the decomposition aimed for.
  std::size_t largest = 0;
  for (std::uint32_t k = 0; k < m.subdomain_count(); ++k)
    largest = std::max<std::size_t>(largest, m.subdomain_first_triangle[k + 1] - m.subdomain_first_triangle[k]);
  const double mean = m.subdomain_count() ? static_cast<double>(m.triangles.size()) / m.subdomain_count() : 0.0;
  add("max_over_mean_triangles", mean > 0 ? static_cast<double>(largest) / mean : 0.0);
  double busiest = 0, busy = 0;
  for (const double s : r.thread_seconds) {
    busiest = std::max(busiest, s);
    busy += s;
  }
  add("threads", static_cast<double>(r.thread_seconds.size()));
  add("thread_imbalance", busy > 0 ? busiest * static_cast<double>(r.thread_seconds.size()) / busy : 0.0);
  out += "  \"thread_seconds\": [";
  for (std::size_t i = 0; i < r.thread_seconds.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.6g", i ? ", " : "", r.thread_seconds[i]);
    out += buf;
  }
  out += "],\n  \"phase_seconds\": {";
  for (std::size_t i = 0; i < r.phases.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s\"%s\": %.6g", i ? ", " : "", r.phases[i].name.c_str(), r.phases[i].seconds);
    out += buf;
  }
  out += "},\n";
  add("seconds", total_seconds, true);
  return out + "}\n";
}

int mesh_body(void* context) {
  auto& args = *static_cast<MeshArgs*>(context);
  const auto start = std::chrono::steady_clock::now();
  Progress progress(!args.quiet);
  MeshOptions options = args.options;
  if (progress.enabled()) {
    options.decomposition.progress = [&progress](std::uint32_t done, std::uint32_t target) {
      progress.count(done, target);
    };
    options.progress = [&progress](std::uint32_t done, std::uint32_t total) { progress.count(done, total, "meshing"); };
  }
  progress.say("reading " + args.input);
  if (!args.sizes_file.empty()) options.size.triangle_area_samples = read_background(args.sizes_file, true);
  const Pslg domain = read_domain(args.input);
  progress.say("meshing " + std::to_string(options.decomposition.subdomains) + " subdomains");
  const MeshRun run = mesh_with_report(domain, options);
  const Mesh& m = run.mesh;
  const MeshReport& report = run.report;
  progress.say("writing");
  OutputSet outputs;
  add_mesh(outputs, m, args.prefix, args.formats);
  if (!args.split_dir.empty()) {
    const std::string stem = std::filesystem::path(args.prefix).filename().string();
    add_split_mesh(outputs, m, args.split_dir, stem, args.formats.first_index);
  }
  const std::string json = args.report ? report_json(args, m, report, seconds_since(start)) : std::string();
  if (args.report && !args.report_out.empty()) outputs.add_file(args.report_out, json);
  writing_outputs = 1;
  outputs.write();
  writing_outputs = 0;
  progress.done();
  if (args.report && args.report_out.empty()) std::fputs(json.c_str(), stdout);
  if (!args.quiet) {
    const AngleFigures a = angle_figures(m);
    std::fprintf(args.report && args.report_out.empty() ? stderr : stdout,
                 "%s: %u subdomains, %zu triangles, %zu vertices, smallest angle %.2f deg (%zu below %.4g: %zu at "
                 "small input angles, %zu at separators), %.2f s -> %s.{node,ele}\n",
                 args.input.c_str(), m.subdomain_count(), m.triangles.size(), m.points.size(), a.min_deg, a.below,
                 m.min_triangle_angle_deg, m.shortfall.input_angle, m.shortfall.separator, seconds_since(start),
                 args.prefix.c_str());
  }
  return exit_ok;
}

int run_mesh(int argc, char** argv) {
  MeshArgs args;
  const std::string problem = parse_mesh_arguments(argc, argv, args, false, true);
  if (problem == "help") {
    std::fputs(mesh_help, stdout);
    return exit_ok;
  }
  if (!problem.empty()) return usage_error("mesh", problem);
  return run_guarded("mesh", mesh_body, &args);
}

const CommandRegistration registration{
    {"mesh", "decompose and mesh every subdomain into one conforming quality mesh", run_mesh}};

} // namespace
} // namespace madd::cli
