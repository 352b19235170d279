#pragma once
// Which G_D vertices of one split hold a point: a uniform grid of the
// vertices' bounding boxes, then exact containment. Used for the weight
// samples of graded runs (Sec. 5.2) and for the isolated points of a face,
// which are not triangulation vertices (docs/algorithm.md, "Interior segments").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/box.hpp"
#include "kernel/containment.hpp"
#include "kernel/uniform_grid.hpp"
#include "madd/medial.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

class GdLocator {
public:
  GdLocator(const MedialGraph& g, const Triangulation& tri) : g_(g), tri_(tri) {
    const auto n = static_cast<std::uint32_t>(g.vertex_triangle.size());
    const Box all = bounding_box(tri.points);
    const auto cells = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(n)), 1.0, 512.0));
    grid_ = UniformGrid(all.lo, std::max(all.width() / cells, 1e-300), std::max(all.height() / cells, 1e-300), cells,
                        cells);
    std::vector<Box> boxes(n);
    for (std::uint32_t v = 0; v < n; ++v) boxes[v] = bounding_box(vertex_triangle_corners(g, tri, v));
    grid_.fill(n, UniformGrid::Index::by_cell,
               [&](std::uint32_t v, auto&& add) { grid_.box_cells(boxes[v].lo, boxes[v].hi, add); });
  }

  // Calls f(v) for every G_D vertex v whose closed (sub-)triangle holds p, in
  // ascending order; stops early when f returns false.
  template <class F>
  void for_each_containing(Point p, F&& f) const {
    for (const UniformGrid::Entry& e : grid_.cell_at(p)) {
      const auto c = vertex_triangle_corners(g_, tri_, e.item);
      if (in_closed_triangle(c[0], c[1], c[2], p) && !f(e.item)) return;
    }
  }

  // Every G_D vertex holding p (two or more when p lies on a partial separator).
  std::vector<std::uint32_t> containing(Point p) const {
    std::vector<std::uint32_t> out;
    for_each_containing(p, [&](std::uint32_t v) {
      out.push_back(v);
      return true;
    });
    return out;
  }

private:
  const MedialGraph& g_;
  const Triangulation& tri_;
  UniformGrid grid_;  // items are G_D vertices, listed in the cells of their triangle's bounding box
};

}  // namespace madd::detail
