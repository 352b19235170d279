#pragma once
// A uniform grid of segments answering the three questions the size field
// asks of the coast and the domain boundary: the nearest segment to a point
// (its exact Euclidean distance, in doubles), the first segment a ray meets
// (the far shore of a chord, feature_width.hpp), and how many segments a
// horizontal ray crosses (the parity that says whether a point far from
// every segment is in the domain). Holds its own copy of the segments' ends,
// so it copies and moves freely.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/segment_distance.hpp"
#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

class SegmentIndex {
public:
  struct Nearest {
    double distance = 0.0;                // +infinity when there is no segment
    std::uint32_t segment = 0xffffffffu;  // lowest index among the nearest
    Point at;                             // the nearest point of that segment
    double t = 0.0;                       // its parameter along the segment, in [0, 1]
  };
  struct Hit {
    double t = 0.0;                       // along the ray (its direction is a unit vector): the distance
    std::uint32_t segment = 0xffffffffu;  // no_index: none in range
  };

  SegmentIndex() = default;
  // The segments `segments` of `points` (indices into it).
  SegmentIndex(const std::vector<Point>& points, const std::vector<Segment>& segments);

  std::size_t size() const noexcept { return ends_.size(); }
  const std::array<Point, 2>& ends(std::uint32_t s) const noexcept { return ends_[s]; }
  Nearest nearest(Point p) const noexcept;
  // The first segment the ray from + t u (u a unit vector) meets with t in
  // (t_min, t_max]; ties to the lowest index. Parallel segments are never met.
  Hit first_hit(Point from, Point u, double t_min, double t_max) const noexcept;
  // The segments within `radius` of p (distance <= radius), in `out`,
  // ascending; false (out incomplete) when there are more than `cap`.
  bool within(Point p, double radius, std::size_t cap, std::vector<std::uint32_t>& out) const;
  // Parity of the number of segments the ray p + (t, 0), t > 0, crosses
  // (half-open in y, so a vertex on the ray counts once). Meant for points
  // not on any segment: those of a closed boundary give "inside" when odd.
  bool odd_crossings(Point p) const noexcept;

private:
  std::vector<std::array<Point, 2>> ends_;
  UniformGrid grid_;  // items are segment indices, by cell
};

}  // namespace madd::detail
