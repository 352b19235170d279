#pragma once
// Meshing one share of the subdomains: what a distributed driver (madd-mpi,
// docs/mpi.md) runs on each of its processes, so that together they make
// exactly the mesh mesh() makes, triangle for triangle and vertex number for
// vertex number, without ever sending a mesh.
//
// Every process decomposes the domain itself (deterministic, so they all get
// the same decomposition), discretises it, and takes the subdomains
// assign_shares gives it. Meshing needs no communication; between rounds
// (docs/mesh.md, "Decoupling": a separator piece that stopped a fix is split
// for both its sides) the processes agree on which pieces to split, and at
// the end on how many points and triangles each subdomain made, so that
// everyone numbers its vertices as mesh() would. Both are small collectives
// that the caller provides (ShareExchange); the library never depends on MPI.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"

namespace madd {

// The decomposition mesh() makes of `domain` with these options (balanced by
// expected triangles when options.balance_by_work), with decompose()'s
// report. Throws what decompose() throws.
DecomposeRun decompose_for_mesh(const Pslg& domain, const MeshOptions& options);

// Which share meshes each subdomain: the subdomains by decreasing expected
// triangles (ties: lower index first), each to the share with the least
// expected work so far (ties: the lower share). Deterministic.
// Precondition: shares >= 1.
std::vector<std::uint32_t> assign_shares(const std::vector<double>& expected_triangles, std::uint32_t shares);

// The two agreements between shares. Every share calls each of them the same
// number of times in the same order (so an MPI driver implements them as
// collectives: MPI_Allgatherv, MPI_Allreduce).
struct ShareExchange {
  // This share's sorted separator ids -> the sorted union over all shares.
  std::function<std::vector<std::uint32_t>(const std::vector<std::uint32_t>& mine)> union_of;
  // A count per subdomain, 0 for other shares' subdomains -> the sum over shares.
  std::function<std::vector<std::uint64_t>(const std::vector<std::uint64_t>& mine)> sum_of;
};

// One share's triangles and the vertices they use, in local numbering: the
// fields mean what Mesh's do, but it is not a Mesh (it covers only the
// share's subdomains, and its points are not the decomposition's).
struct LocalMesh {
  std::vector<Point> points;       // the vertices the share's triangles and mesh segments use
  std::vector<int> point_markers;  // as Mesh::point_markers
  // Counter-clockwise, grouped by subdomain: the share's subdomain k has
  // [subdomain_first_triangle[k], subdomain_first_triangle[k + 1]), other
  // shares' subdomains an empty range.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // neighbours[t][i]: the triangle across edge i; no_index on the domain
  // boundary and towards another share's triangle.
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  std::vector<std::uint32_t> triangle_subdomain;
  std::vector<double> triangle_attribute;               // as Mesh::triangle_attribute
  std::vector<std::uint32_t> subdomain_first_triangle;  // N + 1 offsets
  // The share's mesh edges on pieces of the discretised decomposition
  // (MeshSegment::piece indexes MeshPart::decomposition.segments).
  std::vector<MeshSegment> segments;
  MeshShortfall shortfall;               // of the share's triangles
  double min_triangle_angle_deg = 30.0;  // the bound it was refined to
  friend bool operator==(const LocalMesh&, const LocalMesh&) = default;
};

// One share's part of the mesh.
struct MeshPart {
  std::uint32_t share = 0, shares = 1;
  std::vector<std::uint32_t> owner;       // per subdomain: the share that meshes it
  std::vector<std::uint32_t> subdomains;  // this share's, increasing
  // The whole discretised decomposition, the same for every share (its point
  // indices are global ids, mesh()'s Mesh::points, not local ones).
  Decomposition decomposition;
  LocalMesh mesh;                           // this share's triangles, in local numbering
  std::vector<std::uint64_t> point_ids;     // per local vertex: its index in mesh()'s Mesh::points
  std::vector<std::uint32_t> point_owner;   // per local vertex: the lowest share whose subdomains use it
  std::vector<std::uint64_t> triangle_ids;  // per local triangle: its index in mesh()'s Mesh::triangles
  std::uint64_t total_points = 0;           // of the whole mesh
  std::uint64_t total_triangles = 0;
  friend bool operator==(const MeshPart&, const MeshPart&) = default;
};

// A share's part and the report of the run that made it (the phases "size
// field" when there is one, "discretise", "estimate", "refine", each
// subdomain's check included, and "assemble": the part made from the
// subdomains' meshes; the share's threads and subdomains).
struct MeshPartRun {
  MeshPart part;
  MeshReport report;
  friend bool operator==(const MeshPartRun&, const MeshPartRun&) = default;
};

// Meshes the subdomains of share `share` of `shares` of a decomposition of
// `domain` (decompose_for_mesh's), on options.decomposition.threads threads.
// With options.verify, each of this share's subdomain meshes is checked
// (verify_mesh on the subdomain alone: constrained Delaunay, covering,
// conforming to its discretised boundary, sizes and angles) by the thread
// that meshed it, as soon as its mesh is final;
// the separators both sides share are discretised identically by
// construction, which is what makes the union conform. Throws OptionError on
// bad options (or share >= shares), LimitError, InternalError on a failed
// check; never returns a partial part. The union of the parts of shares
// 0..shares-1 is mesh()'s mesh, for any `shares`.
MeshPartRun mesh_share(const Decomposition& decomposition, const Pslg& domain, const MeshOptions& options,
                       std::uint32_t share, std::uint32_t shares, const ShareExchange& exchange);

// The whole mesh from the parts of every share of one run (in any order):
// mesh()'s Mesh, equal to it, for a driver that writes a file of the whole
// mesh in one place (madd-mpi's model files, written by rank 0). The parts'
// points and triangles go to their global ids; neighbours across shares are
// matched by their shared edge; the segments are listed as mesh() lists
// them. Throws InvalidInputError when the parts are not those of one run
// (a share missing or twice, ids out of range, a triangle left out).
Mesh join_parts(std::span<const MeshPart> parts);

}  // namespace madd
