#pragma once
// The size bound of a mesh at a point: the one function the mesher refines
// to and verify_mesh checks against (and madd::area_bound_at answers with),
// so that the two cannot disagree. The background samples are indexed once
// (sizing/nearest_sample.hpp) for the many queries.

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "sizing/nearest_sample.hpp"

namespace madd::detail {

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
