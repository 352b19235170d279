// The distance term's safe point values (distance_bound.hpp).
#include "sizing/distance_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace madd::detail {

namespace {

// The smallest circle enclosing triangle abc: its centre and radius.
std::pair<Point, double> enclosing_circle(Point a, Point b, Point c) noexcept {
  const double ab = dot(b - a, b - a), bc = dot(c - b, c - b), ca = dot(a - c, a - c);
  // Right or obtuse: the longest edge's diametral circle holds the triangle.
  if (2.0 * ab >= ab + bc + ca) return {midpoint(a, b), 0.5 * std::sqrt(ab)};
  if (2.0 * bc >= ab + bc + ca) return {midpoint(b, c), 0.5 * std::sqrt(bc)};
  if (2.0 * ca >= ab + bc + ca) return {midpoint(c, a), 0.5 * std::sqrt(ca)};
  const double area2 = std::abs(cross(b - a, c - a));
  return {circumcentre(a, b, c), std::sqrt(ab * bc * ca) / (2.0 * area2)};
}

}  // namespace

TriangleBound triangle_bound(const SizeBackground& background, std::span<const RawSample> samples, std::uint32_t t) {
  const auto& v = background.triangles[t];
  const Point p[3] = {background.points[v[0]], background.points[v[1]], background.points[v[2]]};
  const auto [centre, rho] = enclosing_circle(p[0], p[1], p[2]);
  double r = 0.0;  // from the triangle to the nearest end of a coast piece, at least
  for (int i = 0; i < 3; ++i) {
    const double reach = std::max(distance(p[i], p[(i + 1) % 3]), distance(p[i], p[(i + 2) % 3]));
    r = std::max(r, samples[v[i]].vertex_distance - reach);
  }
  return {r > 0.0 ? std::min(rho, rho * rho / (2.0 * r)) : rho, centre, rho};
}

std::vector<double> safe_distance_values(const SizeBackground& background, std::span<const RawSample> samples,
                                         double hmin, double rate, const std::vector<bool>& exact) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const std::size_t n = background.points.size();
  std::vector<double> out(n, infinity);
  if (!(rate > 0.0)) return out;
  std::vector<double> deficit(n, -1.0);  // max delta_T over the point's inside triangles; -1: none
  for (std::uint32_t t = 0; t < background.triangles.size(); ++t) {
    if (background.inside[t] == 0) continue;
    const double delta = !exact.empty() && exact[t] ? 0.0 : triangle_bound(background, samples, t).delta;
    for (const std::uint32_t i : background.triangles[t]) deficit[i] = std::max(deficit[i], delta);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (deficit[i] >= 0.0 && std::isfinite(samples[i].distance))
      out[i] = (hmin + rate * (samples[i].distance - deficit[i])) * (1.0 - 1e-9);
  return out;
}

}  // namespace madd::detail
