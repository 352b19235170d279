// The local projection of a lon/lat coastline, and a depth read through it
// (include/madd/coast.hpp).
#include <cmath>

#include "madd/coast.hpp"

namespace madd {

Point Projection::to_metres(Point lonlat) const noexcept {
  if (!geographic) return lonlat;
  const double scale = earth_radius_m * std::numbers::pi / 180.0;
  return {scale * std::cos(radians(lat0_deg)) * (lonlat.x - lon0_deg), scale * (lonlat.y - lat0_deg)};
}

Point Projection::to_lonlat(Point xy) const noexcept {
  if (!geographic) return xy;
  const double scale = earth_radius_m * std::numbers::pi / 180.0;
  return {lon0_deg + xy.x / (scale * std::cos(radians(lat0_deg))), lat0_deg + xy.y / scale};
}

Point Projection::gradient_to_metres(Point per_unit) const noexcept {
  if (!geographic) return per_unit;
  // d/dx = d/dlon dlon/dx, dlon/dx = 1 / (scale cos lat0); likewise for y.
  const double scale = earth_radius_m * std::numbers::pi / 180.0;
  return {per_unit.x / (scale * std::cos(radians(lat0_deg))), per_unit.y / scale};
}

void set_depth(MeshSizeOptions& size, const DepthField& depth, const Projection& projection) {
  size.depth = [depth, projection](double x, double y) { return depth.depth_at(projection.to_lonlat({x, y})); };
  size.depth_gradient = [depth, projection](double x, double y) {
    return projection.gradient_to_metres(depth.gradient_at(projection.to_lonlat({x, y})));
  };
}

}  // namespace madd
