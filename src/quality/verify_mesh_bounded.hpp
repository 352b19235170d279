#pragma once
// verify_mesh with a size bound built already: mesh() and the distributed
// driver check against the very AreaBound they refined to (one size field,
// built once per run), not a second one built from the options.
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// madd::verify_mesh(mesh, domain, bound.options()), reading sizes from
// `bound`; the per-triangle checks (size, angles) on `threads` threads (0:
// one per core), the same report for any count.
Verification verify_mesh(const Mesh& mesh, const Pslg& domain, const AreaBound& bound, unsigned threads = 1);

}  // namespace madd::detail
