#pragma once
// The area bound of MeshSizeOptions, evaluated fast: the nearest background
// sample is found through a uniform grid of the samples.
#include <cstdint>
#include <vector>

#include "madd/mesh.hpp"

namespace madd::detail {

class SizeField {
public:
  explicit SizeField(const MeshSizeOptions& size);
  // The largest allowed triangle area at p (+infinity when unbounded).
  double area_at(Point p) const;
  bool bounded() const noexcept { return bounded_; }
  const MeshSizeOptions& options() const noexcept { return *size_; }

private:
  double nearest_sample_value(Point p) const;

  const MeshSizeOptions* size_;
  bool bounded_ = false;
  // Background samples bucketed by cell (CSR): cell c holds samples
  // order_[start_[c] .. start_[c + 1]).
  double x0_ = 0, y0_ = 0, cell_ = 1;
  std::uint32_t cols_ = 0, rows_ = 0;
  std::vector<std::uint32_t> start_, order_;
};

} // namespace madd::detail
