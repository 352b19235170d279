#pragma once
// Point location in a fixed triangulation, for many queries from several
// threads: a uniform grid whose every cell names a triangle near its centre
// (where a walk starts), and the core's visibility walk from there
// (triangulation/walk.hpp, walk_weighing) over a half-edge copy of the
// triangulation. The size field asks once per triangle the mesher makes and
// the --sizes samples once per query, so the walk must be short: the grid
// has about one cell per triangle. const and free of shared mutable state,
// so that any number of threads may locate at once; deterministic (the
// walk's edge order comes from a generator restarted at every query).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "triangulation/half_edge_mesh.hpp"

namespace madd::detail {

// A triangulation as Triangulation holds it: counterclockwise triangles,
// neighbours[t][i] across the edge opposite corner i (no_index on the hull),
// covering the convex hull of its points (a walk that would cross the hull
// knows p is outside).
struct TriangleView {
  std::span<const Point> points;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  std::span<const std::array<std::uint32_t, 3>> neighbours;
};

struct Location {
  std::uint32_t triangle = 0xffffffffu;  // no_index: no triangles at all
  bool inside = false;                   // p is in the triangle's closure (else outside the hull, beyond it)
  // When inside: twice the signed areas of p with each edge (the edge
  // opposite corner i): p's barycentric weights, unnormalised, which the
  // walk computed anyway.
  double weight[3] = {0.0, 0.0, 0.0};
};

// Where one caller's last walk ended: its next walk starts there when the
// two points are in the same or neighbouring cells of the grid (else from
// the grid). A mesher asks in runs of a few queries around the point it
// just inserted, where the grid's start is many triangles away near a
// graded coast; between runs it jumps. Kept by one caller on one thread;
// the result of a query does not depend on it (TriangleLocator::locate).
struct WalkHint {
  std::uint32_t triangle = 0xffffffffu;
  std::uint32_t col = 0, row = 0;  // the cell of the last query
};

class TriangleLocator {
public:
  TriangleLocator() = default;
  // Indexes `view`; the locator keeps no view of it: every query is given
  // the same triangulation again (so that the owner may move it).
  explicit TriangleLocator(const TriangleView& view);
  // The triangle holding p, the same whatever the hint: when p is on an
  // edge or a corner it is the lowest-numbered triangle whose closure holds
  // p (the interpolation and the field's exact term may differ in the last
  // bit between two triangles, and refinement and verify_mesh must read one
  // value); outside the hull, the walk from the grid decides.
  Location locate(const TriangleView& view, Point p, WalkHint* hint = nullptr) const noexcept;

private:
  Location walk(const TriangleView& view, Point p, std::uint32_t t) const noexcept;
  Location lowest_holding(const TriangleView& view, Point p, Location at) const noexcept;
  // The view's triangles and adjacency in the core's layout, for its walk
  // (a background is a few tens of thousands of triangles: the copy is small).
  HalfEdgeMesh mesh_;
  UniformGrid frame_;                 // only its cells' frame: col_of, row_of
  std::vector<std::uint32_t> start_;  // per cell (row-major): a triangle near its centre
};

// The linear interpolation over location `at` of p of per-point values
// (+infinity allowed: a corner of infinite value gives +infinity wherever
// its weight is positive). Outside the hull, the weights are clamped to the
// triangle (the value of its nearest point). NaN when `at` is no triangle.
double interpolate(const TriangleView& view, std::span<const double> values, Location at, Point p) noexcept;

}  // namespace madd::detail
