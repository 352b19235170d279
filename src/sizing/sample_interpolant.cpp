// The --sizes samples read linearly or by the nearest sample
// (sample_interpolant.hpp).
#include "sizing/sample_interpolant.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

double as_bound(double value) noexcept { return value > 0.0 ? value : infinity; }  // NaN: no bound

}  // namespace

SampleInterpolant::SampleInterpolant(std::span<const ValuedPoint> samples, MeshSizeOptions::SampleInterpolation how)
    : samples_(samples), nearest_(samples), linear_(how == MeshSizeOptions::SampleInterpolation::linear) {
  if (!linear_) return;
  // The finite samples by position, the first of equal ones kept.
  std::vector<std::uint32_t> order;
  for (std::uint32_t i = 0; i < samples.size(); ++i)
    if (std::isfinite(samples[i].at.x) && std::isfinite(samples[i].at.y)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Point p = samples[a].at, q = samples[b].at;
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::uint32_t a, std::uint32_t b) { return samples[a].at == samples[b].at; }),
              order.end());
  std::sort(order.begin(), order.end());  // input order again: the triangulation does not depend on duplicates
  std::vector<Point> points(order.size());
  values_.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    points[k] = samples[order[k]].at;
    values_[k] = as_bound(samples[order[k]].value);
  }
  delaunay_ = delaunay(points);
  locator_ = TriangleLocator(view());
}

double SampleInterpolant::nearest_value(Point p) const noexcept {
  const std::uint32_t i = nearest_.nearest(p);
  return i == no_index ? infinity : as_bound(samples_[i].value);
}

double SampleInterpolant::area_at(Point p, WalkHint* hint) const noexcept {
  if (!linear_ || delaunay_.triangles.empty()) return nearest_value(p);
  const Location at = locator_.locate(view(), p, hint);
  if (!at.inside) return nearest_value(p);
  return interpolate(view(), values_, at, p);
}

}  // namespace madd::detail
