#pragma once
// The decoupling step, with the choice madd::discretise does not offer.
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "kernel/resource_limits.hpp"
#include "mesh/subdomain_regions.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// madd::discretise when boundary_by_features is true. When false, boundary
// and interior pieces (both in one subdomain only) resolve only the size
// bound and the separators near them (half
// their distance to the nearest separator): our refinement splits them where
// a point encroaches them (they are in one subdomain, so that keeps the mesh
// conforming), as Ruppert's algorithm does, instead of splitting them ahead
// to the local feature size everywhere, which makes coarse meshes several
// times finer than they need be near the boundary. Separators always follow
// the size bound and every feature.
// `guard`, when given, is checked as the split points pile up (a size bound
// far below the segments' lengths asks for millions of points a segment:
// the time and memory limits must stop that, as they stop refinement).
// The segments are split on `threads` threads (0: one per core); the result
// is the same for any number. `view`, when given, is
// region_view(decomposition) (the caller's, found once per run).
Decomposition discretise(const Decomposition& decomposition, const AreaBound& size, bool boundary_by_features,
                         const ResourceGuard* guard = nullptr, unsigned threads = 1, const RegionView* view = nullptr);

// Rounds of separator splitting after meshing, at most (docs/mesh.md, "Decoupling").
inline constexpr int max_separator_rounds = 10;

// Splits each separator segment in `pieces` at its midpoint (computed from
// its ends in index order, like every split point), in `d` and in both rings
// that use it. Returns the subdomains that changed, sorted.
std::vector<std::uint32_t> split_separator_pieces(Decomposition& d, const std::vector<std::uint32_t>& pieces);

}  // namespace madd::detail
