#pragma once
// The boundary of a set of triangles as closed loops: what a coastline's
// domain is rebuilt from (src/gis/coast_domain.cpp) and what a model file's
// boundary lists are cut from (src/output/model_boundaries.cpp).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace madd::detail {

// One closed loop of boundary edges, the triangles on its left: edge k runs
// from vertices[k] to vertices[k + 1] (the last back to vertices[0]) and is
// edge sides[k] % 3 of triangle sides[k] / 3. The outer boundary of a
// region runs counter-clockwise, each hole's clockwise.
struct BoundaryLoop {
  std::vector<std::uint32_t> vertices;
  std::vector<std::uint32_t> sides;
};

// Every edge i of triangle t whose neighbours[t][i] is no_index is a
// boundary edge (triangles counter-clockwise, edge i opposite vertex i, as
// madd::Triangulation and madd::Mesh keep them). The loops are traced so
// that they never jump where two loops share a vertex (an island touching
// the coast at a point, a pinched ring): from an edge arriving at v the loop
// goes on along the boundary edge leaving v that the fan of triangles
// around v reaches first, turning from the arriving edge through the
// triangles on its left. Loops start at the lowest unvisited boundary edge
// in triangle order, so the result depends on the triangles' order only.
// Precondition: neighbours is symmetric (a manifold set of triangles).
std::vector<BoundaryLoop> boundary_loops(std::span<const std::array<std::uint32_t, 3>> triangles,
                                         std::span<const std::array<std::uint32_t, 3>> neighbours);

}  // namespace madd::detail
