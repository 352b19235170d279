#pragma once
// The subdomain meshes as refinement made them, numbered as the merged mesh
// would number them but never copied into it (issue 27: the files are
// written and the mesh checked from these, so the whole mesh is never held
// twice). merge() is assemble() then join().
#include <cstdint>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "mesh/merge.hpp"
#include "mesh/refine.hpp"

namespace madd::detail {

struct MeshPiecesData {
  Decomposition decomposition;        // discretised; its points are the mesh's first points
  std::vector<SubdomainMesh> pieces;  // per subdomain, in its own numbering (empty when not kept)
  std::vector<LocalDomain> local;     // per subdomain: its local points' and segments' global ids
  // Per subdomain k (N + 1 entries): the global id of its first Steiner
  // point, and of its first triangle (Mesh::subdomain_first_triangle).
  std::vector<std::uint32_t> first_point, first_triangle;
  std::vector<int> point_markers;     // of the decomposition's points (Mesh::point_markers' first entries)
  std::vector<MeshSegment> segments;  // as Mesh::segments
  // Per subdomain: (3 t + i, u) for each edge i of its triangle t (local)
  // on a separator whose other side is global triangle u, sorted.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> across;
  MeshShortfall shortfall;
  double min_triangle_angle_deg = 30.0;
  friend bool operator==(const MeshPiecesData&, const MeshPiecesData&) = default;

  std::uint32_t subdomain_count() const noexcept { return static_cast<std::uint32_t>(pieces.size()); }
  std::uint32_t point_count() const noexcept { return first_point.empty() ? 0 : first_point.back(); }
  std::uint32_t triangle_count() const noexcept { return first_triangle.empty() ? 0 : first_triangle.back(); }
  bool has_regions() const noexcept { return !decomposition.regions.empty(); }
  // The subdomain holding global triangle t (< triangle_count()), and the
  // subdomain whose Steiner point global v is (decomposition.points.size()
  // <= v < point_count()).
  std::uint32_t subdomain_of_triangle(std::uint32_t t) const;
  std::uint32_t subdomain_of_point(std::uint32_t v) const;
  // Subdomain k's local vertex v, and its local triangle t's neighbour
  // across edge i, in the merged mesh's numbering.
  std::uint32_t global_point(std::uint32_t k, std::uint32_t v) const {
    const std::size_t own = local[k].to_global.size();
    return v < own ? local[k].to_global[v] : first_point[k] + static_cast<std::uint32_t>(v - own);
  }
  std::uint32_t global_neighbour(std::uint32_t k, std::uint32_t t, std::uint32_t i) const;
  // The marker of global point v (Mesh::point_markers[v]).
  int point_marker(std::uint32_t v) const;
  // Subdomain k's Steiner point v's marker: its segment's, 0 inside.
  int steiner_marker(std::uint32_t k, std::uint32_t v) const {
    const std::uint32_t s = pieces[k].point_segment[v];
    return s == no_index ? 0 : local[k].pslg.segments[s].marker;
  }
};

// The pieces of `d`'s subdomains, numbered: Steiner points after d's points,
// subdomain by subdomain; triangles grouped by subdomain; the mesh segments;
// the links across separators. With `kept`, only the subdomains k with
// (*kept)[k] (as merge()). The per-subdomain steps run on `threads` threads.
MeshPiecesData assemble(Decomposition d, std::vector<SubdomainMesh>&& pieces, double min_triangle_angle_deg,
                        const std::vector<bool>* kept = nullptr, unsigned threads = 1);

// The merged mesh: every piece copied into its place, on `threads` threads
// (each piece released once copied).
Mesh join(MeshPiecesData&& data, unsigned threads = 1);

}  // namespace madd::detail
