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
#include <cstdint>
#include <functional>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"

namespace madd {

// The decomposition mesh() makes of `domain` with these options (balanced by
// expected triangles when options.balance_by_work). Throws what decompose() throws.
Decomposition decompose_for_mesh(const Pslg& domain, const MeshOptions& options, std::vector<PhaseTime>& phases);

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

// One share's part of the mesh.
struct MeshPart {
  std::uint32_t share = 0, shares = 1;
  std::vector<std::uint32_t> owner;       // per subdomain: the share that meshes it
  std::vector<std::uint32_t> subdomains;  // this share's, increasing
  // This share's triangles and the vertices they use, in local numbering:
  // mesh.decomposition is the whole discretised decomposition (its point
  // indices are global ids, not local ones), the triangle ranges of other
  // shares' subdomains are empty, and a neighbour in another share is no_index.
  Mesh mesh;
  std::vector<std::uint64_t> point_ids;     // per local vertex: its index in mesh()'s Mesh::points
  std::vector<std::uint32_t> point_owner;   // per local vertex: the lowest share whose subdomains use it
  std::vector<std::uint64_t> triangle_ids;  // per local triangle: its index in mesh()'s Mesh::triangles
  std::uint64_t total_points = 0;           // of the whole mesh
  std::uint64_t total_triangles = 0;
};

// Meshes the subdomains of share `share` of `shares` of a decomposition of
// `domain` (decompose_for_mesh's), on options.decomposition.threads threads.
// With options.verify, each of this share's subdomain meshes is checked
// (verify_mesh on the subdomain alone: constrained Delaunay, covering,
// conforming to its discretised boundary, sizes and angles) before returning;
// the separators both sides share are discretised identically by
// construction, which is what makes the union conform. Throws OptionError on
// bad options (or share >= shares), LimitError, InternalError on a failed
// check; never returns a partial part. The union of the parts of shares
// 0..shares-1 is mesh()'s mesh, for any `shares`.
MeshPart mesh_share(const Decomposition& decomposition, const Pslg& domain, const MeshOptions& options,
                    std::uint32_t share, std::uint32_t shares, const ShareExchange& exchange, MeshReport& report);

} // namespace madd
