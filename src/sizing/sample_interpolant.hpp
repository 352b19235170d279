#pragma once
// Reading the --sizes samples (MeshSizeOptions::triangle_area_samples, each
// a point and the largest allowed triangle area there) between them, as
// MeshSizeOptions::sample_interpolation says:
// - linear: over the Delaunay triangulation of the samples (madd::delaunay),
//   the value at p linear in the triangle holding it; outside the samples'
//   convex hull, the nearest sample's value;
// - nearest: the nearest sample's value (NearestSample: the smallest squared
//   distance, ties to the lowest index), madd's rule before the linear one.
// A value <= 0 or NaN means "no bound" there, as for the area function; the
// linear reading takes it as an infinite area, so that a triangle with such
// a corner bounds nothing wherever that corner has weight (only its opposite
// edge is read from the two other corners): "no bound" spreads over the
// triangles around such a sample instead of its nearest-sample cell, and
// never lowers a bound. Samples with a non-finite coordinate are left out;
// of samples at the same point the first is kept (the one nearest-sample
// reading picks too), the later ones are ignored.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/triangulation.hpp"
#include "sizing/nearest_sample.hpp"
#include "sizing/triangle_locator.hpp"

namespace madd::detail {

class SampleInterpolant {
public:
  // Keeps a view of `samples`, which must outlive it.
  SampleInterpolant(std::span<const ValuedPoint> samples, MeshSizeOptions::SampleInterpolation how);
  // The area bound at p: +infinity where there is none (no sample, or "no
  // bound" samples decide). Thread-safe (const, no shared mutable state).
  double area_at(Point p, WalkHint* hint = nullptr) const noexcept;

private:
  std::span<const ValuedPoint> samples_;
  NearestSample nearest_;
  bool linear_ = true;
  Triangulation delaunay_;      // of the kept samples
  std::vector<double> values_;  // per point of delaunay_: its area, +infinity for "no bound"
  TriangleLocator locator_;
  double nearest_value(Point p) const noexcept;
  TriangleView view() const noexcept { return {delaunay_.points, delaunay_.triangles, delaunay_.neighbours}; }
};

}  // namespace madd::detail
