// The size bound at a point: max_triangle_area, the area function and the nearest
// background sample, the smallest of those that are set (area_bound.hpp).
#include "quality/area_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/error.hpp"

namespace madd {

namespace detail {

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

namespace {

const Pslg& domain_for_field(const MeshSizeOptions& size, const Pslg* domain) {
  static const Pslg none;
  if (domain) return *domain;
  if (size.has_field_terms())
    throw OptionError("distance_rate",
                      "the distance, feature-size and gradation terms of the size field need the domain they grade");
  return none;
}

double constant_bound(const MeshSizeOptions& size) {
  double bound = size.max_triangle_area > 0.0 ? size.max_triangle_area : infinity;
  if (size.max_edge_length > 0.0) bound = std::min(bound, area_of_edge(size.max_edge_length));
  return bound;
}

using Interpolation = MeshSizeOptions::SampleInterpolation;

std::span<const ValuedPoint> samples_read(const MeshSizeOptions& size, Interpolation how) {
  if (size.sample_interpolation != how) return {};
  return size.triangle_area_samples;
}

}  // namespace

AreaBound::AreaBound(const MeshSizeOptions& size, const Pslg* domain)
    : size_(size),
      constant_(constant_bound(size)),
      nearest_(samples_read(size, Interpolation::nearest)),
      linear_(samples_read(size, Interpolation::linear)),
      field_(domain_for_field(size, domain), size) {}

bool AreaBound::uniform() const noexcept {
  return !size_.triangle_area_function && size_.triangle_area_samples.empty() && field_.empty();
}

double AreaBound::area_at(Point p) const {
  double bound = constant_;
  if (size_.triangle_area_function) {
    const double v = size_.triangle_area_function(p.x, p.y);
    if (v > 0.0) bound = std::min(bound, v);  // false for NaN too: ignored
  }
  if (!size_.triangle_area_samples.empty()) {
    // A sample's value is read like the function's: <= 0 or NaN is no bound.
    if (size_.sample_interpolation == Interpolation::nearest) {
      const std::uint32_t nearest = nearest_.nearest(p);
      if (nearest != no_index && size_.triangle_area_samples[nearest].value > 0.0)
        bound = std::min(bound, size_.triangle_area_samples[nearest].value);
    } else {
      const double v = linear_.value_at(p);
      if (v > 0.0) bound = std::min(bound, v);
    }
  }
  if (!field_.empty()) {
    const double h = field_.edge_at(p);
    if (h > 0.0) bound = std::min(bound, area_of_edge(h));
  }
  return bound;
}

}  // namespace detail

// The same code as the mesher's and verify_mesh's bound (built for one
// query: O(samples), like a scan; with field terms, the whole field). For
// many queries with the same options the library builds a detail::AreaBound once.
double area_bound_at(const MeshSizeOptions& size, Point p) { return detail::AreaBound(size).area_at(p); }
double area_bound_at(const MeshSizeOptions& size, const Pslg& domain, Point p) {
  return detail::AreaBound(size, &domain).area_at(p);
}

}  // namespace madd
