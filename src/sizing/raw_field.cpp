// The size field's terms at a point (raw_field.hpp).
#include "sizing/raw_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/bathymetry.hpp"
#include "sizing/feature_width.hpp"
#include "sizing/edge_length.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

std::vector<ValuedPoint> valued(const std::vector<Point>& points) {
  std::vector<ValuedPoint> out;
  out.reserve(points.size());
  for (const Point p : points) out.push_back({p, 0.0});
  return out;
}

}  // namespace

double RawField::depth_term(Point x) const {
  if (!size_.has_depth_terms()) return infinity;
  const double d = size_.depth(x.x, x.y);
  double h = wavelength_edge(d, size_.wavelength_cells);
  if (size_.slope_cells > 0.0)
    h = std::min(h, slope_edge(d, length(size_.depth_gradient(x.x, x.y)), size_.slope_cells));
  return std::isfinite(h) ? std::max(size_.min_edge_length, h) : infinity;
}

RawField::RawField(const Coast& coast, const MeshSizeOptions& size)
    : coast_(coast), size_(size), coast_vertices_(valued(coast.coast_vertices)), nearest_vertex_(coast_vertices_) {
  if (size.size_gradation > 0.0 && !size.triangle_area_samples.empty())
    samples_.emplace(size.triangle_area_samples, size.sample_interpolation);
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (std::size_t i = 0; i < coast.points.size(); ++i) {
    const Point p = coast.points[i];
    x0 = i == 0 ? p.x : std::min(x0, p.x), x1 = i == 0 ? p.x : std::max(x1, p.x);
    y0 = i == 0 ? p.y : std::min(y0, p.y), y1 = i == 0 ? p.y : std::max(y1, p.y);
  }
  extent_ = std::max(x1 - x0, y1 - y0);
}

RawSample RawField::at(Point x, Point inward) const {
  RawSample out;
  const SegmentIndex::Nearest nearest = coast_.coast_index.nearest(x);
  out.distance = nearest.distance;
  const std::uint32_t v = nearest_vertex_.nearest(x);
  if (v != no_index) out.vertex_distance = distance(x, coast_vertices_[v].at);
  double other = size_.max_edge_length > 0.0 ? size_.max_edge_length : infinity;
  if (size_.size_gradation > 0.0) {
    double area = size_.max_triangle_area > 0.0 ? size_.max_triangle_area : infinity;
    if (size_.triangle_area_function) {
      const double a = size_.triangle_area_function(x.x, x.y);
      if (a > 0.0) area = std::min(area, a);  // false for NaN too: no bound
    }
    if (samples_) area = std::min(area, samples_->area_at(x));
    other = std::min(other, edge_of_area(area));
  }
  if (size_.distance_rate > 0.0) out.distance_term = size_.min_edge_length + size_.distance_rate * out.distance;
  double h = std::min(other, out.distance_term);
  if (size_.cells_across > 0.0) {
    // A chord longer than R h gives a term above h: it cannot bind.
    const double t_max = std::isfinite(h) ? size_.cells_across * h : 4.0 * extent_ + 1.0;
    out.width = feature_width(coast_, x, nearest, inward, t_max, extent_);
    out.feature_term = std::max(size_.min_edge_length, 2.0 * out.width / size_.cells_across);
    other = std::min(other, out.feature_term);
    h = std::min(h, out.feature_term);
  }
  const double depth_term = this->depth_term(x);
  other = std::min(other, depth_term);
  h = std::min(h, depth_term);
  out.other = other;
  out.edge = h;
  return out;
}

}  // namespace madd::detail
