#pragma once
// verify_mesh for a mesh kept in pieces (docs/mesh.md, "Meshes in pieces"):
// every subdomain's mesh checked alone (mesh/subdomain_check.hpp), by the
// thread that made it or here, then what crosses subdomains, from the
// numbering the files are written with: the placement of each piece, every
// separator matched edge for edge by its two subdomains and linked both
// ways, the mesh segments along the decomposition and the input (markers,
// chains, how far the rounded boundary vertices stray), the cover of the
// whole domain by the exact area of the pieces' free edges, and the regions
// flooded over the whole mesh across the separators. Together these are what
// verify_mesh checks on the merged mesh.
#include <vector>

#include "madd/error.hpp"
#include "madd/pslg.hpp"
#include "mesh/mesh_pieces.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// The problems of `m` as one mesh of `domain`. With pieces_checked, every
// piece has passed check_subdomain already (on its worker, without regions)
// and only what crosses subdomains is checked. The pieces and the parts of the crossing checks on `threads`
// threads, the same report for any count. Never throws.
Verification verify_pieces(const MeshPiecesData& m, const Pslg& domain, const AreaBound& field, bool pieces_checked,
                           unsigned threads = 1);

}  // namespace madd::detail
