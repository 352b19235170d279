#pragma once
// The size bound of a mesh at a point (madd::area_bound_at), with the
// background samples indexed once for many queries: verify_mesh and the
// mesher ask it for every triangle, and a scan of 1e5 samples per triangle
// would dominate both.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"

namespace madd::detail {

// The sample nearest to p, as area_bound_at defines it: the smallest
// squared distance (p.x - s.x)^2 + (p.y - s.y)^2 as computed in doubles, ties
// to the lowest index. Samples with a non-finite coordinate are never
// nearest. no_index when there is none (no samples, or p not finite).
std::uint32_t nearest_sample_by_scan(std::span<const ValuedPoint> samples, Point p) noexcept;

// The same answer as nearest_sample_by_scan, from a uniform grid of square
// cells holding about one sample each: a query visits rings of cells around
// p until no unvisited cell can hold a sample as near as the best so far.
class NearestSample {
public:
  explicit NearestSample(std::span<const ValuedPoint> samples);
  std::uint32_t nearest(Point p) const noexcept;

private:
  void visit_cell(std::uint32_t col, std::uint32_t row, Point p, double& best, std::uint32_t& best_index) const noexcept;

  std::span<const ValuedPoint> samples_;
  double x0_ = 0.0, y0_ = 0.0, cell_ = 1.0, inv_cell_ = 1.0;
  double slack_ = 0.0;  // absolute margin on the distance to a cell side, above its rounding
  std::uint32_t cols_ = 0, rows_ = 0;
  std::vector<std::uint32_t> start_;  // per cell (row-major), cols * rows + 1 offsets into items_
  std::vector<std::uint32_t> items_;  // sample indices, increasing within a cell
};

// area_bound_at for many points of one MeshSizeOptions: the background
// samples indexed once. Keeps references to `size`, which must outlive it.
class AreaBound {
public:
  explicit AreaBound(const MeshSizeOptions& size);
  // Bit-identical to area_bound_at(size, p).
  double at(Point p) const;

private:
  const MeshSizeOptions& size_;
  NearestSample background_;
};

// The bound from the three sources, given the nearest background sample
// (no_index for none): what area_bound_at and AreaBound::at both return.
double combine_area_bounds(const MeshSizeOptions& size, Point p, std::uint32_t nearest);

} // namespace madd::detail
