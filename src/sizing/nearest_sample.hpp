#pragma once
// The nearest of a set of valued points (a --sizes background file's
// samples): what area_bound_at reads with nearest-sample interpolation, and
// what the linear reading falls back to outside the samples' hull. The
// samples are indexed once for many queries: the mesher and verify_mesh ask
// for every triangle, and a scan of 1e5 samples per triangle would dominate
// both.
#include <cstdint>
#include <span>

#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// The sample nearest to p: the smallest squared distance
// (p.x - s.x)^2 + (p.y - s.y)^2 as computed in doubles, ties to the lowest
// index. Samples with a non-finite coordinate are never nearest. Found in a
// uniform grid of square cells holding about one sample each: a query visits
// rings of cells around p until no unvisited cell can hold a sample as near
// as the best so far. Keeps a view of the samples, which must outlive it.
class NearestSample {
public:
  explicit NearestSample(std::span<const ValuedPoint> samples);
  // no_index when there is none (no finite sample, or p not finite).
  std::uint32_t nearest(Point p) const noexcept;

private:
  std::span<const ValuedPoint> samples_;
  UniformGrid grid_;  // items are sample indices
};

}  // namespace madd::detail
