#pragma once
// The distance from a point to a segment, written once.
#include <algorithm>
#include <cmath>

#include "madd/geometry.hpp"

namespace madd::detail {

// The distance from p to segment ab, and the parameter t in [0, 1] of its
// nearest point a + t (b - a) (the square root of a sum of squares:
// std::hypot's care for overflow is not needed within the coordinate range
// validate allows, and costs as much as the rest of the test). A segment of
// length 0 is its point.
inline double segment_distance(Point p, Point a, Point b, double& t) noexcept {
  const Point ab = b - a, ap = p - a;
  const double len2 = dot(ab, ab);
  t = len2 > 0.0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  const Point q = ap - t * ab;
  return std::sqrt(dot(q, q));
}

inline double segment_distance(Point p, Point a, Point b) noexcept {
  double t = 0.0;
  return segment_distance(p, a, b, t);
}

}  // namespace madd::detail
