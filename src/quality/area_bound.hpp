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
#include "madd/pslg.hpp"
#include "sizing/sample_interpolant.hpp"
#include "sizing/size_field.hpp"

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
// smallest of max_triangle_area, the area function there, the samples' value
// there (linear or nearest, MeshSizeOptions::sample_interpolation), the
// equilateral triangle of side max_edge_length, and the size field's
// (sizing/size_field.hpp: distance, feature size, gradation), each when set
// and > 0 (+infinity when none is). Built once per run and shared by the
// decomposition's work estimate, the decoupling, refinement and verify_mesh.
// Keeps a reference to `size`, which must outlive it.
class AreaBound {
public:
  // The field terms need the domain (a valid one): without it they throw
  // OptionError.
  explicit AreaBound(const MeshSizeOptions& size, const Pslg* domain = nullptr);
  double area_at(Point p) const;
  bool bounded() const noexcept { return size_.has_size_bound(); }
  // No bound varies over the domain: area_at is one value everywhere.
  bool uniform() const noexcept;
  const MeshSizeOptions& options() const noexcept { return size_; }
  // The size field (empty when no field term is set).
  const SizeField& field() const noexcept { return field_; }

private:
  const MeshSizeOptions& size_;
  double constant_;  // the smallest of max_triangle_area and hmax's area (+infinity: neither)
  NearestSample nearest_;
  SampleInterpolant linear_;
  SizeField field_;
};

}  // namespace madd::detail
