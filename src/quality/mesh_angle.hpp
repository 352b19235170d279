#pragma once
// The smallest angle of a mesh triangle, measured one way for everyone who
// counts triangles below the angle bound (verify_mesh, and the mesher's
// shortfall count, which must agree with it).
#include "madd/geometry.hpp"

namespace madd::detail {

// A triangle is below the bound `min_triangle_angle_deg` when its smallest angle is
// below min_triangle_angle_deg - mesh_angle_slack_deg. The slack is far above the
// rounding of the measure (angle_rounding_bound_deg, src/kernel/angles.hpp,
// 1e-12 degrees), so a triangle the mesher refined to the bound by any
// reasonable measure of its own is never counted, and far below anything a
// user could ask for.
inline constexpr double mesh_angle_slack_deg = 1e-9;

// The smallest angle of triangle abc in degrees: the angle opposite its
// shortest edge (by squared lengths in doubles), as atan2(|cross|, dot) of
// the two edges there (angle_at). Picking the corner by rounded lengths
// cannot matter: two edges within rounding of each other in length face
// angles within ~1e-15 rad of each other (law of sines).
inline double smallest_angle_deg(Point a, Point b, Point c) noexcept {
  const Point ab = b - a, bc = c - b, ca = a - c;
  const double lab = dot(ab, ab), lbc = dot(bc, bc), lca = dot(ca, ca);
  if (lab <= lbc && lab <= lca) return degrees(angle_at(c, a, b));  // ab is shortest
  if (lbc <= lca) return degrees(angle_at(a, b, c));
  return degrees(angle_at(b, c, a));
}

}  // namespace madd::detail
