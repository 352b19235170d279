#pragma once
// The merged mesh (include/madd/mesh.hpp) as files (docs/formats.md, "Mesh
// outputs"): Triangle's .node/.ele/.neigh/.edge, gmsh's .msh 4.1, VTK's .vtu,
// and one .node/.ele pair per subdomain. As in output.hpp, every format_*
// function returns the whole text, and the add_* functions put files into an
// OutputSet, so a caller writes every output of a run all or nothing.
//
// Coordinates are written with %.17g everywhere (they read back exactly, and a
// vertex has the same text in every file, split pieces included). The ids of
// the Triangle files start at `first_index`, 0 or 1 (Triangle's -z); any
// other value throws OptionError("first_index", ...). gmsh and VTK have their
// own fixed conventions (1-based tags, 0-based connectivity).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_pieces.hpp"

namespace madd {

// PREFIX.node: "<#points> 2 0 1", then "id x y marker" per point, the marker
// from Mesh::point_markers.
std::string format_mesh_node(const Mesh& mesh, unsigned first_index = 1);

// PREFIX.ele: "<#triangles> 3 1", then "id a b c k" per triangle: its
// counter-clockwise vertices and, as its one attribute, its subdomain k
// (what `triangle -pA` writes for a region attribute).
std::string format_mesh_ele(const Mesh& mesh, unsigned first_index = 1);

// PREFIX.neigh: "<#triangles> 3", then "id n0 n1 n2": the triangle across
// the edge opposite vertex i, -1 outside the domain.
std::string format_mesh_neigh(const Mesh& mesh, unsigned first_index = 1);

// PREFIX.edge: "<#edges> 1", then "id a b marker": every edge of the mesh
// once (from the lower-numbered of its triangles, in that triangle's
// direction). A domain-boundary edge carries the marker of its boundary
// piece; interior edges, separators included, carry 0, as Triangle -pe
// writes an unmarked interior segment.
std::string format_mesh_edge(const Mesh& mesh, unsigned first_index = 1);

// PREFIX.msh, gmsh's MSH 4.1 ASCII. Entities: no points; one curve per
// boundary marker (in increasing marker order, tags 1, 2, ...), holding that
// marker's boundary edges as 2-node lines oriented counter-clockwise around
// the domain; one surface per subdomain k (tag k + 1), holding its triangles,
// bounded by the curves it touches. Physical groups: "subdomain_<k>"
// (dimension 2, tag k + 1) on surface k + 1, "boundary_<m>" (dimension 1) on
// the curve of marker m, tag m when m > 0, else the next tags after the
// largest positive marker. Node tag = point index + 1; each node is listed
// once, on the curve of its largest boundary marker when it is on the domain
// boundary, else on the surface of the lowest subdomain using it. Element
// tags: triangle t is t + 1 (its .ele id with first_index 1), then the lines.
std::string format_mesh_msh(const Mesh& mesh);

// PREFIX.vtu, a VTK XML UnstructuredGrid (ASCII): Float64 points (z = 0),
// one triangle cell (type 5) per triangle in order, 0-based connectivity;
// CellData: Int32 "subdomain"; PointData: Int32 "marker" (point_markers).
std::string format_mesh_vtu(const Mesh& mesh);

// One subdomain's mesh on its own, for --split-mesh: its vertices in
// increasing global index, renumbered from first_index. The .node is
// "<#vertices> 2 1 1", then "id x y global marker": the one attribute is the
// vertex's id in PREFIX.node written with the same first_index (exact as a
// double up to 2^53), so a vertex on a separator has the same global id, and
// the same coordinate text, in both pieces. The .ele is "<#triangles> 3 1",
// then "id a b c k" in local ids, the attribute k being the subdomain.
// Precondition: k < mesh.subdomain_count().
std::string format_subdomain_mesh_node(const Mesh& mesh, std::uint32_t k, unsigned first_index = 1);
std::string format_subdomain_mesh_ele(const Mesh& mesh, std::uint32_t k, unsigned first_index = 1);

// "<stem>-<k><extension>", k zero-padded as split_file_name pads it
// (extension with its dot: ".node").
std::string split_mesh_file_name(std::string_view stem, std::uint32_t k, std::uint32_t count,
                                 std::string_view extension);

// The mesh report: every figure of `metrics` as one JSON object, one member
// per line (counts as integers, other figures with every digit, %.17g; a
// median that is not known, NaN, is left out), then the figures of the run in
// the order given (a number with every digit, seconds with six: %.6g). Keys
// are those of MeshMetrics, "below_bound_<why>" for its shortfall and
// "smallest_angle_histogram_10deg"; docs/mesh.md, "The report".
std::string format_mesh_report_json(const MeshMetrics& metrics, const std::vector<RunFigure>& run = {});

// Which files add_mesh writes.
struct MeshFormats {
  bool triangle = true;      // PREFIX.node, PREFIX.ele
  bool neigh = false;        // PREFIX.neigh (Triangle's -n)
  bool edge = false;         // PREFIX.edge (Triangle's -e)
  bool msh = false;          // PREFIX.msh
  bool vtu = false;          // PREFIX.vtu
  unsigned first_index = 1;  // of the Triangle files: 0 or 1
  friend bool operator==(const MeshFormats&, const MeshFormats&) = default;
};

// Adds the chosen files of `mesh` under `prefix` to `outputs` (nothing is
// written yet). Throws OptionError on a bad first_index, OutputError when a
// path is already in the set. The .node, .ele, .neigh and .vtu files are made
// while they are written, on `threads` threads (0: one per core), the same
// bytes for any count (FilePieces): `mesh` must outlive outputs.write().
void add_mesh(OutputSet& outputs, const Mesh& mesh, const std::string& prefix, const MeshFormats& formats = {},
              unsigned threads = 1);
// The same files of a mesh kept in pieces (madd/mesh_pieces.hpp), byte for
// byte those of join(mesh), read from the pieces while they are written:
// `mesh` must outlive outputs.write().
void add_mesh(OutputSet& outputs, const MeshPieces& mesh, const std::string& prefix, const MeshFormats& formats = {},
              unsigned threads = 1);
// The same, written at once, all or nothing. Throws OutputError on I/O failure.
void write_mesh(const Mesh& mesh, const std::string& prefix, const MeshFormats& formats = {}, unsigned threads = 1);

// --split-mesh DIR: directory `dir` (created when missing) holding, for every
// subdomain k, split_mesh_file_name(stem, k, N, ".node") and ".ele". Files of
// an earlier run named "<stem>-<digits>.node" or ".ele" that this run does
// not produce are removed, so `dir` holds exactly this mesh's pieces.
// The subdomains' files are formatted on `threads` threads (0: one per
// core), the same bytes for any count.
void add_split_mesh(OutputSet& outputs, const Mesh& mesh, const std::string& dir, std::string_view stem,
                    unsigned first_index = 1, unsigned threads = 1);
void add_split_mesh(OutputSet& outputs, const MeshPieces& mesh, const std::string& dir, std::string_view stem,
                    unsigned first_index = 1, unsigned threads = 1);
void write_split_mesh(const Mesh& mesh, const std::string& dir, std::string_view stem, unsigned first_index = 1,
                      unsigned threads = 1);

}  // namespace madd
