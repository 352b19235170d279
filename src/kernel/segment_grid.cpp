// The cell size of the segment grid used by validate() (segment_grid.hpp).
#include "kernel/segment_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

SegmentGrid::SegmentGrid(const std::vector<Point>& points, const std::vector<Segment>& segments) {
  xmin_ = ymin_ = std::numeric_limits<double>::infinity();
  xmax_ = ymax_ = -std::numeric_limits<double>::infinity();
  double total_length = 0.0;
  for (const Segment& s : segments) {
    for (std::uint32_t v : {s.a, s.b}) {
      xmin_ = std::min(xmin_, points[v].x);
      xmax_ = std::max(xmax_, points[v].x);
      ymin_ = std::min(ymin_, points[v].y);
      ymax_ = std::max(ymax_, points[v].y);
    }
    // L1 length: what cell visits depend on, and it cannot overflow.
    total_length += std::abs(points[s.b].x - points[s.a].x) + std::abs(points[s.b].y - points[s.a].y);
  }
  if (segments.empty()) xmin_ = xmax_ = ymin_ = ymax_ = 0.0;
  const double n = static_cast<double>(std::max<std::size_t>(segments.size(), 1));
  const double width = xmax_ - xmin_, height = ymax_ - ymin_;
  // Twice the mean length: a segment visits ~1 + |dx|/w + |dy|/h cells, so the
  // total stays below ~2n entries, and cells along a curve hold O(1) segments.
  double cell = 2.0 * total_length / n;
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
  // Rows are stored densely: at most 2n + 1 of them. Columns are sparse.
  const double rows = std::clamp(std::ceil(height / cell), 1.0, 2.0 * n + 1.0);
  const double cols = std::clamp(std::ceil(width / cell), 1.0, 1073741824.0);
  const double w = width > 0.0 ? width / cols : 1.0;
  const double h = height > 0.0 ? height / rows : 1.0;
  static_cast<UniformGrid&>(*this) =
      UniformGrid({xmin_, ymin_}, w, h, static_cast<std::uint32_t>(cols), static_cast<std::uint32_t>(rows));
  // Rounding in the cell arithmetic is a few ulps of the largest coordinate;
  // the widening is orders of magnitude above it, so membership is conservative.
  const double scale = std::max({std::abs(xmin_), std::abs(xmax_), std::abs(ymin_), std::abs(ymax_)});
  const double tol_x = 1e-3 * w + 1e-12 * scale, tol_y = 1e-3 * h + 1e-12 * scale;
  fill(static_cast<std::uint32_t>(segments.size()), Index::by_row, [&](std::uint32_t i, auto&& add) {
    segment_cells(points[segments[i].a], points[segments[i].b], tol_x, tol_y, add);
  });
}

}  // namespace madd::detail
