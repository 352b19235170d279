// Nearest non-incident feature through a uniform grid of the segments: the
// cells around the query are searched ring by ring until a ring lies farther
// than the nearest feature found.
#include "mesh/feature_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/segment_distance.hpp"

namespace madd::detail {

FeatureDistance::FeatureDistance(const std::vector<Point>& points, const std::vector<Segment>& segments)
    : points_(points), segments_(segments) {
  if (segments.empty()) return;
  double x0 = points[segments[0].a].x, y0 = points[segments[0].a].y, total = 0;
  double x1 = x0, y1 = y0;
  for (const Segment& s : segments) {
    for (const std::uint32_t v : {s.a, s.b}) {
      x0 = std::min(x0, points[v].x);
      y0 = std::min(y0, points[v].y);
      x1 = std::max(x1, points[v].x);
      y1 = std::max(y1, points[v].y);
    }
    total += distance(points[s.a], points[s.b]);
  }
  // Cells about the mean segment length, at most about 4 per segment.
  const double extent = std::max(x1 - x0, y1 - y0);
  const double n = static_cast<double>(segments.size());
  const double cell =
      std::max({total / n, extent / std::sqrt(4 * n), extent * 1e-9, std::numeric_limits<double>::min()});
  const auto cols = static_cast<std::uint32_t>((x1 - x0) / cell) + 1;
  const auto rows = static_cast<std::uint32_t>((y1 - y0) / cell) + 1;
  grid_ = UniformGrid({x0, y0}, cell, cell, cols, rows);
  // A segment is listed in the cells it passes through and a little beyond
  // (a superset is harmless, a miss is not).
  const double tol = 1e-3 * cell + 1e-12 * std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
  grid_.fill(static_cast<std::uint32_t>(segments.size()), UniformGrid::Index::by_cell,
             [&](std::uint32_t j, auto&& add) {
               grid_.segment_cells(points[segments[j].a], points[segments[j].b], tol, tol, add);
             });
}

double FeatureDistance::to_nonincident(Point p, std::uint32_t ja, std::uint32_t jb) const {
  double best = std::numeric_limits<double>::infinity();
  if (segments_.empty()) return best;
  const auto visit = [&](std::uint32_t j) {
    const Segment& s = segments_[j];
    const bool shares_end = s.a == ja || s.a == jb || s.b == ja || s.b == jb;
    if (!shares_end) {
      best = std::min(best, segment_distance(p, points_[s.a], points_[s.b]));
      return;
    }
    // A neighbour at an end: only its far vertex is a non-incident feature.
    for (const std::uint32_t v : {s.a, s.b}) {
      if (v != ja && v != jb) best = std::min(best, distance(p, points_[v]));
    }
  };
  // The distances are rounded too: a relative margin keeps a feature a few
  // ulps nearer than computed from being missed.
  grid_.rings(p, visit, [&](double lower) { return lower * (1.0 - 1e-9) > best; });
  return best;
}

}  // namespace madd::detail
