#pragma once
// The size field's terms at one point, before the background carries them
// (docs/mesh.md, "Size field"): the smallest of
//   hmax;
//   the distance term hmin + G_d d(x), d the exact distance to the coast;
//   the feature-size term max(hmin, 2 width(x) / R) (feature_width.hpp);
//   the depth rules (madd/bathymetry.hpp's wavelength_edge and slope_edge:
//   the M2 tide's wavelength in K_w cells, the slope's 2 pi depth / (K_s
//   |grad depth|)), each floored at hmin, not binding where depth <= 0;
//   the user's bounds (-a, --size-fn, --sizes) as edge lengths, only when a
//   gradation is asked for (the mesher applies them exactly at every point
//   anyway; the background needs them only to grade them);
// each when set. Also the two distances the background's safety bound
// needs (distance_bound.hpp).
#include <limits>
#include <optional>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "sizing/coast.hpp"
#include "sizing/nearest_sample.hpp"
#include "sizing/sample_interpolant.hpp"

namespace madd::detail {

struct RawSample {
  double distance = std::numeric_limits<double>::infinity();         // d(x): to the nearest coast piece
  double vertex_distance = std::numeric_limits<double>::infinity();  // to the nearest end of a coast piece
  double width = std::numeric_limits<double>::infinity();            // half-width of the water (when R > 0)
  double distance_term = std::numeric_limits<double>::infinity();    // hmin + G_d d (when G_d > 0)
  double feature_term = std::numeric_limits<double>::infinity();     // max(hmin, 2 width / R) (when R > 0)
  double other = std::numeric_limits<double>::infinity();            // the smallest term but the distance term
  double edge = std::numeric_limits<double>::infinity();             // h: the smallest term
};

// Keeps references to `coast` and `size`, which must outlive it; neither
// copies nor moves (it indexes its own vector).
class RawField {
public:
  RawField(const Coast& coast, const MeshSizeOptions& size);
  RawField(const RawField&) = delete;
  RawField& operator=(const RawField&) = delete;
  // `inward`: for a point on the coast, the direction into the water there
  // ((0, 0): taken from the nearest coast piece).
  RawSample at(Point x, Point inward = {}) const;
  double extent() const noexcept { return extent_; }

private:
  double depth_term(Point x) const;
  const Coast& coast_;
  const MeshSizeOptions& size_;
  std::vector<ValuedPoint> coast_vertices_;
  NearestSample nearest_vertex_;
  std::optional<SampleInterpolant> samples_;  // only with a gradation
  double extent_ = 0.0;                       // the larger side of the domain's bounding box
};

}  // namespace madd::detail
