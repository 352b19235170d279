#pragma once
// madd mesh's coastal model files (docs/coastal.md): --fort14, --gr3 (with
// hgrid.ll beside it for a lon/lat input), --2dm, with the depths of
// --depth at every node, and --lonlat's Triangle, gmsh and VTK files in
// longitude/latitude.
#include <optional>
#include <string>

#include "command_line.hpp"
#include "madd/atomic_write.hpp"
#include "madd/bathymetry.hpp"
#include "madd/coast.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/model_output.hpp"

namespace madd::cli {

// What the model files of one run are made from; must outlive the
// OutputSet they are added to (the files are made while written).
struct ModelFiles {
  ModelGrid metres;          // coordinates in the projection's metres
  ModelGrid lonlat;          // the same in longitude/latitude (a lon/lat input only)
  Mesh lonlat_mesh;          // --lonlat: the mesh with its points in lon/lat (of a merged mesh)
  MeshPieces lonlat_pieces;  // the same of a mesh in pieces
};

// The depth file of the command line, read (nullopt without --depth).
std::optional<DepthField> read_depth(const CommandLine& line);

// Whether the command line asks for model files (--fort14, --gr3, --sms) or
// for the mesh files in lon/lat (--lonlat on a geographic input): what
// add_model_files writes.
bool wants_model_files(const CommandLine& line, const Projection& projection);

// Fills `files` for `mesh` and adds every model file the command line asks
// for to `outputs`, and with --lonlat PREFIX's mesh files in lon/lat
// (instead of add_mesh's). Returns whether it added the mesh files. The
// files' title is `title`, or when empty PREFIX's file name + " (madd mesh)".
bool add_model_files(OutputSet& outputs, ModelFiles& files, const Mesh& mesh, const CommandLine& line,
                     const std::string& prefix, const Projection& projection, const std::optional<DepthField>& depth,
                     unsigned threads, const std::string& title = {});
// The same files of a mesh kept in pieces (byte for byte those of its join).
bool add_model_files(OutputSet& outputs, ModelFiles& files, const MeshPieces& mesh, const CommandLine& line,
                     const std::string& prefix, const Projection& projection, const std::optional<DepthField>& depth,
                     unsigned threads, const std::string& title = {});

}  // namespace madd::cli
