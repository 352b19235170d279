#pragma once
// The triangles a narrow gap of water costs, whatever the size bound says
// (docs/mesh.md, "Balance by work"). Delaunay refinement cannot make a
// triangle much wider than the water it fills: a channel of width W is
// meshed in a strip of triangles with sides of about 1.6 W however large
// the bound there, a cost the integral of the bound alone does not see. So
// the work estimate reads the smaller of the bound and the area of that
// edge, from the chord across the water at the point (as
// sizing/feature_width.hpp draws it), every boundary piece counted as coast:
// refinement honours every segment. Under one bound everywhere (whose
// interior the estimate counts by area) the gaps' excess over the bound is
// added the same way (mesh/work.cpp).
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"
#include "sizing/coast.hpp"

namespace madd::detail {

class NarrowGaps {
public:
  // `domain` passed validate().
  explicit NarrowGaps(const Pslg& domain);
  // The smaller of `bound` (an area bound at p, +infinity for none) and the
  // area refinement reaches in the gap holding p, if any is narrow enough
  // to bind.
  double area_at(Point p, double bound) const noexcept;

private:
  Coast coast_;
  double extent_ = 0.0;
};

// Two boundary pieces that meet at less than this (radians: 3 degrees) are
// the banks of a needle of water, which refinement fills as it fills a
// channel (one 0.085 degrees wide and 1.8 long in the Seto Inland Sea took
// triangles of area 5e-9, twice the mean subdomain's count at N = 256);
// above it they are the sides of a wedge, whose small input angle
// refinement leaves alone (the spikes of Puget Sound's coast: counting them
// as gaps over-counted a subdomain 3 x).
inline constexpr double needle_angle = 0.05235987755982988;

// The gap's edge is taken no shorter than this x the bound's edge.
inline constexpr double smallest_gap_edge = 1e-3;

// Edge length over chord across a gap, of the triangles refinement leaves
// there (their mean area is kappa x that edge's area bound; measured on the
// channel of tests/mesh_field_test.cpp, "narrow gap": 0.72 W^2 a triangle).
inline constexpr double gap_edge_fraction = 1.6;

}  // namespace madd::detail
