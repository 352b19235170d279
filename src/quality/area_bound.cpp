// The size bound at a point: max_triangle_area, the area function and the nearest
// background sample, the smallest of those that are set (area_bound.hpp).
#include "quality/area_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd {

namespace detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

AreaBound::AreaBound(const MeshSizeOptions& size) : size_(size), background_(size.triangle_area_samples) {}

double AreaBound::area_at(Point p) const {
  double bound = size_.max_triangle_area > 0.0 ? size_.max_triangle_area : infinity;
  if (size_.triangle_area_function) {
    const double v = size_.triangle_area_function(p.x, p.y);
    if (v > 0.0) bound = std::min(bound, v);  // false for NaN too: ignored
  }
  if (size_.triangle_area_samples.empty()) return bound;
  // A sample's value is read like the function's: <= 0 or NaN is no bound.
  const std::uint32_t nearest = background_.nearest(p);
  if (nearest != no_index && size_.triangle_area_samples[nearest].value > 0.0)
    bound = std::min(bound, size_.triangle_area_samples[nearest].value);
  return bound;
}

}  // namespace detail

// The same code as the mesher's and verify_mesh's bound (a grid built for
// one query: O(samples), like a scan). For many queries with the same
// options the library builds a detail::AreaBound once.
double area_bound_at(const MeshSizeOptions& size, Point p) { return detail::AreaBound(size).area_at(p); }

}  // namespace madd
