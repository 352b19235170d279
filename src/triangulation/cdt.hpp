#pragma once
// Building triangulations in the half-edge core (triangulation/half_edge_mesh.hpp):
// the Delaunay triangulation of points, its segments inserted, and the
// constrained Delaunay triangulation of a PSLG with its outside and holes
// removed, which triangulate() exports and mesh refinement grows in place.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"
#include "triangulation/half_edge_mesh.hpp"

namespace madd::detail {

// Builds the Delaunay triangulation (with ghost triangles) of `input` into
// `mesh`. Returns false when every point is collinear (mesh left empty).
// Inserts in a sorted copy of the points for locality, then relabels.
// Throws InvalidInputError on duplicate points (naming input indices).
bool build_delaunay(HalfEdgeMesh& mesh, std::span<const Point> input);

// Inserts every segment of `pslg` into the Delaunay `mesh` (fills mesh.seg).
// Throws InvalidInputError when a segment crosses another one.
void insert_segments(HalfEdgeMesh& mesh, const Pslg& pslg);

// The constrained Delaunay triangulation triangulate(pslg, options) makes,
// still in the core: the triangles it keeps, numbered as it numbers them,
// with no ghosts, twins into what was removed no_index, and mesh.seg filled
// (its vertices index pslg.points). With `regions`, (*regions)[t] is 1 + the
// index in pslg.regions of the region whose flood holds triangle t (the later
// region where two floods meet), 0 for none. Returns false when every point
// is collinear (no triangles).
bool constrained_delaunay(HalfEdgeMesh& mesh, const Pslg& pslg, const TriangulateOptions& options,
                          std::vector<std::uint32_t>* regions = nullptr);

}  // namespace madd::detail
