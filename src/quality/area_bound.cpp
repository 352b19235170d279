// The size bound at a point: max_triangle_area, the area function and the nearest
// background sample, the smallest of those that are set (area_bound.hpp).
#include "quality/area_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd {

namespace detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool finite_point(Point p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

// The one formula both searches compare, so they agree bit for bit.
double squared_distance(Point p, Point s) noexcept {
  const double dx = p.x - s.x, dy = p.y - s.y;
  return dx * dx + dy * dy;
}

} // namespace

std::uint32_t nearest_sample_by_scan(std::span<const ValuedPoint> samples, Point p) noexcept {
  if (!finite_point(p)) return no_index;
  double best = infinity;
  std::uint32_t best_index = no_index;
  for (std::uint32_t i = 0; i < samples.size(); ++i) {
    if (!finite_point(samples[i].at)) continue;
    const double d = squared_distance(p, samples[i].at);
    if (d < best) {  // strict: the first of equals (lowest index) stays
      best = d;
      best_index = i;
    }
  }
  return best_index;
}

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
  if (n == 0) return;  // cols_ == 0: nothing to find
  const double width = xmax - xmin, height = ymax - ymin;  // may overflow to inf for extreme input
  const double count = static_cast<double>(n);
  // Square cells, about one sample each; never more than ~3n cells (the
  // second term keeps a thin strip of samples from asking for n^2 cells).
  double cell = std::max(std::sqrt(width * height / count), std::max(width, height) / count);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
  if (!std::isfinite(cell)) cell = std::numeric_limits<double>::max();
  cols_ = static_cast<std::uint32_t>(std::clamp(std::floor(width / cell) + 1.0, 1.0, count + 1.0));
  rows_ = static_cast<std::uint32_t>(std::clamp(std::floor(height / cell) + 1.0, 1.0, count + 1.0));
  x0_ = xmin;
  y0_ = ymin;
  cell_ = cell;
  inv_cell_ = 1.0 / cell;
  // x0 + c * cell and the differences from p are each off by a few ulps of
  // the largest coordinate; this margin is far above that.
  const double scale = std::max({std::abs(xmin), std::abs(xmax), std::abs(ymin), std::abs(ymax)});
  slack_ = 64.0 * 0x1p-53 * scale + 1e-9 * cell;
  // Counting sort by cell; samples in index order, so each cell's list is increasing.
  const auto cell_of = [&](Point q) {
    const auto c = std::min<std::uint32_t>(static_cast<std::uint32_t>(std::max(0.0, (q.x - x0_) * inv_cell_)), cols_ - 1);
    const auto r = std::min<std::uint32_t>(static_cast<std::uint32_t>(std::max(0.0, (q.y - y0_) * inv_cell_)), rows_ - 1);
    return std::size_t{r} * cols_ + c;
  };
  start_.assign(std::size_t{cols_} * rows_ + 1, 0);
  for (const ValuedPoint& s : samples)
    if (finite_point(s.at)) ++start_[cell_of(s.at) + 1];
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  items_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < samples.size(); ++i)
    if (finite_point(samples[i].at)) items_[fill[cell_of(samples[i].at)]++] = i;
}

void NearestSample::visit_cell(std::uint32_t col, std::uint32_t row, Point p, double& best,
                               std::uint32_t& best_index) const noexcept {
  const std::size_t cell = std::size_t{row} * cols_ + col;
  for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
    const std::uint32_t i = items_[k];
    const double d = squared_distance(p, samples_[i].at);
    if (d < best || (d == best && i < best_index)) {
      best = d;
      best_index = i;
    }
  }
}

std::uint32_t NearestSample::nearest(Point p) const noexcept {
  if (cols_ == 0 || !finite_point(p)) return no_index;
  const auto clamp_cell = [](double t, std::uint32_t n) -> std::int64_t {
    if (!(t > 0.0)) return 0;
    if (t >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<std::int64_t>(t);
  };
  const std::int64_t cx = clamp_cell((p.x - x0_) * inv_cell_, cols_), cy = clamp_cell((p.y - y0_) * inv_cell_, rows_);
  const std::int64_t cols = cols_, rows = rows_;
  double best = infinity;
  std::uint32_t best_index = no_index;
  for (std::int64_t r = 0;; ++r) {
    // Ring r: the cells at Chebyshev distance r from (cx, cy), inside the grid.
    const std::int64_t c0 = cx - r, c1 = cx + r, r0 = cy - r, r1 = cy + r;
    const std::int64_t lo_c = std::max<std::int64_t>(c0, 0), hi_c = std::min(c1, cols - 1);
    for (std::int64_t c = lo_c; c <= hi_c; ++c) {
      if (r0 >= 0) visit_cell(static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(r0), p, best, best_index);
      if (r > 0 && r1 < rows) visit_cell(static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(r1), p, best, best_index);
    }
    for (std::int64_t q = std::max<std::int64_t>(r0 + 1, 0); q <= std::min(r1 - 1, rows - 1); ++q) {
      if (c0 >= 0) visit_cell(static_cast<std::uint32_t>(c0), static_cast<std::uint32_t>(q), p, best, best_index);
      if (r > 0 && c1 < cols) visit_cell(static_cast<std::uint32_t>(c1), static_cast<std::uint32_t>(q), p, best, best_index);
    }
    // Every unvisited cell lies beyond one of the four sides of the visited
    // block that still has cells behind it; the nearest such side bounds
    // the distance of every sample not yet seen.
    const bool left = c0 > 0, right = c1 < cols - 1, below = r0 > 0, above = r1 < rows - 1;
    if (!left && !right && !below && !above) break;
    double lower = infinity;
    if (left) lower = std::min(lower, p.x - (x0_ + static_cast<double>(c0) * cell_));
    if (right) lower = std::min(lower, (x0_ + static_cast<double>(c1 + 1) * cell_) - p.x);
    if (below) lower = std::min(lower, p.y - (y0_ + static_cast<double>(r0) * cell_));
    if (above) lower = std::min(lower, (y0_ + static_cast<double>(r1 + 1) * cell_) - p.y);
    lower -= slack_;
    if (lower > 0.0 && lower * lower * (1.0 - 1e-9) > best) break;
  }
  return best_index;
}

AreaBound::AreaBound(const MeshSizeOptions& size) : size_(size), background_(size.triangle_area_samples) {}

double AreaBound::at(Point p) const { return combine_area_bounds(size_, p, background_.nearest(p)); }

double combine_area_bounds(const MeshSizeOptions& size, Point p, std::uint32_t nearest) {
  double bound = infinity;
  if (size.max_triangle_area > 0.0) bound = size.max_triangle_area;
  if (size.triangle_area_function) {
    const double v = size.triangle_area_function(p.x, p.y);
    if (v > 0.0) bound = std::min(bound, v);  // false for NaN too: ignored
  }
  // A sample's value is read like the function's: <= 0 or NaN is no bound.
  if (nearest != no_index && size.triangle_area_samples[nearest].value > 0.0)
    bound = std::min(bound, size.triangle_area_samples[nearest].value);
  return bound;
}

} // namespace detail

// One query: a scan of the samples (O(samples)). For many queries with the
// same options build a detail::AreaBound once (src/quality/area_bound.hpp).
double area_bound_at(const MeshSizeOptions& size, Point p) {
  return detail::combine_area_bounds(size, p, detail::nearest_sample_by_scan(size.triangle_area_samples, p));
}

} // namespace madd
