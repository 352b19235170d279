#pragma once
// The one uniform grid of madd: items (segments, points) listed in every
// cell of a regular grid they may touch, so that a search looks at the items
// near a place instead of all of them. Each user chooses the cell size and
// what "may touch" means (SegmentGrid for validate and the verifiers,
// FeatureDistance for the mesher's local feature size, NearestSample for the
// size bound, GdLocator for points among G_D's triangles, the mesher's region
// labels); the grid stores the lists, finds the cells of a coordinate, a box
// or a segment, and walks rings of cells outwards from a point. It only prunes
// candidates: every decision is the caller's, so a grid that lists an item
// in a few cells too many changes no result.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::detail {

class UniformGrid {
public:
  struct Entry {
    std::uint32_t col;
    std::uint32_t item;
  };
  // How a cell's entries are found. by_row keeps one offset per row and finds
  // a cell by binary search in its row, so that only occupied cells cost
  // memory (SegmentGrid's cells follow the segment length, and far-apart
  // segments may span 2^30 columns); by_cell keeps one offset per cell, for
  // the ring searches of a grid sized to its items (a direct lookup).
  enum class Index { by_row, by_cell };

  UniformGrid() = default;  // no cells: the ring search finds nothing
  // cols x rows cells of w x h, the first with its lower left corner at origin.
  UniformGrid(Point origin, double w, double h, std::uint32_t cols, std::uint32_t rows) noexcept;

  // Lists item i, for i in [0, count), in every cell cells_of(i, add) names by
  // calling add(col, row). Entries are sorted by row, column, then item.
  template <class CellsOf>
  void fill(std::uint32_t count, Index index, CellsOf&& cells_of);

  std::uint32_t rows() const noexcept { return rows_; }
  std::uint32_t cols() const noexcept { return cols_; }
  std::size_t entries() const noexcept { return items_.size(); }
  // Cell column/row of a coordinate, clamped to the grid (monotone in x, y;
  // NaN gives 0).
  std::uint32_t col_of(double x) const noexcept { return clamp_index((x - x0_) * inv_w_, cols_); }
  std::uint32_t row_of(double y) const noexcept { return clamp_index((y - y0_) * inv_h_, rows_); }
  // Entries of row `row` with column in [c0, c1], sorted by (column, item).
  std::span<const Entry> row_range(std::uint32_t row, std::uint32_t c0, std::uint32_t c1) const noexcept;
  // Entries of the cell holding p (clamped into the grid), items increasing.
  std::span<const Entry> cell_at(Point p) const noexcept {
    const std::uint32_t col = col_of(p.x);
    return row_range(row_of(p.y), col, col);
  }

  // Calls add(col, row) for every cell of the box [lo, hi] (clamped).
  template <class Add>
  void box_cells(Point lo, Point hi, Add&& add) const {
    for (std::uint32_t r = row_of(lo.y), r1 = row_of(hi.y); r <= r1; ++r)
      for (std::uint32_t c = col_of(lo.x), c1 = col_of(hi.x); c <= c1; ++c) add(c, r);
  }
  // Calls visit(item) for the entries of every cell of the box [lo, hi]
  // (clamped), row by row; an item in several of them, once per cell.
  template <class Visit>
  void in_box(Point lo, Point hi, Visit&& visit) const {
    const std::uint32_t c0 = col_of(lo.x), c1 = col_of(hi.x);
    for (std::uint32_t r = row_of(lo.y), r1 = row_of(hi.y); r <= r1; ++r)
      for (const Entry& e : row_range(r, c0, c1)) visit(e.item);
  }

  // Calls add(col, row) for every cell segment a-b may pass through: its
  // exact cells and whatever lies within tol_x, tol_y of them (a widening the
  // caller chooses far above the rounding of the cell arithmetic).
  template <class Add>
  void segment_cells(Point a, Point b, double tol_x, double tol_y, Add&& add) const;

