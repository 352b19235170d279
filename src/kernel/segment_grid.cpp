// Construction of the sparse uniform segment grid used by validate().
#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/segment_grid.hpp"

namespace madd::detail {

void SegmentGrid::choose_size(const std::vector<Point>& points, const std::vector<Segment>& segments) {
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
  rows_ = static_cast<std::uint32_t>(rows);
  cols_ = static_cast<std::uint32_t>(cols);
  w_ = width > 0.0 ? width / cols : 1.0;
  h_ = height > 0.0 ? height / rows : 1.0;
  x0_ = xmin_;
  y0_ = ymin_;
  inv_w_ = 1.0 / w_;
  inv_h_ = 1.0 / h_;
  // Rounding in the cell arithmetic is a few ulps of the largest coordinate;
  // the widening is orders of magnitude above it, so membership is conservative.
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
    for (std::uint32_t r = r0; r <= r1; ++r)
      for (std::uint32_t c = c0; c <= c1; ++c) add(c, r);
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
    for (std::uint32_t r = r0; r <= r1; ++r) add(c, r);
  }
}

SegmentGrid::SegmentGrid(const std::vector<Point>& points, const std::vector<Segment>& segments) {
  choose_size(points, segments);
  // Counting sort by row, then each row sorted by column: O(n) plus small sorts.
  start_.assign(std::size_t{rows_} + 1, 0);
  for (const Segment& s : segments)
    visit_cells(points[s.a], points[s.b], [&](std::uint32_t, std::uint32_t r) { ++start_[r + 1]; });
  for (std::uint32_t r = 0; r < rows_; ++r) start_[r + 1] += start_[r];
  items_.resize(start_[rows_]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < segments.size(); ++i)
    visit_cells(points[segments[i].a], points[segments[i].b],
                [&](std::uint32_t c, std::uint32_t r) { items_[fill[r]++] = {c, i}; });
  for (std::uint32_t r = 0; r < rows_; ++r) {
    // Segments were added in index order, so a stable sort by column keeps
    // each cell's segments sorted by index.
    std::stable_sort(items_.begin() + start_[r], items_.begin() + start_[r + 1],
                     [](const Entry& e, const Entry& f) { return e.col < f.col; });
  }
}

std::span<const SegmentGrid::Entry> SegmentGrid::row_range(std::uint32_t row, std::uint32_t c0,
                                                           std::uint32_t c1) const noexcept {
  const Entry* first = items_.data() + start_[row];
  const Entry* last = items_.data() + start_[row + 1];
  const Entry* lo = std::lower_bound(first, last, c0, [](const Entry& e, std::uint32_t c) { return e.col < c; });
  const Entry* hi = std::upper_bound(lo, last, c1, [](std::uint32_t c, const Entry& e) { return c < e.col; });
  return {lo, hi};
}

} // namespace madd::detail
