#include "triangulation/boundary_loops.hpp"

#include "madd/error.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

namespace {

std::uint32_t position_of(const std::array<std::uint32_t, 3>& triangle, std::uint32_t v) {
  for (std::uint32_t k = 0; k < 3; ++k)
    if (triangle[k] == v) return k;
  throw InternalError("boundary_loops: a neighbour does not share the fan's vertex (neighbours not symmetric)");
}

// The boundary edge leaving the end vertex of boundary edge `side` (3 t + i),
// found by turning through the triangles around that vertex: in a triangle
// the edge leaving its vertex at position k is edge (k + 2) % 3.
std::uint32_t next_side(std::span<const std::array<std::uint32_t, 3>> triangles,
                        std::span<const std::array<std::uint32_t, 3>> neighbours, std::uint32_t side) {
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

}  // namespace

std::vector<BoundaryLoop> boundary_loops(std::span<const std::array<std::uint32_t, 3>> triangles,
                                         std::span<const std::array<std::uint32_t, 3>> neighbours) {
  std::vector<bool> visited(3 * triangles.size(), false);
  std::vector<BoundaryLoop> loops;
  for (std::uint32_t start = 0; start < visited.size(); ++start) {
    if (visited[start] || neighbours[start / 3][start % 3] != no_index) continue;
    BoundaryLoop loop;
    std::uint32_t side = start;
    do {
      if (visited[side]) throw InternalError("boundary_loops: a loop ran into another one");
      visited[side] = true;
      loop.vertices.push_back(triangles[side / 3][(side % 3 + 1) % 3]);
      loop.sides.push_back(side);
      side = next_side(triangles, neighbours, side);
    } while (side != start);
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace madd::detail
