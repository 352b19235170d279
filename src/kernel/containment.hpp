#pragma once
// Exact containment of a point in a closed segment or a closed triangle
// (orient2d decides every sign; comparisons of coordinates are exact).
#include <algorithm>

#include "madd/predicates.hpp"

namespace madd::detail {

// p lies on the closed segment ab (its ends included). A degenerate segment
// (a == b) contains only a.
inline bool on_segment(Point a, Point b, Point p) noexcept {
  const bool in_box =
      std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
  return in_box && orient2d(a, b, p) == 0.0;
}

// The closed segments ab and cd share a point: they cross, touch or overlap.
inline bool closed_segments_meet(Point a, Point b, Point c, Point d) noexcept {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
    return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

// q lies inside triangle abc or on its boundary, whichever way abc turns.
// A degenerate (collinear) triangle contains every point of its line.
inline bool in_closed_triangle(Point a, Point b, Point c, Point q) noexcept {
  const double s = orient2d(a, b, c) > 0.0 ? 1.0 : -1.0;
  return s * orient2d(a, b, q) >= 0.0 && s * orient2d(b, c, q) >= 0.0 && s * orient2d(c, a, q) >= 0.0;
}

}  // namespace madd::detail
