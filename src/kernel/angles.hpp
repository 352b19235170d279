#pragma once
// Angles between directions, with the turn decided exactly.
#include "madd/geometry.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

// The counter-clockwise angle in degrees, in [0, 360), that turns direction
// o -> from into direction o -> to. Its size comes from angle_at (floating
// point); whether it passes 180 is decided by orient2d, so a reflex corner is
// never mistaken for a convex one.
inline double ccw_angle_deg(Point o, Point from, Point to) noexcept {
  const double base = degrees(angle_at(o, from, to));
  return orient2d(o, from, to) < 0.0 ? 360.0 - base : base;
}

} // namespace madd::detail
