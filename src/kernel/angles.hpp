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

// How far an angle computed as angle_at / ccw_angle_deg does (in degrees) can
// be from the exact angle of the same double points, whatever their scale
// (u = 2^-53, docs/quality.md "Angle checks"):
// - each difference p - o is correctly rounded, component by component, so
//   each direction turns by at most sqrt(2) u: 2 sqrt(2) u for the two;
// - cross and dot of the rounded vectors are two products and a sum, each
//   off by at most gamma_2 (|x1 y2| + |x2 y1|) <= sqrt(2) gamma_2 |u| |v|
//   (gamma_2 = 2u / (1 - 2u)), which moves atan2(|cross|, dot) by at most
//   their sum over |u| |v|: 2 sqrt(2) gamma_2;
// - atan2 itself (within 1 ulp of pi in glibc), the conversion to degrees
//   and 360 - angle add a few ulps of 360.
// That is below 2e-15 rad + 4 ulp(360) < 2e-13 degrees; the bound below is
// five times that. It holds while no difference underflows, which the
// supported coordinate range guarantees (docs/hostile.md).
inline constexpr double angle_rounding_bound_deg = 1e-12;

}  // namespace madd::detail
