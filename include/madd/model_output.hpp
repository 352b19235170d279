#pragma once
// A mesh (include/madd/mesh.hpp, or kept in pieces: madd/mesh_pieces.hpp)
// as the grid files of coastal ocean models: ADCIRC's fort.14, SCHISM's
// hgrid.gr3 / hgrid.ll and SMS's .2dm, with the domain's open (ocean) and
// land boundaries; and fort.14 read back and checked. As in mesh_output.hpp, every format_* function returns the
// whole text and the add_* functions put a file into an OutputSet.
//
// The sources of each layout (cited again where it is written):
//   fort.14: ADCIRC, "Fort.14: Grid and Boundary Information File"
//     (adcirc.github.io/adcirc/technical_reference/input_files/fort14.html), its
//     IBTYPE table ("Flux specified boundaries", wiki.adcirc.org) and the
//     v51/v52 manual's "General Notes for Normal Flow Boundary Conditions"
//     (adcirc.org/home/documentation/users-manual-v52/input-file-descriptions/
//     adcirc-grid-and-boundary-information-file-fort-14/);
//   hgrid.gr3, hgrid.ll: SCHISM's "Horizontal grid" input
//     (schism-dev.github.io/schism, its pages input-output/hgrid and
//     input-output/optional-inputs for hgrid.ll);
//   .2dm: SMS, "2D Mesh Files *.2dm" (xmswiki.com/wiki/SMS:2D_Mesh_Files_*.2dm).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/error.hpp"
#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_pieces.hpp"

