#pragma once
// Weighted samples merged per cell of a grid over their bounding box: a
// cell's weight goes to its member nearest the cell's weighted centroid (a
// real sample, so inside whatever region held them all). The work estimate
// merges its samples this way for the decomposition (mesh/work.cpp,
// cluster_samples), and the chord search a face's many samples
// (split/chord.cpp, merged_for_chords).
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::detail {

class SampleGrid {
public:
  // A cells x cells grid over the samples' bounding box (not empty), each
  // cell's weight and weighted centroid summed.
  SampleGrid(std::span<const ValuedPoint> samples, int cells) : cells_(cells) {
    lo_ = hi_ = samples[0].at;
    for (const ValuedPoint& s : samples) {
      lo_ = {std::min(lo_.x, s.at.x), std::min(lo_.y, s.at.y)};
      hi_ = {std::max(hi_.x, s.at.x), std::max(hi_.y, s.at.y)};
    }
    w_ = std::max((hi_.x - lo_.x) / cells, 1e-300);
    h_ = std::max((hi_.y - lo_.y) / cells, 1e-300);
    const std::size_t n = cell_count();
    sum_.assign(n, 0.0), sx_.assign(n, 0.0), sy_.assign(n, 0.0);
    for (const ValuedPoint& s : samples) {
      const std::size_t c = cell_of(s.at);
      sum_[c] += s.value, sx_[c] += s.value * s.at.x, sy_[c] += s.value * s.at.y;
    }
  }
  std::size_t cell_count() const noexcept {
    return static_cast<std::size_t>(cells_) * static_cast<std::size_t>(cells_);
  }
  // Row by row; p within the bounding box.
  std::size_t cell_of(Point p) const noexcept {
    const int i = std::clamp(static_cast<int>((p.x - lo_.x) / w_), 0, cells_ - 1);
    const int j = std::clamp(static_cast<int>((p.y - lo_.y) / h_), 0, cells_ - 1);
    return static_cast<std::size_t>(j * cells_ + i);
  }
  double weight(std::size_t c) const noexcept { return sum_[c]; }
  Point origin(std::size_t c) const noexcept {
    return {lo_.x + static_cast<double>(c % static_cast<std::size_t>(cells_)) * w_,
            lo_.y + static_cast<double>(c / static_cast<std::size_t>(cells_)) * h_};
  }
  double cell_width() const noexcept { return w_; }
  double cell_height() const noexcept { return h_; }

  // Per cell, the index of its member nearest its weighted centroid (the
  // first of equals), or samples.size() where it has none or skip(cell).
  template <typename Skip>
  std::vector<std::size_t> nearest_to_centres(std::span<const ValuedPoint> samples, Skip skip) const {
    std::vector<std::size_t> best(cell_count(), samples.size());
    std::vector<double> best_d(cell_count(), 0.0);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const std::size_t c = cell_of(samples[i].at);
      if (skip(c)) continue;
      const Point centre = sum_[c] > 0 ? Point{sx_[c] / sum_[c], sy_[c] / sum_[c]} : samples[i].at;
      const double d = distance(samples[i].at, centre);
      if (best[c] == samples.size() || d < best_d[c]) best[c] = i, best_d[c] = d;
    }
    return best;
  }

private:
  int cells_;
  Point lo_, hi_;
  double w_ = 0.0, h_ = 0.0;
  std::vector<double> sum_, sx_, sy_;
};

}  // namespace madd::detail
