// Nearest non-incident feature through a uniform grid of the segments: the
// cells around the query are searched ring by ring until a ring lies farther
// than the nearest feature found.
#include "mesh/feature_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

namespace {

double point_segment_distance(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, lerp(a, b, t));
}

} // namespace

FeatureDistance::FeatureDistance(const std::vector<Point>& points, const std::vector<Segment>& segments)
    : points_(points), segments_(segments) {
  if (segments.empty()) return;
  double x1 = points[segments[0].a].x, y1 = points[segments[0].a].y, total = 0;
  x0_ = x1;
  y0_ = y1;
  for (const Segment& s : segments) {
    for (const std::uint32_t v : {s.a, s.b}) {
      x0_ = std::min(x0_, points[v].x);
      y0_ = std::min(y0_, points[v].y);
      x1 = std::max(x1, points[v].x);
      y1 = std::max(y1, points[v].y);
    }
    total += distance(points[s.a], points[s.b]);
  }
  // Cells about the mean segment length, at most about 4 per segment.
  const double extent = std::max(x1 - x0_, y1 - y0_);
  const double n = static_cast<double>(segments.size());
  cell_ = std::max({total / n, extent / std::sqrt(4 * n), extent * 1e-9, std::numeric_limits<double>::min()});
  cols_ = static_cast<std::int64_t>((x1 - x0_) / cell_) + 1;
  rows_ = static_cast<std::int64_t>((y1 - y0_) / cell_) + 1;
  start_.assign(static_cast<std::size_t>(cols_ * rows_) + 1, 0);
  for (std::uint32_t j = 0; j < segments.size(); ++j) for_cells_of(j, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  items_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t j = 0; j < segments.size(); ++j) for_cells_of(j, [&](std::size_t c) { items_[fill[c]++] = j; });
}

// Every cell segment j passes through, each once: the cells of its bounding
// box row by row, clipped to the columns the segment spans within that row.
template <class Visit>
void FeatureDistance::for_cells_of(std::uint32_t j, Visit&& visit) const {
  const Point a = points_[segments_[j].a], b = points_[segments_[j].b];
  const auto col = [&](double x) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - x0_) / cell_), 0, cols_ - 1); };
  const auto row = [&](double y) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - y0_) / cell_), 0, rows_ - 1); };
  const std::int64_t r0 = row(std::min(a.y, b.y)), r1 = row(std::max(a.y, b.y));
  for (std::int64_t r = r0; r <= r1; ++r) {
    // The x range of the segment within this row's y band (widened by a cell
    // for rounding: a superset is harmless, a miss is not).
    double xa = std::min(a.x, b.x), xb = std::max(a.x, b.x);
    if (a.y != b.y) {
      const double ylo = y0_ + static_cast<double>(r) * cell_, yhi = ylo + cell_;
      const double ta = std::clamp((ylo - a.y) / (b.y - a.y), 0.0, 1.0), tb = std::clamp((yhi - a.y) / (b.y - a.y), 0.0, 1.0);
      const double xs = a.x + ta * (b.x - a.x), xe = a.x + tb * (b.x - a.x);
      xa = std::max(xa, std::min(xs, xe) - cell_);
      xb = std::min(xb, std::max(xs, xe) + cell_);
    }
    for (std::int64_t c = col(xa); c <= col(xb); ++c) visit(static_cast<std::size_t>(r * cols_ + c));
  }
}

double FeatureDistance::to_nonincident(Point p, std::uint32_t ja, std::uint32_t jb) const {
  double best = std::numeric_limits<double>::infinity();
  if (segments_.empty()) return best;
  const auto c0 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p.x - x0_) / cell_)), 0, cols_ - 1);
  const auto r0 = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p.y - y0_) / cell_)), 0, rows_ - 1);
  const std::int64_t max_ring = std::max(cols_, rows_);
  for (std::int64_t ring = 0; ring <= max_ring; ++ring) {
    if (ring > 1 && static_cast<double>(ring - 1) * cell_ > best) break;
    for (std::int64_t r = r0 - ring; r <= r0 + ring; ++r) {
      if (r < 0 || r >= rows_) continue;
      const bool full_row = r == r0 - ring || r == r0 + ring;
      for (std::int64_t c = c0 - ring; c <= c0 + ring; c += full_row || ring == 0 ? 1 : 2 * ring) {
        if (c < 0 || c >= cols_) continue;
        const auto cell = static_cast<std::size_t>(r * cols_ + c);
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
          const Segment& s = segments_[items_[k]];
          const bool shares_end = s.a == ja || s.a == jb || s.b == ja || s.b == jb;
          if (!shares_end) {
            best = std::min(best, point_segment_distance(p, points_[s.a], points_[s.b]));
            continue;
          }
          // A neighbour at an end: only its far vertex is a non-incident feature.
          for (const std::uint32_t v : {s.a, s.b}) {
            if (v != ja && v != jb) best = std::min(best, distance(p, points_[v]));
          }
        }
      }
    }
  }
  return best;
}

} // namespace madd::detail