  // Calls visit(item) for the entries of the cells around p, ring by ring
  // (ring r: the cells at Chebyshev distance r from p's cell, clamped into
  // the grid); after each ring, done(lower) with a lower bound on the distance
  // from p to every cell not yet visited (a rounding margin already taken
  // off), stopping when it returns true or when no cell is left. An item in
  // several cells may be visited more than once.
  template <class Visit, class Done>
  void rings(Point p, Visit&& visit, Done&& done) const;

private:
  static std::uint32_t clamp_index(double t, std::uint32_t n) noexcept {
    if (!(t > 0.0)) return 0;
    if (t >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<std::uint32_t>(t);
  }
  std::size_t key(std::uint32_t col, std::uint32_t row) const noexcept {
    return index_ == Index::by_cell ? std::size_t{row} * cols_ + col : row;
  }

  std::uint32_t cols_ = 0, rows_ = 0;
  double x0_ = 0.0, y0_ = 0.0;  // the grid's origin
  double w_ = 1.0, h_ = 1.0;    // cell size
  double inv_w_ = 1.0, inv_h_ = 1.0;
  double slack_ = 0.0;  // margin on a distance to a cell side, above its rounding
  Index index_ = Index::by_row;
  std::vector<std::uint32_t> start_;  // per row or per cell (index_), + 1: offsets into items_
  std::vector<Entry> items_;
};

inline std::span<const UniformGrid::Entry> UniformGrid::row_range(std::uint32_t row, std::uint32_t c0,
                                                                  std::uint32_t c1) const noexcept {
  if (c0 > c1 || start_.empty()) return {};  // an empty range, or a grid never filled
  if (index_ == Index::by_cell) {
    const std::size_t first = std::size_t{row} * cols_;
    return {items_.data() + start_[first + c0], items_.data() + start_[first + c1 + 1]};
  }
  const Entry* first = items_.data() + start_[row];
  const Entry* last = items_.data() + start_[row + 1];
  const Entry* lo = std::lower_bound(first, last, c0, [](const Entry& e, std::uint32_t c) { return e.col < c; });
  const Entry* hi = std::upper_bound(lo, last, c1, [](std::uint32_t c, const Entry& e) { return c < e.col; });
  return {lo, hi};
}

template <class CellsOf>
void UniformGrid::fill(std::uint32_t count, Index index, CellsOf&& cells_of) {
  index_ = index;
  // Counting sort by key, items in increasing order; by row, then each row
  // sorted by column (stable: a cell's items stay increasing).
  start_.assign((index == Index::by_cell ? std::size_t{cols_} * rows_ : rows_) + 1, 0);
  for (std::uint32_t i = 0; i < count; ++i)
    cells_of(i, [&](std::uint32_t c, std::uint32_t r) { ++start_[key(c, r) + 1]; });
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  items_.resize(start_.back());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < count; ++i)
    cells_of(i, [&](std::uint32_t c, std::uint32_t r) { items_[next[key(c, r)]++] = {c, i}; });
  if (index == Index::by_cell) return;
  for (std::uint32_t r = 0; r < rows_; ++r)
    std::stable_sort(items_.begin() + start_[r], items_.begin() + start_[r + 1],
                     [](const Entry& e, const Entry& f) { return e.col < f.col; });
}

template <class Add>
void UniformGrid::segment_cells(Point a, Point b, double tol_x, double tol_y, Add&& add) const {
  const double lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
  const double lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
  const std::uint32_t c0 = col_of(lo_x - tol_x), c1 = col_of(hi_x + tol_x);
  if (c0 == c1 || hi_x == lo_x) {
    const std::uint32_t r0 = row_of(lo_y - tol_y), r1 = row_of(hi_y + tol_y);
    for (std::uint32_t r = r0; r <= r1; ++r)
      for (std::uint32_t c = c0; c <= c1; ++c) add(c, r);
    return;
  }
  // Column by column: the rows the segment crosses within the column's x range.
  const double slope = (b.y - a.y) / (b.x - a.x);
  for (std::uint32_t c = c0; c <= c1; ++c) {
    const double left = std::max(lo_x, x0_ + c * w_ - tol_x);
    const double right = std::min(hi_x, x0_ + (c + 1.0) * w_ + tol_x);
    double ya = a.y + (left - a.x) * slope;
    double yb = a.y + (right - a.x) * slope;
    if (ya > yb) std::swap(ya, yb);
    ya = std::max(ya, lo_y);
    yb = std::min(yb, hi_y);
    const std::uint32_t r0 = row_of(ya - tol_y), r1 = row_of(yb + tol_y);
    for (std::uint32_t r = r0; r <= r1; ++r) add(c, r);
  }
}

template <class Visit, class Done>
void UniformGrid::rings(Point p, Visit&& visit, Done&& done) const {
  if (cols_ == 0 || rows_ == 0) return;
  const std::int64_t cx = col_of(p.x), cy = row_of(p.y), cols = cols_, rows = rows_;
  const auto cells = [&](std::int64_t row, std::int64_t c0, std::int64_t c1) {
    for (const Entry& e :
         row_range(static_cast<std::uint32_t>(row), static_cast<std::uint32_t>(c0), static_cast<std::uint32_t>(c1)))
      visit(e.item);
  };
  for (std::int64_t r = 0;; ++r) {
    // Ring r: its bottom and top rows whole, then its two side columns.
    const std::int64_t c0 = cx - r, c1 = cx + r, r0 = cy - r, r1 = cy + r;
    const std::int64_t lo_c = std::max<std::int64_t>(c0, 0), hi_c = std::min(c1, cols - 1);
    if (r0 >= 0) cells(r0, lo_c, hi_c);
    if (r > 0 && r1 < rows) cells(r1, lo_c, hi_c);
    for (std::int64_t q = std::max<std::int64_t>(r0 + 1, 0); q <= std::min(r1 - 1, rows - 1); ++q) {
      if (c0 >= 0) cells(q, c0, c0);
      if (r > 0 && c1 < cols) cells(q, c1, c1);
    }
    // Every unvisited cell lies beyond one of the four sides of the visited
    // block that still has cells behind it; the nearest such side bounds
    // the distance of every item not yet seen.
    const bool left = c0 > 0, right = c1<cols - 1, below = r0> 0, above = r1 < rows - 1;
    if (!left && !right && !below && !above) return;
    double lower = std::numeric_limits<double>::infinity();
    if (left) lower = std::min(lower, p.x - (x0_ + static_cast<double>(c0) * w_));
    if (right) lower = std::min(lower, (x0_ + static_cast<double>(c1 + 1) * w_) - p.x);
    if (below) lower = std::min(lower, p.y - (y0_ + static_cast<double>(r0) * h_));
    if (above) lower = std::min(lower, (y0_ + static_cast<double>(r1 + 1) * h_) - p.y);
    if (done(lower - slack_)) return;
  }
}

}  // namespace madd::detail
