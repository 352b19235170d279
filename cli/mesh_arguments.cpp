// The command line of `madd mesh` and `madd-mpi mesh` (cli/mesh_arguments.hpp).
#include "mesh_arguments.hpp"

#include <algorithm>
#include <string>
#include <thread>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"

namespace madd::cli {

namespace {

// The files of the whole mesh, which one process of several does not write
// (madd-mpi gathers the parts on rank 0 for the coastal model files only:
// docs/mpi.md), and --lonlat, which is of PREFIX's files.
constexpr const char* whole_mesh_only[] = {"neigh", "edge", "msh", "split-mesh", "lonlat"};

// check_options of the decomposition and of the mesh, said with the flags.
std::string option_problem(const CommandLine& line) {
  try {
    check_options(line.mesh.decomposition);
  } catch (const OptionError& e) {
    return cli_message(e, Scope::decomposition, mesh_options(), line);
  }
  MeshOptions mesh = line.mesh;
  // The --sizes file is read later; its presence is what a check needs (a size bound to grade).
  if (!line.sizes_file.empty()) mesh.size.triangle_area_samples = {{{0, 0}, 1.0}};
  // Likewise the --depth file, read with the domain (its coordinates are the input's).
  if (!line.depth_file.empty()) {
    mesh.size.depth = [](double, double) { return 1.0; };
    mesh.size.depth_gradient = [](double, double) { return Point{}; };
  }
  try {
    check_options(mesh);
  } catch (const OptionError& e) {
    return cli_message(e, Scope::mesh_size, mesh_options(), line);
  }
  return {};
}

}  // namespace

std::span<const char* const> whole_mesh_file_options() { return whole_mesh_only; }

std::string parse_mesh_arguments(int argc, char** argv, MeshArgs& args, bool require_subdomains,
                                 bool whole_mesh_files) {
  CommandLine& line = args.line;
  const auto declined = whole_mesh_files ? std::span<const char* const>() : whole_mesh_file_options();
  const std::string problem = parse_command_line(mesh_options(), argc, argv, line, declined);
  if (!problem.empty() || line.help) return problem;
  if (line.operands.size() != 1) return "expected exactly one input file";
  args.input = line.operands.front();
  if (!line.subdomains_given) {
    if (require_subdomains) return "-n N is required (the mesh depends on N, and must not depend on the rank count)";
    const unsigned t = line.mesh.decomposition.threads ? line.mesh.decomposition.threads
                                                       : std::max(1u, std::thread::hardware_concurrency());
    line.mesh.decomposition.subdomains = 4 * t;
  }
  args.prefix = line.output;
  if (args.prefix.empty()) {
    args.prefix = args.input;
    for (const std::string ext : {".poly", ".geojson", ".json", ".shp"})
      if (args.prefix.size() > ext.size() &&
          args.prefix.compare(args.prefix.size() - ext.size(), ext.size(), ext) == 0) {
        args.prefix.resize(args.prefix.size() - ext.size());
        break;
      }
  }
  return option_problem(line);
}

}  // namespace madd::cli
