#pragma once
// Uniform grid bucketing of the segments of a Pslg (internal to validate).
// Every segment is listed in every cell it may pass through, decided
// conservatively (cell ranges are widened by a tolerance far above rounding
// error), so two segments that share a point always share a cell. The grid
// only prunes candidates: every geometric decision is made later with the
// exact orient2d.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/pslg.hpp"

namespace madd::detail {

// Cells are square, about twice the mean segment length, so each cell holds
// O(1) segments of a boundary curve and the total number of (cell, segment)
// entries is O(n) however long individual segments are. Only occupied cells
// are stored: each row keeps its entries sorted by column (row-major CSR).
class SegmentGrid {
public:
  struct Entry {
    std::uint32_t col;
    std::uint32_t segment;
  };

  SegmentGrid(const std::vector<Point>& points, const std::vector<Segment>& segments);

  std::uint32_t rows() const noexcept { return rows_; }
  std::uint32_t cols() const noexcept { return cols_; }
  // Entries of row `row` with column in [c0, c1], sorted by (column, segment).
  std::span<const Entry> row_range(std::uint32_t row, std::uint32_t c0, std::uint32_t c1) const noexcept;
  // Cell column/row of a coordinate, clamped to the grid (monotone in x, y).
  std::uint32_t col_of(double x) const noexcept { return clamp_index((x - x0_) * inv_w_, cols_); }
  std::uint32_t row_of(double y) const noexcept { return clamp_index((y - y0_) * inv_h_, rows_); }
  bool y_in_range(double y) const noexcept { return y >= ymin_ && y <= ymax_; }
  bool contains(Point p) const noexcept { return p.x >= xmin_ && p.x <= xmax_ && y_in_range(p.y); }
  std::size_t entries() const noexcept { return items_.size(); }

private:
  static std::uint32_t clamp_index(double t, std::uint32_t n) noexcept {
    if (!(t > 0.0)) return 0;
    if (t >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<std::uint32_t>(t);
  }
  void choose_size(const std::vector<Point>& points, const std::vector<Segment>& segments);
  // Calls add(col, row) for every cell segment a-b may pass through.
  template <class Add>
  void visit_cells(Point a, Point b, Add&& add) const;

  std::uint32_t cols_ = 1;
  std::uint32_t rows_ = 1;
  double xmin_ = 0.0, xmax_ = 0.0, ymin_ = 0.0, ymax_ = 0.0;
  double x0_ = 0.0, y0_ = 0.0;        // grid origin
  double w_ = 1.0, h_ = 1.0;          // cell size
  double inv_w_ = 1.0, inv_h_ = 1.0;
  double tol_x_ = 0.0, tol_y_ = 0.0;  // widening of every cell range
  std::vector<std::uint32_t> start_;  // per row, rows + 1 offsets into items_
  std::vector<Entry> items_;
};

} // namespace madd::detail
