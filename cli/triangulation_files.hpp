#pragma once
// Triangle's files of a triangulation (`madd triangulate`, and the Python
// module's Triangulation.write): PREFIX.node, .ele, .neigh and .edge, ids
// from the PSLG's first index, markers as Triangle gives them (constrained
// edges their segment's marker, other edges 0, hull edges 1 for points;
// vertices a nonzero input marker, else a segment's through them, else 1 on
// the boundary).
#include <string>

#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::cli {

std::string triangulation_node_text(const Pslg& pslg, const Triangulation& tri);
// With region attributes (tri.attributes), one column of them.
std::string triangulation_ele_text(const Pslg& pslg, const Triangulation& tri);
std::string triangulation_neigh_text(const Pslg& pslg, const Triangulation& tri);
// Each edge once: from the triangle with the smaller index, or the only one.
std::string triangulation_edge_text(const Pslg& pslg, const Triangulation& tri);

}  // namespace madd::cli
