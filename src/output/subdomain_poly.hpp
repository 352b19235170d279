#pragma once
// Output 2's file of one subdomain, given the decomposition's faces computed
// once for all files (output/faces.hpp): add_split writes N files and must
// not triangulate the whole decomposition N times.
#include <cstdint>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "output/faces.hpp"

namespace madd::detail {

// format_subdomain_poly(d, k) with `faces` = decomposition_faces(d); when the
// decomposition has no regions, `faces` is not read and may be empty.
std::string format_subdomain_poly(const Decomposition& d, std::uint32_t k, const std::vector<DecompositionFace>& faces);

}  // namespace madd::detail
