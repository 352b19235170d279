#pragma once
// Which G_D vertices of one split hold a point: a uniform bucket grid of the
// vertices' bounding boxes, then exact containment. Used for the weight
// samples of graded runs (Sec. 5.2) and for the isolated points of a face,
// which are not triangulation vertices (docs/algorithm.md, "Interior segments").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/box.hpp"
#include "kernel/containment.hpp"
#include "madd/medial.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

class GdLocator {
public:
  GdLocator(const MedialGraph& g, const Triangulation& tri) : g_(g), tri_(tri) {
    const std::size_t n = g.vertex_triangle.size();
    const Box all = bounding_box(tri.points);
    lo_ = all.lo;
    cells_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(n)), 1.0, 512.0));
    cw_ = std::max(all.width() / cells_, 1e-300);
    ch_ = std::max(all.height() / cells_, 1e-300);
    bucket_.resize(static_cast<std::size_t>(cells_) * cells_);
    for (std::uint32_t v = 0; v < n; ++v) {
      const Box box = bounding_box(vertex_triangle_corners(g, tri, v));
      for (std::uint32_t i = cell(box.lo.x, lo_.x, cw_); i <= cell(box.hi.x, lo_.x, cw_); ++i)
        for (std::uint32_t j = cell(box.lo.y, lo_.y, ch_); j <= cell(box.hi.y, lo_.y, ch_); ++j)
          bucket_[i * cells_ + j].push_back(v);
    }
  }

  // Calls f(v) for every G_D vertex v whose closed (sub-)triangle holds p, in
  // ascending order; stops early when f returns false.
  template <class F>
  void for_each_containing(Point p, F&& f) const {
    for (const std::uint32_t v : bucket_[cell(p.x, lo_.x, cw_) * cells_ + cell(p.y, lo_.y, ch_)]) {
      const auto c = vertex_triangle_corners(g_, tri_, v);
      if (in_closed_triangle(c[0], c[1], c[2], p) && !f(v)) return;
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
  std::uint32_t cell(double x, double origin, double size) const {
    return static_cast<std::uint32_t>(std::clamp(std::floor((x - origin) / size), 0.0, cells_ - 1.0));
  }

  const MedialGraph& g_;
  const Triangulation& tri_;
  Point lo_;
  std::uint32_t cells_ = 1;
  double cw_ = 1.0, ch_ = 1.0;
  std::vector<std::vector<std::uint32_t>> bucket_;
};

} // namespace madd::detail
