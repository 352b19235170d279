#pragma once
// One subdomain's mesh checked on its own (docs/mesh.md, "Meshes in
// pieces"): verify_mesh on the subdomain as a domain of its own, every ring
// segment a boundary piece, its interior pieces, isolated vertices and
// regions its own. What a subdomain's mesh must be in the whole mesh it must
// be alone (constrained Delaunay, covering its rings exactly, conforming to
// its pieces, sizes, angles, region attributes); what crosses subdomains is
// checked from the pieces' numbering (mesh/pieces_check.hpp).
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "mesh/refine.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// The problems of subdomain k's mesh `piece` (local numbering, as
// refine_subdomain made it), each prefixed "subdomain k: "; `regions` are
// the subdomain's (subdomain_regions), or none: its region attributes and
// regional area bounds are then not checked (a mesh kept in pieces has them
// checked over the whole mesh, mesh/pieces_check.hpp).
Verification check_subdomain(const Decomposition& d, std::uint32_t k, const std::vector<Region>& regions,
                             const SubdomainMesh& piece, double min_triangle_angle_deg, const AreaBound& field);

// The same, throwing InternalError (throw_failed_check) on a problem: the
// check a worker runs on the mesh it has just made.
void verify_subdomain(const Decomposition& d, std::uint32_t k, const std::vector<Region>& regions,
                      const SubdomainMesh& piece, double min_triangle_angle_deg, const AreaBound& field);

}  // namespace madd::detail
