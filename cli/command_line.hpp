#pragma once
// What a command line of madd or madd-mpi says: the library's options as the
// rows of the option table fill them (cli/option_table.hpp), the files it
// names and the front end's own switches. Each command reads what it takes.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "madd/bisect.hpp"
#include "madd/coast.hpp"
#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_output.hpp"
#include "madd/output.hpp"
#include "madd/triangulation.hpp"

namespace madd::cli {

// An option as the user typed it: its flag ("-q" or "--quality") and value.
struct Typed {
  std::string flag;
  std::string value;
};

struct CommandLine {
  // The library's options. mesh.decomposition is what every command that
  // decomposes runs (madd decompose starts it from DecomposeOptions' own
  // defaults); mesh.size bounds madd mesh's triangles and discretises madd
  // decompose's outputs; mesh.verify is the self-check of either.
  MeshOptions mesh;
  SvgOptions svg;
  PartitionOptions partition;
  TriangulateOptions triangulate;

  // Files: -o (decompose's FILE.poly, mesh's and triangulate's PREFIX), the
  // other outputs, and the inputs options name.
  std::string output, split_dir, subdomains_file, svg_file, geo_file, vtk_file, geojson_file, split_mesh_dir;
  std::string weights_file, areas_file, sizes_file;
  MeshFormats formats;  // madd mesh's files besides PREFIX.node and PREFIX.ele

  // A GIS polygon input (docs/coastal.md): how it becomes a domain, and the
  // coastal model's files and depths.
  CoastOptions coast;
  bool min_island_area_given = false;  // else 4 hmin^2 when --hmin is given
  std::string write_poly_file;         // check: the domain as cleaned, in metres
  std::string depth_file;
  bool depth_up = false;  // the depth file holds elevations, positive up
  std::string fort14_file, gr3_file, sms_file;
  bool lonlat = false;  // mesh: PREFIX.node/.msh/.vtu in longitude/latitude
  bool report = false;
  std::string report_file;  // --report=FILE; empty: on stdout

  std::uint32_t parts = 0;         // partition: -k
  long ufactor = 1;                // partition: METIS's default for -ptype=rb, 1.001
  bool write_output = true;        // partition: not --nooutput
  bool resolve_crossings = false;  // triangulate -r
  bool subdomains_given = false;   // -n was given
  bool quiet = false, verbose = false, help = false;

  std::vector<std::string> operands;   // the arguments that are no option, in order
  std::map<std::string, Typed> typed;  // by option name: what the user typed, for messages
};

// line.mesh with the background meshes the command line names read into the
// options they are for: --weights and --areas into the decomposition's
// density weights and required areas, --sizes into the triangle sizes.
// Throws what read_background_samples throws (bad input, exit 3).
MeshOptions with_background_files(const CommandLine& line);

}  // namespace madd::cli
