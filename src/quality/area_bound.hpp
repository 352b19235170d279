#pragma once
// The size bound of a mesh at a point: the one function the mesher refines
// to and verify_mesh checks against (and madd::area_bound_at answers with),
// so that the two cannot disagree. The background samples are indexed once
// for many queries: both ask for every triangle, and a scan of 1e5 samples
// per triangle would dominate both.
#include <cstdint>
#include <span>

#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "madd/mesh.hpp"

namespace madd::detail {

// The sample nearest to p, as area_bound_at defines it: the smallest squared
// distance (p.x - s.x)^2 + (p.y - s.y)^2 as computed in doubles, ties to the
// lowest index. Samples with a non-finite coordinate are never nearest.
// Found in a uniform grid of square cells holding about one sample each: a
// query visits rings of cells around p until no unvisited cell can hold a
// sample as near as the best so far.
class NearestSample {
public:
  explicit NearestSample(std::span<const ValuedPoint> samples);
  // no_index when there is none (no finite sample, or p not finite).
  std::uint32_t nearest(Point p) const noexcept;

private:
  std::span<const ValuedPoint> samples_;
  UniformGrid grid_;  // items are sample indices
};

// The largest allowed triangle area at a point for one MeshSizeOptions: the
// smallest of max_area, the area function there and the value of the
// nearest background sample, each when set and > 0 (+infinity when none
// is). Keeps a reference to `size`, which must outlive it.
class AreaBound {
public:
  explicit AreaBound(const MeshSizeOptions& size);
  double area_at(Point p) const;
  bool bounded() const noexcept { return size_.has_size_bound(); }
  const MeshSizeOptions& options() const noexcept { return size_; }

private:
  const MeshSizeOptions& size_;
  NearestSample background_;
};

}  // namespace madd::detail
