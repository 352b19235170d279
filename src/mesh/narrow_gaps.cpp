// The area refinement reaches in a narrow gap (narrow_gaps.hpp).
#include "mesh/narrow_gaps.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/box.hpp"
#include "sizing/edge_length.hpp"

namespace madd::detail {

NarrowGaps::NarrowGaps(const Pslg& domain) : coast_(trace_coast(domain, {})) {
  const Box box = bounding_box(coast_.points);
  extent_ = std::max(box.width(), box.height());
}

double NarrowGaps::area_at(Point p, double bound) const noexcept {
  if (!(bound > 0.0)) return bound;
  // A chord longer than this leaves triangles above the bound: it cannot bind.
  const double longest = std::isfinite(bound) ? edge_of_area(bound) / gap_edge_fraction : 4.0 * extent_ + 1.0;
  // The chord from p's nearest boundary point through p (as
  // sizing/feature_width.hpp draws it) to the next boundary piece.
  const SegmentIndex::Nearest nearest = coast_.coast_index.nearest(p);
  if (!(nearest.distance > 1e-9 * extent_)) return bound;
  const Point u = (1.0 / nearest.distance) * (p - nearest.at);
  const SegmentIndex::Hit hit =
      coast_.boundary_index.first_hit(nearest.at, u, nearest.distance * (1.0 - 1e-9), longest);
  if (hit.segment == no_index) return bound;
  // Two pieces that meet are the sides of a wedge, not the banks of a gap
  // (refinement leaves a small input angle's triangles alone), unless they
  // meet at less than needle_angle.
  const Segment& near = coast_.pieces[coast_.coast_piece[nearest.segment]];
  const Segment& far = coast_.pieces[coast_.boundary_piece[hit.segment]];
  if (near.a == far.a || near.a == far.b || near.b == far.a || near.b == far.b) {
    const std::uint32_t apex = near.a == far.a || near.a == far.b ? near.a : near.b;
    const Point along_near = coast_.points[near.a == apex ? near.b : near.a] - coast_.points[apex];
    const Point along_far = coast_.points[far.a == apex ? far.b : far.a] - coast_.points[apex];
    const double angle = std::atan2(std::abs(cross(along_near, along_far)), dot(along_near, along_far));
    if (angle >= needle_angle) return bound;
  }
  // Near a needle's tip the chord goes to 0, refinement does not.
  const double edge = std::max(gap_edge_fraction * hit.t, smallest_gap_edge * edge_of_area(bound));
  return std::min(bound, area_of_edge(edge));
}

}  // namespace madd::detail
