#pragma once
// Axis-aligned bounding boxes.
#include <algorithm>
#include <limits>

#include "madd/geometry.hpp"

namespace madd::detail {

// Starts empty (lo above hi), so that the first add() sets both corners.
struct Box {
  Point lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void add(Point p) noexcept {
    lo = Point{std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = Point{std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  double width() const noexcept { return hi.x - lo.x; }
  double height() const noexcept { return hi.y - lo.y; }
  // In the closed box.
  bool contains(Point p) const noexcept { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

// The smallest box holding every point of `points` (any range of Point).
template <class Points>
Box bounding_box(const Points& points) noexcept {
  Box box;
  for (const Point p : points) box.add(p);
  return box;
}

}  // namespace madd::detail
