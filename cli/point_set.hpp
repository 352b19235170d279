#pragma once
// Point sets (a .node, or a .poly without segments and holes): what
// `madd triangulate` and `madd check` do with them, in one place.
#include <string>

#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::cli {

// The Delaunay triangulation of a point set, covering its convex hull. Points
// that have no triangle at all (fewer than three, or all on one line) are bad
// input (InvalidInputError naming the file).
Triangulation triangulate_points(const Pslg& points, const std::string& path);

}  // namespace madd::cli
