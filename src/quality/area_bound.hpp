#pragma once
// The size bound of a mesh at a point: the one function the mesher refines
// to and verify_mesh checks against (and madd::area_bound_at answers with),
// so that the two cannot disagree. Built once per run: the samples are
// indexed (sizing/sample_interpolant.hpp) and the size field's background
// made (sizing/size_field.hpp) for the many queries.
#include <optional>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "sizing/sample_interpolant.hpp"
#include "sizing/size_field.hpp"

namespace madd::detail {

// Where one caller's last queries ended in the samples' and the field's
// triangulations: its next ones start there (sizing/triangle_locator.hpp).
// One per caller and thread; the bound read does not depend on it.
struct BoundHint {
  WalkHint samples, field;
};

// The largest allowed triangle area at a point for one MeshSizeOptions: the
// smallest of max_triangle_area, the area function there, the samples' value
// there (linear or nearest, MeshSizeOptions::sample_interpolation), the
// equilateral triangle of side max_edge_length, and the size field's
// (distance, feature size, gradation), each when set and > 0 (+infinity
// when none is). Shared by the work estimate, the decoupling, refinement and
// verify_mesh. Keeps a reference to `size`, which must outlive it.
class AreaBound {
public:
  // The field terms need the domain (a valid one): without it they throw
  // OptionError. The field is built on `threads` threads (0: one per core),
  // the same for any count.
  explicit AreaBound(const MeshSizeOptions& size, const Pslg* domain = nullptr, unsigned threads = 1);
  double area_at(Point p, BoundHint* hint = nullptr) const;
  bool bounded() const noexcept { return size_.has_size_bound(); }
  // No bound varies over the domain: area_at is one value everywhere.
  bool uniform() const noexcept;
  const MeshSizeOptions& options() const noexcept { return size_; }
  // The size field (empty when no field term is set).
  const SizeField& field() const noexcept { return field_; }

  // When the bound is min(c, area_of_edge(h(x))), c a constant and h the
  // field's edge length, limited to a gradation L (--gradation): L, else 0.
  // Then |h(x) - h(y)| <= L times the length of any path from x to y in the
  // domain (sizing/gradation.hpp: the field is L-Lipschitz on each of its
  // triangles and continuous; the exact distance term's rate is at most L,
  // sizing/size_field.cpp), so one query near x bounds h(x) from both sides: the
  // mesher reads the bound of most triangles from a neighbour's
  // (mesh/refine.cpp, Refiner::bound_of).
  double edge_slope() const noexcept { return edge_slope_; }
  // h(p), when edge_slope() > 0; area_at(p) = area_of_field_edge(field_edge_at(p)).
  double field_edge_at(Point p, BoundHint* hint = nullptr) const {
    return field_.edge_at(p, hint != nullptr ? &hint->field : nullptr);
  }
  double area_of_field_edge(double h) const noexcept;
  // No point's bound is below this (0 when unknown: an area function or
  // samples vary the bound). The field is hmin or more everywhere
  // (SizeField::least_edge): a triangle no larger than the equilateral one
  // of side hmin needs no query (a third of a graded coast's mesh).
  double least() const noexcept { return least_; }

private:
  const MeshSizeOptions& size_;
  double constant_;  // the smallest of max_triangle_area and hmax's area (+infinity: neither)
  SampleInterpolant samples_;
  SizeField field_;
  double edge_slope_ = 0.0;
  double least_ = 0.0;
};

}  // namespace madd::detail
