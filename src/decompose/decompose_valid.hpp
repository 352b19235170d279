#pragma once
// decompose_with_report for a caller that has validated the domain already
// (mesh(): the size field is built on the valid domain before the
// decomposition it weighs, and the domain is validated once).
#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// decompose_with_report(domain, options) without validate(domain): `domain`
// must be one validate() accepted.
DecomposeRun decompose_valid(const Pslg& domain, const DecomposeOptions& options);

}  // namespace madd::detail
