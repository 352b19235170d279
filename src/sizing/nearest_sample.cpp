// The nearest sample of a set of valued points (nearest_sample.hpp).
#include "sizing/nearest_sample.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool finite_point(Point p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

NearestSample::NearestSample(std::span<const ValuedPoint> samples) : samples_(samples) {
  double xmin = infinity, ymin = infinity, xmax = -infinity, ymax = -infinity;
  std::size_t n = 0;
  for (const ValuedPoint& s : samples) {
    if (!finite_point(s.at)) continue;
    xmin = std::min(xmin, s.at.x);
    xmax = std::max(xmax, s.at.x);
    ymin = std::min(ymin, s.at.y);
    ymax = std::max(ymax, s.at.y);
    ++n;
  }
  if (n == 0) return;                                      // no cells: nothing to find
  const double width = xmax - xmin, height = ymax - ymin;  // may overflow to inf for extreme input
  const double count = static_cast<double>(n);
  // Square cells, about one sample each; never more than ~3n cells (the
  // second term keeps a thin strip of samples from asking for n^2 cells).
  double cell = std::max(std::sqrt(width * height / count), std::max(width, height) / count);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
  if (!std::isfinite(cell)) cell = std::numeric_limits<double>::max();
  const auto cols = static_cast<std::uint32_t>(std::clamp(std::floor(width / cell) + 1.0, 1.0, count + 1.0));
  const auto rows = static_cast<std::uint32_t>(std::clamp(std::floor(height / cell) + 1.0, 1.0, count + 1.0));
  grid_ = UniformGrid({xmin, ymin}, cell, cell, cols, rows);
  grid_.fill(static_cast<std::uint32_t>(samples.size()), UniformGrid::Index::by_cell, [&](std::uint32_t i, auto&& add) {
    if (finite_point(samples[i].at)) add(grid_.col_of(samples[i].at.x), grid_.row_of(samples[i].at.y));
  });
}

std::uint32_t NearestSample::nearest(Point p) const noexcept {
  if (!finite_point(p)) return no_index;
  double best = infinity;
  std::uint32_t best_index = no_index;
  grid_.rings(
      p,
      [&](std::uint32_t i) {
        const double dx = p.x - samples_[i].at.x, dy = p.y - samples_[i].at.y;
        const double d = dx * dx + dy * dy;
        if (d < best || (d == best && i < best_index)) {
          best = d;
          best_index = i;
        }
      },
      // The squared distances are rounded too: a relative margin.
      [&](double lower) { return lower > 0.0 && lower * lower * (1.0 - 1e-9) > best; });
  return best_index;
}

}  // namespace madd::detail
