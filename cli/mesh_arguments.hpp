#pragma once
// The command line of `madd mesh`, shared with the MPI driver `madd-mpi mesh`
// (cli/mpi/): the same options mean the same mesh in both.
#include <string>

#include "madd/mesh.hpp"
#include "madd/mesh_output.hpp"

namespace madd::cli {

// What the command line asks for.
struct MeshArgs {
  std::string input, prefix, split_dir, report_out, sizes_file;
  MeshOptions options;
  MeshFormats formats;
  bool subdomains_given = false;
  bool report = false;
  bool quiet = false;
};

// Parses `argv` (argv[0] is the command name). Returns "" when the command
// line is good, "help" when --help was asked, else the usage problem, said
// with the CLI's option names. `require_subdomains`: -n must be given (the
// MPI driver: its default could depend on the rank count); otherwise N
// defaults to 4 x the thread count. `extra_formats`: --neigh, --edge, --msh
// and --split-mesh are accepted (the single-process tool).
std::string parse_mesh_arguments(int argc, char** argv, MeshArgs& args, bool require_subdomains, bool extra_formats);

} // namespace madd::cli
