#pragma once
// From the discretised decomposition to each subdomain's own domain, and
// from the subdomain meshes back to one mesh.
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "mesh/refine.hpp"

namespace madd::detail {

// Subdomain k as a standalone domain: its ring vertices (ring by ring, in
// ring order) and its ring segments, then its interior pieces (in the order
// of Subdomain::interior_segments; their ends not on a ring as new local
// points in order of first use) and its isolated vertices, with what
// refinement and the merge need to map them back.
struct LocalDomain {
  Pslg pslg;
  std::vector<bool> splittable;          // per local segment: a boundary or interior piece (never a separator)
  std::vector<std::uint32_t> to_global;  // per local point: its point of the decomposition
  std::vector<std::uint32_t> piece;      // per local segment: its segment of the decomposition
  friend bool operator==(const LocalDomain&, const LocalDomain&) = default;
};
LocalDomain local_domain(const Decomposition& d, std::uint32_t k);

// The subdomain meshes joined into one: Steiner points numbered after the
// decomposition's points, subdomain by subdomain; triangles grouped by
// subdomain; neighbours matched across separators by their shared vertices.
// With `kept`, only the subdomains k with (*kept)[k] (the others' triangle
// ranges are empty, and only the separators of kept subdomains are listed);
// the points are still all of d's, then the kept subdomains' Steiner points.
// The subdomains are copied on `threads` threads, each into its own ranges
// (the same mesh for any count); `pieces` are moved from. assemble() then
// join() (mesh/mesh_pieces.hpp).
Mesh merge(const Decomposition& d, std::vector<SubdomainMesh>& pieces, double min_triangle_angle_deg,
           const std::vector<bool>* kept = nullptr, unsigned threads = 1);

}  // namespace madd::detail
