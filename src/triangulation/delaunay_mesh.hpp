#pragma once
// Internal working representation of the triangulator: flat triangle arrays
// with half-edge adjacency, plus "ghost" triangles that close the convex hull
// through one virtual vertex, so hull handling needs no special cases.
//
// Half-edge h = 3*t + i is edge i of triangle t, the edge opposite corner i,
// directed counter-clockwise in t: from tv[3t+(i+1)%3] to tv[3t+(i+2)%3].
// tn[h] is the twin half-edge (the same edge seen from the neighbour).
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

inline std::uint32_t next_edge(std::uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
inline std::uint32_t prev_edge(std::uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }

// Vertices are input indices, so the mesh holds no copy of the points: every
// user passes the input's points alongside it.
struct Mesh {
  std::uint32_t ghost = 0;           // the virtual vertex: index points.size()
  std::vector<std::uint32_t> tv;     // 3 vertex ids per triangle
  std::vector<std::uint32_t> tn;     // twin half-edge per half-edge
  std::vector<std::uint32_t> seg;    // per half-edge: input segment or no_index (CDT only)

  std::uint32_t triangle_count() const noexcept { return static_cast<std::uint32_t>(tv.size() / 3); }
  std::uint32_t origin(std::uint32_t h) const noexcept { return tv[next_edge(h)]; }
  std::uint32_t dest(std::uint32_t h) const noexcept { return tv[prev_edge(h)]; }
  bool is_ghost(std::uint32_t t) const noexcept {
    return tv[3 * t] == ghost || tv[3 * t + 1] == ghost || tv[3 * t + 2] == ghost;
  }
  void link(std::uint32_t a, std::uint32_t b) noexcept {
    tn[a] = b;
    tn[b] = a;
  }
};

// Builds the Delaunay triangulation (with ghost triangles) of `input` into
// `mesh`. Returns false when every point is collinear (mesh left empty).
// Inserts in a sorted copy of the points for locality, then relabels.
// Throws InvalidInputError on duplicate points (naming input indices).
bool build_delaunay(Mesh& mesh, std::span<const Point> input);

// Inserts every segment of `pslg` into the Delaunay `mesh` (fills mesh.seg).
// Throws InvalidInputError when a segment crosses another one.
void insert_segments(Mesh& mesh, const Pslg& pslg);

// A triangle containing p in its closure found by a stochastic visibility walk
// from `start`, or a ghost triangle when p lies outside the convex hull.
std::uint32_t walk_to(const Mesh& mesh, std::span<const Point> points, Point p, std::uint32_t start);

} // namespace madd::detail
