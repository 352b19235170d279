#pragma once
// A mesh kept as its subdomains made it (docs/mesh.md, "Meshes in pieces"):
// each subdomain's triangles in its own numbering, with the offsets that
// number them as the merged Mesh would, never copied into one array. A
// program that only writes the mesh's files keeps this instead of a Mesh:
// no merge, half the memory at the end of a run, each subdomain checked by
// the thread that meshed it, and files byte-identical to the merged mesh's
// (add_mesh and add_split_mesh in madd/mesh_output.hpp, mesh_metrics in
// madd/mesh_metrics.hpp).
#include <cstdint>
#include <memory>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"

namespace madd {

namespace detail {
struct MeshPiecesData;
}

class MeshPieces {
public:
  MeshPieces();
  explicit MeshPieces(detail::MeshPiecesData data);
  MeshPieces(const MeshPieces& other);
  MeshPieces(MeshPieces&& other) noexcept;
  MeshPieces& operator=(const MeshPieces& other);
  MeshPieces& operator=(MeshPieces&& other) noexcept;
  ~MeshPieces();

  // What the merged mesh's fields would say: Mesh::subdomain_count(),
  // points.size(), triangle_count(), the triangles of subdomain k
  // (precondition k < subdomain_count()), decomposition, shortfall and
  // min_triangle_angle_deg.
  std::uint32_t subdomain_count() const noexcept;
  std::uint64_t point_count() const noexcept;
  std::uint64_t triangle_count() const noexcept;
  std::uint64_t subdomain_triangle_count(std::uint32_t k) const;
  const Decomposition& decomposition() const noexcept;
  MeshShortfall shortfall() const noexcept;
  double min_triangle_angle_deg() const noexcept;

  // Equal pieces: the same mesh, in the same pieces.
  friend bool operator==(const MeshPieces& a, const MeshPieces& b);

  // The library's own view (src/mesh/mesh_pieces.hpp).
  const detail::MeshPiecesData& data() const noexcept { return *data_; }

private:
  friend Mesh join(MeshPieces pieces, unsigned threads);
  friend MeshPieces with_points(MeshPieces mesh, const std::vector<Point>& points, unsigned threads);
  std::unique_ptr<detail::MeshPiecesData> data_;
};

// A mesh in pieces and the report of the run that made it.
struct MeshPiecesRun {
  MeshPieces mesh;
  MeshReport report;
  friend bool operator==(const MeshPiecesRun&, const MeshPiecesRun&) = default;
};

// mesh_with_report()'s mesh, kept in pieces: the same options, the same
// triangles and numbering (join() of it equals mesh()'s Mesh). With
// options.verify, each subdomain's mesh is checked alone by the thread that
// made it, as soon as it is final, and what crosses subdomains (placement,
// separators matched and linked both ways, the mesh segments along the
// decomposition and the input, the cover of the domain) after; the report's
// phases end "refine" (the subdomains' checks included), "assemble",
// "verify". Throws as mesh() does (InternalError when a check fails).
MeshPiecesRun mesh_pieces_with_report(const Pslg& domain, const MeshOptions& options = {});

// The merged mesh, each piece copied into its place on `threads` threads
// (0: one per core) and released as it goes.
Mesh join(MeshPieces pieces, unsigned threads = 1);

// Every point of the mesh, in the merged numbering: join(mesh).points, read
// from the pieces on `threads` threads (what the per-point columns of a
// model file, its depths and longitudes/latitudes, are computed from).
std::vector<Point> mesh_points(const MeshPieces& mesh, unsigned threads = 1);

// The same mesh with point v at points[v] (merged numbering, one per point:
// mesh_points' size), in the decomposition and in every piece: the mesh to
// write in other coordinates (longitude/latitude). The pieces' files are
// then those of join(mesh) with its points replaced. Not a mesh of the
// domain any more (do not check it against it). Throws OptionError
// ("points") on a wrong count.
MeshPieces with_points(MeshPieces mesh, const std::vector<Point>& points, unsigned threads = 1);

// verify_mesh() of the mesh the pieces make, without joining them: each
// piece alone, on `threads` threads, then what crosses subdomains.
Verification verify_mesh(const MeshPieces& mesh, const Pslg& domain, const MeshSizeOptions& size, unsigned threads = 1);

}  // namespace madd
