// Which options of the table each command takes, in the order of its help,
// with the help it gives them (cli/option_table.hpp). madd-mpi mesh takes
// madd mesh's list, but for the whole-mesh files (cli/mesh_arguments.cpp).
#include <array>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>

#include "option_table.hpp"

namespace madd::cli {

namespace {

using enum Letter;

// The options of a GeoJSON or shapefile input, first in the list of every
// command that reads a domain (docs/coastal.md).
constexpr OptionUse coast_input_uses[] = {
    {nullptr, "GeoJSON and shapefile input (docs/coastal.md):"},
    {"clip", "cut the water polygons to the box X0,Y0,X1,Y1 (lon/lat, or x/y\n"
             "when projected); its sides become open boundary (marker 2)"},
    {"water-at", "keep the water body holding this point (default: the largest)"},
    {"min-island-area", "remove islands and lakes below A square metres\n"
                        "(default 4 hmin^2 with --hmin, else none)"},
};

template <std::size_t N>
constexpr std::array<OptionUse, std::size(coast_input_uses) + N> with_coast_input(const std::array<OptionUse, N>& own) {
  std::array<OptionUse, std::size(coast_input_uses) + N> all{};
  std::size_t k = 0;
  for (const OptionUse& use : coast_input_uses) all[k++] = use;
  for (const OptionUse& use : own) all[k++] = use;
  return all;
}

constexpr auto decompose_uses = with_coast_input(std::to_array<OptionUse>({
    {nullptr, ""},
    {nullptr, "decomposition:"},
    {"subdomains", "number of subdomains (default 2)"},
    {"min-angle", "smallest angle a separator may make (Phi0; default 60; 0 < DEG < 90)"},
    {"refine", "uniform boundary refinement factor (default 3)"},
    {"imbalance", "acceptable imbalance during a split, 0 < I <= 1 (default 0.75)"},
    {"threads", "worker threads, 0 = all cores (default 0); the result is identical"},
    {"seed", "random seed (default 1)", none},
    {"smoothing", "smoothing iterations, Sec. 5.1 (default 1; 0 = off)"},
    {"rebalance", "re-split subdomains above X x the mean area with their\n"
                  "neighbours (default 1.2; 0 = off; uniform or --weights runs)"},
    {"weight-gradation",
     "grade by the boundary density weights (vertex attribute 1):\n"
     "a subdomain weighs r * area + A * weight (default 0 = uniform)\n"
     "(was --gradation, now the size field's; -a A is deprecated here:\n"
     "madd mesh's -a is the largest triangle area)",
     deprecated},
    {"adaptive-refine", "graded by boundary weights: heavier edges get up to L times\n"
                        "more refinement points (default 4; 1 = uniform; 1 <= L <= 64)"},
    {"interpolation", "weight of new separator points = P x the interpolated weight\n"
                      "of the separator's ends (default 0)"},
    {"weight-fn", "grade by a density weight function f(x, y) (Sec. 5.2 case 3)"},
    {"area-fn", "split while a subdomain's area > bound x the required area\n"
                "function's minimum inside it (N is then the maximum)"},
    {"weights", "background density weights: .node, first attribute (case 2)"},
    {"areas", "background required areas: .node, first attribute (case 2)"},
    {"area-bound", "area / required area bound (default 1)"},
    {"time-limit", "give up (exit 6, nothing written) after S seconds (default 0 = none)"},
    {"max-memory", "give up (exit 6, nothing written) above MB megabytes resident\n"
                   "(default 0 = none; checked before every split)"},
    {"max-area",
     "write the outputs with every segment split for meshes of\n"
     "triangle area <= A (the decoupling, docs/mesh.md): --split's\n"
     "files, meshed one by one by `triangle -pq30Y`, join up",
     none},
    {"size-fn", "the same, the largest area at (x, y) given by EXPR"},
    {"sizes", "the same, the largest area at background nodes (.node,\n"
              "attribute 1), linear between them"},
    {"sizes-nearest", "read --sizes by the nearest node's value instead"},
    {"hmin", "the same, by madd mesh's size field in edge lengths h:\n"
             "h at the coast (--distance-rate), least h of --cells-across"},
    {"hmax", "largest h anywhere"},
    {"distance-rate", "h <= hmin + G x the distance to the coast"},
    {"cells-across", "at least R triangles across every channel and strait"},
    {"gradation", "h(x) <= h(y) + G |x - y| (was the decomposition's\n"
                  "grading factor: that is --weight-gradation now)"},
    {"coast-markers", "the boundary markers that are coast (default: all)"},
    {"no-verify", "skip the self-check (verify_decomposition) before writing"},
    {nullptr, ""},
    {nullptr, "outputs (none by default; see docs/formats.md):"},
    {"output",
     "the whole decomposition as one .poly, one region per subdomain\n"
     "(per face: with the input's regions, their attributes)",
     usual, "FILE.poly"},
    {"split", "one .poly per subdomain: DIR/<stem>-<k>.poly"},
    {"subdomains-file", "the paper's subdomain file"},
    {"svg", "a picture"},
    {"svg-numbers", "write subdomain numbers in the picture"},
    {"svg-mark-angles", "circle the new angles below DEG in the picture (0 = none)"},
    {"geo", "a gmsh model: gmsh -2 FILE.geo meshes all subdomains conformingly"},
    {"vtk", "legacy VTK for ParaView: subdomains as triangles, segments as\n"
            "lines, isolated vertices as vertices, with cell data"},
    {"geojson", "GeoJSON: one Polygon feature per subdomain, then interior\n"
                "segments (LineString) and isolated vertices (Point)"},
    {"report", "the quality figures as JSON (on stdout without FILE)"},
    {nullptr, ""},
    {"quiet", "print nothing on success\n(-q is deprecated here: madd mesh's -q is the angle bound)", deprecated},
    {"verbose", "print every quality figure and the phase times"},
    {"help", "this text"},
}));

constexpr auto mesh_uses = with_coast_input(std::to_array<OptionUse>({
    {"depth", "bathymetry: an Esri ASCII grid (.asc) or x y z scatter, in the\n"
              "input's coordinates, depth positive down; read at every node"},
    {"depth-up", "the depth file holds elevations (positive up)"},
    {nullptr, "mesh:"},
    {"quality", "smallest angle of every triangle, away from smaller input\n"
                "angles (default 30; 0 <= DEG < 60; the guarantee holds to 20.7,\n"
                "in practice to about 34)"},
    {"max-area", "largest triangle area (default none)"},
    {"size-fn", "largest triangle area at (x, y), an expression in x and y"},
    {"sizes", "largest triangle area at background nodes (.node, attribute 1;\n"
              "linear over the nodes' Delaunay triangulation)"},
    {"sizes-nearest", "read --sizes by the nearest node's value instead"},
    {"balance", "what the decomposition balances: the expected triangle\n"
                "count of each subdomain (work, default) or its area"},
    {"no-off-centres", "insert circumcentres only (more triangles)"},
    {"no-verify", "skip the self-check (verify_mesh) before writing"},
    {nullptr, "size field, in edge lengths h (area bound sqrt(3)/4 h^2; 0 = off):"},
    {"hmin", "h at the coast (--distance-rate), least h of --cells-across"},
    {"hmax", "largest h anywhere"},
    {"distance-rate", "h <= hmin + G x the distance to the coast (needs --hmin)"},
    {"cells-across", "at least R triangles across every channel, strait and gap:\n"
                     "h <= 2 x the local half-width of the water / R"},
    {"gradation", "h(x) <= h(y) + G |x - y|: sizes grow by at most G per unit\n"
                  "length (needs another size bound)"},
    {"wavelength-cells", "h <= T sqrt(g depth) / K: K cells per M2 tidal wavelength\n"
                         "(needs --depth)"},
    {"slope-cells", "h <= 2 pi depth / (K |grad depth|) (needs --depth)"},
    {"coast-markers", "the boundary markers that are coast for --distance-rate and\n"
                      "--cells-across (default: every boundary segment)"},
    {nullptr, "decomposition:"},
    {"subdomains", "number of subdomains (default: the thread count x 4)"},
    {"min-angle", "Phi0, the smallest angle a separator makes (default 60)"},
    {"threads", "threads, 0 = all cores (default 0); the mesh is identical"},
    {"seed", "random seed of the decomposition (default 1)", none},
    {"rebalance", "repair subdomains above X x the mean work (default 1.1; 0 = off)"},
    {"time-limit", "give up (exit 6, nothing written) after S seconds (default none)"},
    {"max-memory", "give up (exit 6, nothing written) above MB megabytes resident"},
    {nullptr, "outputs:"},
    {"output", "PREFIX.node and PREFIX.ele (default: INPUT without .poly)", usual, "PREFIX"},
    {"neigh", "also PREFIX.neigh (Triangle's -n)"},
    {"edge", "also PREFIX.edge (Triangle's -e)"},
    {"msh", "also PREFIX.msh (gmsh 4.1: a physical surface per subdomain)"},
    {"vtu", "also PREFIX.vtu (VTK; subdomain as cell data)"},
    {"split-mesh", "also one .node/.ele per subdomain in DIR, with global vertex ids"},
    {"fort14", "also an ADCIRC fort.14 (lon/lat for a lon/lat input; open and\n"
               "land boundaries from the markers; depths from --depth)"},
    {"gr3", "also a SCHISM hgrid.gr3 (metres), and hgrid.ll beside it for a\n"
            "lon/lat input"},
    {"2dm", "also an SMS .2dm (nodestrings for the open and land boundaries)"},
    {"lonlat", "write PREFIX.node, .msh and .vtu in lon/lat (default: metres)"},
    {"report", "the mesh figures as JSON on stdout (or in FILE)"},
    {"quiet", "print nothing on success", none},
    {"help", "this text"},
}));

// gpmetis's spellings without a line of their own: the help's text names them.
constexpr OptionUse partition_uses[] = {
    {"parts", "number of parts (>= 1)"},
    {"ufactor", "allowed imbalance (1 + U/1000) of the largest part, as gpmetis;\n"
                "default 1 (gpmetis's default for -ptype=rb). For K > 2 each\n"
                "bisection gets (1 + U/1000)^(1/ceil(log2 K))."},
    {"seed", "random seed (default 1); same seed, same result"},
    {"contig", "make every part connected (when the graph is)"},
    {"niter", "FM refinement passes per level, 0 to 1000 (default {niter})"},
    {"nooutput", "write no GRAPH.part.K, only print the figures"},
    {"quiet", "print nothing on success"},
    {"help", "this text"},
    {"ptype", nullptr},
    {"objtype", nullptr},
    {"ctype", nullptr},
    {"iptype", nullptr},
    {"no2hop", nullptr},
};

constexpr OptionUse script_uses[] = {
    {"quiet", "print nothing on success"},
    {"help", "this text"},
};

constexpr auto check_uses = with_coast_input(std::to_array<OptionUse>({
    {"hmin", "the mesh's --hmin: islands below 4 hmin^2 are removed, as madd mesh\n"
             "removes them (unless --min-island-area)"},
    {"write-poly", "write the domain as it was cleaned and projected (metres)"},
    {"quiet", "print nothing on success; only the exit code tells"},
    {"help", "this text"},
}));

constexpr auto triangulate_uses = with_coast_input(std::to_array<OptionUse>({
    {"convex-hull", "keep the whole convex hull but the holes (Triangle -pc)"},
    {"region-attributes", "give each triangle the attribute of its region (a\n"
                          "column of PREFIX.ele; 0 outside every region), as Triangle -A"},
    {"resolve-crossings", "split crossing and overlapping segments at new\n"
                          "intersection vertices (default: such segments are bad input)"},
    {"output", "output prefix (default: FILE without .poly or .node, plus \".1\")", usual, "PREFIX"},
    {"quiet", "print nothing on success"},
    {"help", "this text"},
}));

const CommandOptions commands[] = {
    {"decompose", decompose_uses, 25}, {"mesh", mesh_uses, 25},   {"partition", partition_uses, 21},
    {"script", script_uses, 25},       {"check", check_uses, 25}, {"triangulate", triangulate_uses, 25},
};

}  // namespace

const CommandOptions& options_of(std::string_view command) {
  for (const CommandOptions& c : commands)
    if (command == c.command) return c;
  throw std::out_of_range("no options of command '" + std::string(command) + "'");
}

std::span<const CommandOptions> command_options() { return commands; }

}  // namespace madd::cli
