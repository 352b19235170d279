#pragma once
// A brute-force reference for triangulation tests: the number of points on
// the boundary of the convex hull (collinear ones included), by Andrew's
// monotone chain with exact orientation.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/predicates.hpp"

namespace madd::test {

inline std::size_t hull_point_count(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Point> h;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.size();
    for (const Point& p : pts) {
      while (h.size() >= base + 2 && orient2d(h[h.size() - 2], h.back(), p) < 0) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();
    std::reverse(pts.begin(), pts.end());
  }
  return h.size();
}

}  // namespace madd::test
