#pragma once
// The command line of `madd mesh`, shared with the MPI driver `madd-mpi mesh`
// (cli/mpi/): the same options, from the one option table, mean the same
// mesh in both.
#include <span>
#include <string>

#include "command_line.hpp"
#include "option_table.hpp"

namespace madd::cli {

// What the command line asks for: line.mesh is the mesh's options, line.sizes_file
// the --sizes file to read into line.mesh.size.
struct MeshArgs {
  std::string input, prefix;  // prefix: -o, or INPUT without .poly
  CommandLine line;
};

// madd mesh's options (madd-mpi mesh's, but for the whole-mesh files).
inline const CommandOptions& mesh_options() { return options_of("mesh"); }

// The options of the files of the whole mesh (--neigh, --edge, --msh,
// --split-mesh), which madd-mpi, writing one part per rank, does not take.
std::span<const char* const> whole_mesh_file_options();

// Parses `argv` (argv[0] is the command name). Returns "" when the command
// line is good or --help was asked (args.line.help), else the usage problem,
// said with the flags as typed. `require_subdomains`: -n must be given (the
// MPI driver: its default could depend on the rank count); otherwise N
// defaults to 4 x the thread count. `whole_mesh_files`: --neigh, --edge,
// --msh and --split-mesh are taken (the single-process tool); else they are
// refused as not available here.
std::string parse_mesh_arguments(int argc, char** argv, MeshArgs& args, bool require_subdomains, bool whole_mesh_files);

}  // namespace madd::cli
