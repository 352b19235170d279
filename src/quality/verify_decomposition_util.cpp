// Small helpers of verify_decomposition(): exact point location in a ring,
// number formatting, the capped problem log.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "madd/predicates.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

namespace {

bool in_box(Point a, Point b, Point p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

} // namespace

int locate_in_ring(const std::vector<Point>& points, const std::vector<std::uint32_t>& ring, Point p) {
  int winding = 0;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point u = points[ring[k]];
    const Point v = points[ring[(k + 1) % n]];
    if (in_box(u, v, p) && orient2d(u, v, p) == 0.0) return 0;
    if (u.y <= p.y) {
      if (v.y > p.y && orient2d(u, v, p) > 0.0) ++winding;
    } else if (v.y <= p.y && orient2d(u, v, p) < 0.0) {
      --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

std::string point_text(Point p) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g)", p.x, p.y);
  return buffer;
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

void ProblemLog::add(std::string problem) {
  if (count_++ < cap_) out_.add(std::move(problem));
}

void ProblemLog::finish() {
  if (count_ > cap_) out_.add("... and " + std::to_string(count_ - cap_) + " more problems");
}

} // namespace madd::detail
