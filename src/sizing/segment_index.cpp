// The nearest segment, the first segment on a ray, and the crossing parity
// (segment_index.hpp).
#include "sizing/segment_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

SegmentIndex::SegmentIndex(const std::vector<Point>& points, const std::vector<Segment>& segments) {
  ends_.reserve(segments.size());
  Point lo{infinity, infinity}, hi{-infinity, -infinity};
  for (const Segment& s : segments) {
    ends_.push_back({points[s.a], points[s.b]});
    for (const Point p : ends_.back()) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  }
  if (ends_.empty()) return;
  // Square cells, about four per segment (a coast fills a thin band of its
  // bounding box, and the field's queries ask for a radius of a few h
  // there: finer cells visit fewer segments; measured, 2 x 2 per segment's
  // share beat 1 and 4 x 4). The strip term keeps a thin row of segments
  // from asking for n^2 cells; a segment is listed in every cell it passes,
  // so long ones cost their length in cells.
  const double width = hi.x - lo.x, height = hi.y - lo.y, count = static_cast<double>(ends_.size());
  double cell = std::max(std::sqrt(width * height / count) / 2.0, std::max(width, height) / count);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
  const auto cols = static_cast<std::uint32_t>(std::clamp(std::floor(width / cell) + 1.0, 1.0, count + 1.0));
  const auto rows = static_cast<std::uint32_t>(std::clamp(std::floor(height / cell) + 1.0, 1.0, count + 1.0));
  grid_ = UniformGrid(lo, cell, cell, cols, rows);
  const double tol = 1e-9 * cell;  // far above the rounding of the cell arithmetic
  grid_.fill(static_cast<std::uint32_t>(ends_.size()), UniformGrid::Index::by_cell,
             [&](std::uint32_t i, auto&& add) { grid_.segment_cells(ends_[i][0], ends_[i][1], tol, tol, add); });
}

SegmentIndex::Nearest SegmentIndex::nearest(Point p) const noexcept {
  Nearest best;
  best.distance = infinity;
  grid_.rings(
      p,
      [&](std::uint32_t s) {
        if (s == best.segment) return;
        double t = 0.0;
        const double d = segment_distance(p, ends_[s][0], ends_[s][1], t);
        if (d < best.distance || (d == best.distance && s < best.segment)) best = {d, s, {}, t};
      },
      [&](double lower) { return lower > best.distance; });
  if (best.segment != no_index)
    best.at = best.t == 1.0 ? ends_[best.segment][1] : lerp(ends_[best.segment][0], ends_[best.segment][1], best.t);
  return best;
}

SegmentIndex::Hit SegmentIndex::first_hit(Point from, Point u, double t_min, double t_max) const noexcept {
  Hit best{infinity, no_index};
  if (ends_.empty() || !(t_max > t_min)) return best;
  const Point a = from + t_min * u, b = from + t_max * u;
  const double tol = 1e-9 * std::max({std::abs(t_max), std::abs(a.x), std::abs(a.y), 1e-300});
  grid_.segment_cells(a, b, tol, tol, [&](std::uint32_t col, std::uint32_t row) {
    for (const UniformGrid::Entry& e : grid_.row_range(row, col, col)) {
      const Point p = ends_[e.item][0], q = ends_[e.item][1];
      const Point pq = q - p, fp = p - from;
      const double denom = cross(u, pq);
      if (denom == 0.0) continue;
      const double t = cross(fp, pq) / denom, s = cross(fp, u) / denom;
      if (!(s >= 0.0 && s <= 1.0 && t > t_min && t <= t_max)) continue;
      if (t < best.t || (t == best.t && e.item < best.segment)) best = {t, e.item};
    }
  });
  if (best.segment == no_index) best.t = infinity;
  return best;
}

bool SegmentIndex::within(Point p, double radius, std::size_t cap, std::vector<std::uint32_t>& out) const {
  out.clear();
  bool complete = true;
  grid_.rings(
      p,
      [&](std::uint32_t s) {
        if (!complete || std::find(out.begin(), out.end(), s) != out.end()) return;
        double t = 0.0;
        if (!(segment_distance(p, ends_[s][0], ends_[s][1], t) <= radius)) return;
        if (out.size() == cap) complete = false;
        else out.push_back(s);
      },
      [&](double lower) { return !complete || lower > radius; });
  std::sort(out.begin(), out.end());
  return complete;
}

bool SegmentIndex::odd_crossings(Point p) const noexcept {
  if (ends_.empty()) return false;
  const std::uint32_t row = grid_.row_of(p.y), c0 = grid_.col_of(p.x);
  bool odd = false;
  for (const UniformGrid::Entry& e : grid_.row_range(row, c0, grid_.cols() - 1)) {
    const Point a = ends_[e.item][0], b = ends_[e.item][1];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
    // Counted once: in the cell of the crossing, which the segment is listed in.
    if (x > p.x && grid_.col_of(x) == e.col) odd = !odd;
  }
  return odd;
}

}  // namespace madd::detail
