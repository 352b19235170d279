#pragma once
// The uniform grid of the segments of a Pslg (validate, the verifiers).
// Every segment is listed in every cell it may pass through, decided
// conservatively (cell ranges are widened by a tolerance far above rounding
// error), so two segments that share a point always share a cell. The grid
// only prunes candidates: every geometric decision is made later with the
// exact orient2d.
#include <vector>

#include "kernel/uniform_grid.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// Cells are about twice the mean segment length, so each cell holds O(1)
// segments of a boundary curve and the total number of (cell, segment)
// entries is O(n) however long individual segments are. Only occupied cells
// are stored (UniformGrid::Index::by_row): far-apart segments may span many
// columns. An entry's item is a segment index.
class SegmentGrid : public UniformGrid {
public:
  SegmentGrid(const std::vector<Point>& points, const std::vector<Segment>& segments);

  // Within the bounding box of the segments' ends.
  bool y_in_range(double y) const noexcept { return y >= ymin_ && y <= ymax_; }
  bool contains(Point p) const noexcept { return p.x >= xmin_ && p.x <= xmax_ && y_in_range(p.y); }

private:
  double xmin_ = 0.0, xmax_ = 0.0, ymin_ = 0.0, ymax_ = 0.0;
};

}  // namespace madd::detail