namespace madd {

// What a model file says beyond the mesh. Checked by every format_* and
// add_* function: OptionError("coordinates" | "depth" | "title", ...).
struct ModelGrid {
  std::string title = "madd";      // the first line (fort.14's AGRID, the .gr3 description); one line
  std::vector<Point> coordinates;  // per mesh point, as written (lon/lat degrees, or metres); empty: mesh.points
  std::vector<double> depth;       // per mesh point, metres positive below the datum; empty: all 0
  int open_marker = 2;             // boundary edges with this marker are open (ocean) boundary, all others land
  friend bool operator==(const ModelGrid&, const ModelGrid&) = default;
};

// open: elevation specified (fort.14's NOPE lists); mainland: land lists of
// the outer boundary, and the land runs of a hole whose boundary is partly
// open (external, no normal flow); island: a hole's whole boundary when all
// of it is land (internal, no normal flow, closed).
enum class BoundaryKind : std::uint8_t { open, mainland, island };
const char* to_string(BoundaryKind kind) noexcept;  // "open", "mainland", "island"

// One boundary list: 0-based mesh point ids in order, the domain on the left
// (counter-clockwise along the outer boundary, clockwise around a hole).
// closed: the list is a whole boundary loop of one kind, its first node
// repeated at the end (ADCIRC's rule for islands and for a boundary that
// surrounds the domain); otherwise a run from one end to the other, sharing
// its end nodes with the runs before and after it on its loop.
struct ModelBoundary {
  BoundaryKind kind = BoundaryKind::mainland;
  std::vector<std::uint32_t> nodes;
  bool closed = false;
  friend bool operator==(const ModelBoundary&, const ModelBoundary&) = default;
};

// The mesh's boundary as model boundary lists (docs/formats.md, "Coastal
// model files"). The boundary edges (triangle edges with no neighbour) are
// chained into closed loops with the domain on their left, each edge to the
// next one turning around their common vertex through that vertex's fan of
// triangles, so a loop never jumps where boundaries touch at a vertex (an
// island touching the coast or another island: one loop through it twice).
// The outer loop is the one of largest signed area (the only
// counter-clockwise one of a connected domain); every other loop is a hole.
// A loop's edges are open when their MeshSegment marker is `open_marker`
// (an edge no segment covers: marker 1), else land. Each loop starts at its
// smallest directed edge (a, b) in (a, b) order, then, if it has both kinds,
// at the first start of an open run from there; it is split into maximal
// runs of one kind, or, all one kind, is one closed list. Order: the open
// lists (the outer loop's, then the holes'), the mainland lists (likewise),
// the islands; holes in the order of their smallest directed edge.
// Deterministic. Throws InvalidInputError when the triangles' neighbours are
// not consistent (a malformed Mesh).
std::vector<ModelBoundary> model_boundaries(const Mesh& mesh, int open_marker = 2);
// The same lists of a mesh kept in pieces (madd/mesh_pieces.hpp): those of
// join(mesh), traced through the pieces.
std::vector<ModelBoundary> model_boundaries(const MeshPieces& mesh, int open_marker = 2);

// fort.14: AGRID; "NE NP"; NP lines "JN X Y DP"; NE lines "JE 3 N1 N2 N3"
// (counter-clockwise in mesh.points); NOPE, NETA, then per open list
// "NVDLL 0" and its nodes; NBOU, NVEL, then per land list "NVELL IBTYPE"
// (20 mainland, 21 island: natural no normal flow, external or internal)
// and its nodes. Ids are 1-based; reals are the shortest text that reads
// back as the same double. Each count line carries a "! NAME = ..." comment.
std::string format_fort14(const Mesh& mesh, const ModelGrid& grid = {});

// hgrid.gr3 (hgrid.ll with lon/lat coordinates): the layout of fort.14 with
// SCHISM's boundary part: "N = Number of open boundaries", "... = Total
// number of open boundary nodes", per open list "NVDLL = Number of nodes for
// open boundary k" (no type); then the land lists with flag 0 (exterior:
// the mainland lists) or 1 (island). Islands are not closed (the first node is not repeated). A loop
// of one kind all round (the outer boundary all land, or any loop all open)
// is written as two lists of that kind linked at both ends, as SCHISM's notes
// ask for a domain with no open, or no land, boundary.
std::string format_gr3(const Mesh& mesh, const ModelGrid& grid = {});

// .2dm: "MESH2D", "NUM_MATERIALS_PER_ELEM 1", "MESHNAME \"title\"", then
// "ND id x y z" per point with z = -depth (the card's z is the vertical
// coordinate, positive up: elevation), "E3T id n1 n2 n3 m" per triangle with
// material m = subdomain + 1, then one nodestring per model boundary list
// (fort.14's lists, closed ones repeating their first node): "NS" cards of
// at most 10 ids, the last id of each nodestring negative. The title must
// not hold '"' (OptionError).
std::string format_2dm(const Mesh& mesh, const ModelGrid& grid = {});

// Add the file at `path` to `outputs` (nothing is written yet); the node and
// element lines are made while written, on `threads` threads (0: one per
// core), the same bytes for any count: `mesh` and `grid` must outlive
// outputs.write(). Throw OptionError as format_* do, OutputError when `path`
// is already in the set.
void add_fort14(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid,
                unsigned threads = 1);
void add_gr3(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid,
             unsigned threads = 1);
void add_2dm(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid,
             unsigned threads = 1);
// The same files of a mesh kept in pieces, byte for byte those of
// join(mesh), read from the pieces while they are written (a grid's
// coordinates and depths are per point in the merged numbering: mesh_points).
void add_fort14(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
                unsigned threads = 1);
void add_gr3(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
             unsigned threads = 1);
void add_2dm(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
             unsigned threads = 1);

// One boundary segment of a fort.14, as the file gives it.
struct Fort14Boundary {
  int type = 0;                       // IBTYPEE (open) or IBTYPE (flow boundary)
  std::vector<std::uint32_t> nodes;   // NBDV / NBVV, 0-based
  std::vector<std::uint32_t> paired;  // IBCONN, 0-based, for IBTYPE 4, 24, 64, 5, 25; else empty
  std::vector<double> values;         // per node, the reals after its ids, row-major (barrier heights...)
  std::uint32_t line = 0;             // the line of its "NVDLL IBTYPEE" / "NVELL IBTYPE" record
  friend bool operator==(const Fort14Boundary&, const Fort14Boundary&) = default;
};

// A fort.14 as read: ids 0-based.
struct Fort14 {
  std::string title;                                   // AGRID, the whole first line
  std::vector<Point> points;                           // X, Y
  std::vector<double> depths;                          // DP
  std::vector<std::array<std::uint32_t, 3>> elements;  // NM
  std::uint64_t declared_open_nodes = 0;               // NETA as written
  std::uint64_t declared_land_nodes = 0;               // NVEL as written
  std::vector<Fort14Boundary> open_boundaries;         // NOPE lists
  std::vector<Fort14Boundary> land_boundaries;         // NBOU lists
  friend bool operator==(const Fort14&, const Fort14&) = default;
};

// Strict reader (docs/formats.md, "Coastal model files"): one record a line, as
// documented; blank lines skipped; after a record's numbers the rest of the
// line is a comment when its first word is not a number ("! NE NP", "= Number
// of open boundaries"), and an error when it is (an extra field); JN and JE
// must run 1, 2, ...; NHY must be 3; node ids within 1..NP; IBTYPE one the
// page lists (0, 1, 2, 10, 11, 12, 20, 21, 22, 30; 3, 13, 23; 4, 24, 64;
// 5, 25), with its per-node fields; reals finite ('D' exponents accepted);
// nothing but blank lines after the last flow boundary. Counts are checked
// against the bytes left before anything is allocated. NETA and NVEL are
// kept as written (check_fort14 compares them). Throws ParseError
// ("path:line:column: message").
Fort14 parse_fort14(std::string_view text, const std::string& path = "<memory>");
// Reads the file and parses it; InputFileError when it cannot be read.
Fort14 read_fort14_file(const std::string& path);

// What a model needs of a fort.14 beyond its syntax (docs/formats.md,
// "Coastal model files"): NETA and NVEL equal to the nodes listed (NVEL
// counting a barrier's paired nodes too); every element non-degenerate and
// counter-clockwise in the file's coordinates (exact orientation); every edge
// in at most two elements, oppositely oriented; every node in an element;
// every boundary list of at least 2 nodes, each consecutive pair a boundary
// edge (in exactly one element) with the domain on its left (a barrier's
// IBCONN list: on its right); every boundary edge in exactly one list; the
// islands (IBTYPE 1, 11, 21) closed, their first node repeated last; every
// external flow boundary before the internal ones (1, 11, 21, 4, 24, 64, 5,
// 25). Problems name lists and nodes 1-based, as in the file; each kind of
// problem is reported for its first 10 cases and counted. Never throws.
Verification check_fort14(const Fort14& grid);

}  // namespace madd
