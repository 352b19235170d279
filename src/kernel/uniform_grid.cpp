// The uniform grid's frame (uniform_grid.hpp).
#include "kernel/uniform_grid.hpp"

namespace madd::detail {

UniformGrid::UniformGrid(Point origin, double w, double h, std::uint32_t cols, std::uint32_t rows) noexcept
    : cols_(cols), rows_(rows), x0_(origin.x), y0_(origin.y), w_(w), h_(h), inv_w_(1.0 / w), inv_h_(1.0 / h) {
  // x0 + c * w and its difference from a query coordinate are each off by a
  // few ulps of the largest coordinate; this margin is far above that.
  const double scale = std::max({std::abs(x0_), std::abs(y0_), std::abs(x0_ + cols * w_), std::abs(y0_ + rows * h_)});
  slack_ = 64.0 * 0x1p-53 * scale + 1e-9 * std::max(w_, h_);
}

}  // namespace madd::detail
