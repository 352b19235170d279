#pragma once
// --weights and --areas: a background mesh of density weights or required
// areas (paper Sec. 5.2, case 2) read from a Triangle .node file.
#include <string>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::cli {

// The nodes of a .node file, value = first attribute. A value a weight
// (finite, >= 0) or a required area (finite, > 0) cannot have is bad input,
// a ParseError located at its line, as `read_areas` in a script reports it.
std::vector<ValuedPoint> read_background(const std::string& path, bool areas);

} // namespace madd::cli
