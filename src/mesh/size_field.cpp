// The area bound at a point: the smallest of -a, --size-fn and the nearest
// background sample.
#include "mesh/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace madd::detail {

namespace {
constexpr double unbounded = std::numeric_limits<double>::infinity();
}

SizeField::SizeField(const MeshSizeOptions& size) : size_(&size), bounded_(size.has_size_bound()) {
  const auto& samples = size.triangle_area_samples;
  if (samples.empty()) return;
  double x1 = samples[0].at.x, y1 = samples[0].at.y;
  x0_ = x1;
  y0_ = y1;
  for (const ValuedPoint& s : samples) {
    x0_ = std::min(x0_, s.at.x);
    y0_ = std::min(y0_, s.at.y);
    x1 = std::max(x1, s.at.x);
    y1 = std::max(y1, s.at.y);
  }
  // About two samples a cell.
  const double extent = std::max({x1 - x0_, y1 - y0_, std::numeric_limits<double>::min()});
  const double cells = std::max(1.0, std::sqrt(static_cast<double>(samples.size()) / 2.0));
  cell_ = extent / cells;
  if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = 1;
  cols_ = static_cast<std::uint32_t>(std::min(4096.0, std::floor((x1 - x0_) / cell_) + 1));
  rows_ = static_cast<std::uint32_t>(std::min(4096.0, std::floor((y1 - y0_) / cell_) + 1));
  const auto cell_of = [&](Point p) {
    const auto c = std::min<std::uint32_t>(cols_ - 1, static_cast<std::uint32_t>(std::max(0.0, (p.x - x0_) / cell_)));
    const auto r = std::min<std::uint32_t>(rows_ - 1, static_cast<std::uint32_t>(std::max(0.0, (p.y - y0_) / cell_)));
    return r * cols_ + c;
  };
  start_.assign(std::size_t{cols_} * rows_ + 1, 0);
  for (const ValuedPoint& s : samples) ++start_[cell_of(s.at) + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  order_.resize(samples.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < samples.size(); ++i) order_[fill[cell_of(samples[i].at)]++] = i;
}

// Rings of cells around p's cell, outwards, until the ring is farther than
// the best sample found (ties broken by the lower index).
double SizeField::nearest_sample_value(Point p) const {
  const auto& samples = size_->triangle_area_samples;
  const double fc = std::clamp(std::floor((p.x - x0_) / cell_), 0.0, static_cast<double>(cols_ - 1));
  const double fr = std::clamp(std::floor((p.y - y0_) / cell_), 0.0, static_cast<double>(rows_ - 1));
  const auto c0 = static_cast<std::int64_t>(fc), r0 = static_cast<std::int64_t>(fr);
  double best = unbounded;
  std::uint32_t best_index = 0;
  const std::int64_t max_ring = std::max<std::int64_t>(cols_, rows_);
  for (std::int64_t ring = 0; ring <= max_ring; ++ring) {
    // The nearest point of this ring is at least (ring - 1) cells away
    // (p may lie anywhere in its own cell, or outside the grid, nearer still).
    if (best < unbounded) {
      const double reach = static_cast<double>(ring - 1) * cell_;
      if (ring > 1 && reach * reach > best) break;
    }
    for (std::int64_t r = r0 - ring; r <= r0 + ring; ++r) {
      if (r < 0 || r >= rows_) continue;
      const bool edge_row = r == r0 - ring || r == r0 + ring;
      for (std::int64_t c = c0 - ring; c <= c0 + ring; c += edge_row ? 1 : 2 * ring) {
        if (c >= 0 && c < cols_) {
          const auto cell = static_cast<std::size_t>(r * cols_ + c);
          for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
            const std::uint32_t i = order_[k];
            const Point d = samples[i].at - p;
            const double d2 = dot(d, d);
            if (d2 < best || (d2 == best && i < best_index)) {
              best = d2;
              best_index = i;
            }
          }
        }
        if (ring == 0) break;
      }
    }
  }
  return samples[best_index].value;
}

double SizeField::area_at(Point p) const {
  double bound = size_->max_triangle_area > 0 ? size_->max_triangle_area : unbounded;
  if (size_->triangle_area_function) {
    const double v = size_->triangle_area_function(p.x, p.y);
    if (v > 0) bound = std::min(bound, v);  // <= 0 and NaN: no bound here
  }
  if (!size_->triangle_area_samples.empty()) bound = std::min(bound, nearest_sample_value(p));
  return bound;
}

} // namespace madd::detail
