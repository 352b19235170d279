#pragma once
// The boundary of a set of triangles as closed loops: what a coastline's
// domain is rebuilt from (src/gis/coast_domain.cpp) and what a model file's
// boundary lists are cut from (src/output/model_boundaries.cpp), of a merged
// mesh or of one kept in pieces (read through mesh/pieces_view.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "madd/error.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// One closed loop of boundary edges, the triangles on its left: edge k runs
// from vertices[k] to vertices[k + 1] (the last back to vertices[0]) and is
// edge sides[k] % 3 of triangle sides[k] / 3. The outer boundary of a
// region runs counter-clockwise, each hole's clockwise.
struct BoundaryLoop {
  std::vector<std::uint32_t> vertices;
  std::vector<std::uint32_t> sides;
};

namespace boundary_loops_detail {

inline std::uint32_t position_of(const std::array<std::uint32_t, 3>& triangle, std::uint32_t v) {
  for (std::uint32_t k = 0; k < 3; ++k)
    if (triangle[k] == v) return k;
  throw InternalError("boundary_loops: a neighbour does not share the fan's vertex (neighbours not symmetric)");
}

// The boundary edge leaving the end vertex of boundary edge `side` (3 t + i),
// found by turning through the triangles around that vertex: in a triangle
// the edge leaving its vertex at position k is edge (k + 2) % 3.
template <typename Triangles, typename Neighbours>
std::uint32_t next_side(const Triangles& triangles, const Neighbours& neighbours, std::uint32_t side) {
  std::uint32_t t = side / 3;
  const std::uint32_t i = side % 3;
  const std::uint32_t v = triangles[t][(i + 2) % 3];
  std::uint32_t edge = (i + 1) % 3;  // leaves v in t
  for (std::size_t steps = 0; steps <= triangles.size(); ++steps) {
    const std::uint32_t across = neighbours[t][edge];
    if (across == no_index) return 3 * t + edge;
    t = across;
    edge = (position_of(triangles[t], v) + 2) % 3;
  }
  throw InternalError("boundary_loops: the fan around a boundary vertex does not end at a boundary edge");
}

}  // namespace boundary_loops_detail

// Every edge i of triangle t whose neighbours[t][i] is no_index is a
// boundary edge (triangles counter-clockwise, edge i opposite vertex i, as
// madd::Triangulation and madd::Mesh keep them). The loops are traced so
// that they never jump where two loops share a vertex (an island touching
// the coast at a point, a pinched ring): from an edge arriving at v the loop
// goes on along the boundary edge leaving v that the fan of triangles
// around v reaches first, turning from the arriving edge through the
// triangles on its left. Loops start at the lowest unvisited boundary edge
// in triangle order, so the result depends on the triangles' order only.
// Triangles and Neighbours: anything with size() and [t] giving a triangle's
// three corners and three neighbours (the vectors of a Mesh, a view of one).
// Precondition: neighbours is symmetric (a manifold set of triangles).
template <typename Triangles, typename Neighbours>
std::vector<BoundaryLoop> boundary_loops(const Triangles& triangles, const Neighbours& neighbours) {
  std::vector<bool> visited(3 * triangles.size(), false);
  std::vector<BoundaryLoop> loops;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const std::array<std::uint32_t, 3> across = neighbours[t];  // once per triangle: a view computes it
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t start = 3 * t + i;
      if (visited[start] || across[i] != no_index) continue;
      BoundaryLoop loop;
      std::uint32_t side = start;
      do {
        if (visited[side]) throw InternalError("boundary_loops: a loop ran into another one");
        visited[side] = true;
        loop.vertices.push_back(triangles[side / 3][(side % 3 + 1) % 3]);
        loop.sides.push_back(side);
        side = boundary_loops_detail::next_side(triangles, neighbours, side);
      } while (side != start);
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

}  // namespace madd::detail
