#pragma once
// The input's regions (Triangle's -A and -a) as each subdomain sees them
// (docs/mesh.md, "Interior constraints and regions"). A region is the face
// of the input's segments holding its point; separators cut faces into
// subdomain pieces but are no constraint of the input, so a region point in
// one subdomain may colour triangles of several. Each subdomain is meshed
// alone, so it gets its own regions: one point strictly inside each face of
// its own segments (rings and interior pieces) that lies in a region, with
// that region's attribute and area bound. Flooding those inside the
// subdomain gives every triangle the region the whole-domain flood gives it.
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// Per subdomain of the (discretised) decomposition: its regions, as above;
// all empty when d.regions is. The region of a face is decided once, on the
// constrained triangulation of every boundary and interior piece of d, by
// Triangle's rule (of two region points in one face the later wins).
// Deterministic.
std::vector<std::vector<Region>> subdomain_regions(const Decomposition& d);

} // namespace madd::detail
