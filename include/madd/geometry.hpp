#pragma once
// Plain geometric values and constructions. Signs of orientation and in-circle
// tests are never decided here: use madd/predicates.hpp for those.
#include <cmath>
#include <numbers>

namespace madd {

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

// A point with a value attached: a sample of a density weight or of a
// required area (a background mesh node, docs/grading.md).
struct ValuedPoint {
  Point at;
  double value = 0.0;
  friend bool operator==(const ValuedPoint&, const ValuedPoint&) = default;
};

inline Point operator+(Point a, Point b) noexcept { return {a.x + b.x, a.y + b.y}; }
inline Point operator-(Point a, Point b) noexcept { return {a.x - b.x, a.y - b.y}; }
inline Point operator*(double s, Point a) noexcept { return {s * a.x, s * a.y}; }
inline double dot(Point a, Point b) noexcept { return a.x * b.x + a.y * b.y; }
inline double cross(Point a, Point b) noexcept { return a.x * b.y - a.y * b.x; }
// sqrt(x^2 + y^2), not std::hypot: validate() keeps coordinates within
// [1e-40, 1e70] in magnitude, so the squares neither overflow nor lose
// their digits, and hypot's care for that cost 7-9% of a graded mesh run.
inline double length(Point a) noexcept { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double distance(Point a, Point b) noexcept { return length(b - a); }
inline Point midpoint(Point a, Point b) noexcept { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }
inline Point lerp(Point a, Point b, double t) noexcept { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

// Signed area of triangle abc: positive when counter-clockwise (floating point;
// for the exact sign use orient2d).
inline double signed_area(Point a, Point b, Point c) noexcept { return 0.5 * cross(b - a, c - a); }
inline double triangle_area(Point a, Point b, Point c) noexcept { return std::abs(signed_area(a, b, c)); }

// Centroid of triangle abc (the mean of its corners).
inline Point triangle_centroid(Point a, Point b, Point c) noexcept {
  return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
}

// Angle at vertex `apex` between rays apex->a and apex->b, in radians, in [0, pi].
inline double angle_at(Point apex, Point a, Point b) noexcept {
  const Point u = a - apex;
  const Point v = b - apex;
  return std::atan2(std::abs(cross(u, v)), dot(u, v));
}

// Circumcentre of triangle abc, computed relative to a for accuracy.
// Precondition: abc is not degenerate.
inline Point circumcentre(Point a, Point b, Point c) noexcept {
  const Point ab = b - a;
  const Point ac = c - a;
  const double d = 2.0 * cross(ab, ac);
  const double ab2 = dot(ab, ab);
  const double ac2 = dot(ac, ac);
  return {a.x + (ac.y * ab2 - ab.y * ac2) / d, a.y + (ab.x * ac2 - ac.x * ab2) / d};
}

inline constexpr double degrees(double radians) noexcept { return radians * 180.0 / std::numbers::pi; }
inline constexpr double radians(double degrees) noexcept { return degrees * std::numbers::pi / 180.0; }

}  // namespace madd
