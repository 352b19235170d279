// The distance term's safe point values (distance_bound.hpp).
#include "sizing/distance_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

namespace {

// The radius of the smallest circle enclosing triangle abc.
double enclosing_radius(Point a, Point b, Point c) noexcept {
  const double ab = dot(b - a, b - a), bc = dot(c - b, c - b), ca = dot(a - c, a - c);
  const double longest = std::max({ab, bc, ca});
  // Right or obtuse: the longest edge's diametral circle holds the triangle.
  if (2.0 * longest >= ab + bc + ca) return 0.5 * std::sqrt(longest);
  const double area2 = std::abs(cross(b - a, c - a));
  return std::sqrt(ab * bc * ca) / (2.0 * area2);
}

}  // namespace

std::vector<double> safe_distance_values(const SizeBackground& background, std::span<const RawSample> samples,
                                         double hmin, double rate) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t n = background.points.size();
  std::vector<double> out(n, infinity);
  if (!(rate > 0.0)) return out;
  std::vector<double> deficit(n, -1.0);  // max delta_T over the point's inside triangles; -1: none
  for (std::size_t t = 0; t < background.triangles.size(); ++t) {
    if (background.inside[t] == 0) continue;
    const auto& v = background.triangles[t];
    const Point p[3] = {background.points[v[0]], background.points[v[1]], background.points[v[2]]};
    const double rho = enclosing_radius(p[0], p[1], p[2]);
    double r = 0.0;  // from the triangle to the nearest end of a coast piece, at least
    for (int i = 0; i < 3; ++i) {
      const double reach = std::max(distance(p[i], p[(i + 1) % 3]), distance(p[i], p[(i + 2) % 3]));
      r = std::max(r, samples[v[i]].vertex_distance - reach);
    }
    const double delta = r > 0.0 ? std::min(rho, rho * rho / (2.0 * r)) : rho;
    for (const std::uint32_t i : v) deficit[i] = std::max(deficit[i], delta);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (deficit[i] >= 0.0 && std::isfinite(samples[i].distance))
      out[i] = (hmin + rate * (samples[i].distance - deficit[i])) * (1.0 - 1e-9);
  return out;
}

}  // namespace madd::detail
