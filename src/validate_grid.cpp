// Construction of the uniform segment grid used by validate().
#include <algorithm>
#include <cmath>

#include "segment_grid.hpp"

namespace madd::detail {

void SegmentGrid::choose_size(const std::vector<Point>& points, const std::vector<Segment>& segments) {
  xmin_ = ymin_ = std::numeric_limits<double>::infinity();
  xmax_ = ymax_ = -std::numeric_limits<double>::infinity();
  for (const Segment& s : segments) {
    for (std::uint32_t v : {s.a, s.b}) {
      xmin_ = std::min(xmin_, points[v].x);
      xmax_ = std::max(xmax_, points[v].x);
      ymin_ = std::min(ymin_, points[v].y);
      ymax_ = std::max(ymax_, points[v].y);
    }
  }
  if (segments.empty()) xmin_ = xmax_ = ymin_ = ymax_ = 0.0;
  const double n = static_cast<double>(std::max<std::size_t>(segments.size(), 1));
  const double width = xmax_ - xmin_;
  const double height = ymax_ - ymin_;
  double cols = 1.0, rows = 1.0;
  if (width > 0.0 && height > 0.0) {
    cols = std::sqrt(n * width / height);
    rows = std::sqrt(n * height / width);
  } else if (width > 0.0) {
    cols = n;
  } else if (height > 0.0) {
    rows = n;
  }
  // A segment visits about 1 + cols*|dx|/width + rows*|dy|/height cells; keep
  // the total near 4n so that long segments cannot blow the grid up.
  double span_x = 0.0, span_y = 0.0;
  for (const Segment& s : segments) {
    if (width > 0.0) span_x += std::abs(points[s.b].x - points[s.a].x) / width;
    if (height > 0.0) span_y += std::abs(points[s.b].y - points[s.a].y) / height;
  }
  const double visits = cols * span_x + rows * span_y;
  if (visits > 4.0 * n) {
    cols *= 4.0 * n / visits;
    rows *= 4.0 * n / visits;
  }
  cols_ = static_cast<std::uint32_t>(std::clamp(std::ceil(cols), 1.0, 65536.0));
  rows_ = static_cast<std::uint32_t>(std::clamp(std::ceil(rows), 1.0, 65536.0));
  while (double(cols_) * rows_ > 4.0 * n + 16.0) {
    cols_ = std::max<std::uint32_t>(1, cols_ / 2);
    rows_ = std::max<std::uint32_t>(1, rows_ / 2);
  }
  w_ = width > 0.0 ? width / cols_ : 1.0;
  h_ = height > 0.0 ? height / rows_ : 1.0;
  x0_ = xmin_;
  y0_ = ymin_;
  inv_w_ = 1.0 / w_;
  inv_h_ = 1.0 / h_;
  // Rounding in the cell arithmetic is a few ulps of the largest coordinate;
  // the widening is orders of magnitude above it.
  const double scale = std::max({std::abs(xmin_), std::abs(xmax_), std::abs(ymin_), std::abs(ymax_)});
  tol_x_ = 1e-3 * w_ + 1e-12 * scale;
  tol_y_ = 1e-3 * h_ + 1e-12 * scale;
}

template <class Add>
void SegmentGrid::visit_cells(Point a, Point b, Add&& add) const {
  const double lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
  const double lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
  const std::uint32_t c0 = col_of(lo_x - tol_x_), c1 = col_of(hi_x + tol_x_);
  if (c0 == c1 || hi_x == lo_x) {
    const std::uint32_t r0 = row_of(lo_y - tol_y_), r1 = row_of(hi_y + tol_y_);
    for (std::uint32_t c = c0; c <= c1; ++c)
      for (std::uint32_t r = r0; r <= r1; ++r) add(std::size_t{r} * cols_ + c);
    return;
  }
  const double slope = (b.y - a.y) / (b.x - a.x);
  for (std::uint32_t c = c0; c <= c1; ++c) {
    const double left = std::max(lo_x, x0_ + c * w_ - tol_x_);
    const double right = std::min(hi_x, x0_ + (c + 1.0) * w_ + tol_x_);
    double ya = a.y + (left - a.x) * slope;
    double yb = a.y + (right - a.x) * slope;
    if (ya > yb) std::swap(ya, yb);
    ya = std::max(ya, lo_y);
    yb = std::min(yb, hi_y);
    const std::uint32_t r0 = row_of(ya - tol_y_), r1 = row_of(yb + tol_y_);
    for (std::uint32_t r = r0; r <= r1; ++r) add(std::size_t{r} * cols_ + c);
  }
}

SegmentGrid::SegmentGrid(const std::vector<Point>& points, const std::vector<Segment>& segments) {
  choose_size(points, segments);
  const std::size_t cells = std::size_t{cols_} * rows_;
  start_.assign(cells + 1, 0);
  for (const Segment& s : segments) visit_cells(points[s.a], points[s.b], [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < segments.size(); ++i)
    visit_cells(points[segments[i].a], points[segments[i].b], [&](std::size_t c) { items_[fill[c]++] = i; });
}

} // namespace madd::detail
