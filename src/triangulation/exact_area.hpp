#pragma once
// Exact areas for the self-checks: the domain's, as domain_area() defines it
// (the faces Triangle keeps after flooding from the outside and the hole
// points), and a triangulation's. Each is twice the area, as an exact sum
// (kernel/exact_sum.hpp), so two of them can be compared without rounding.
#include "kernel/exact_sum.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

// Twice the area domain_area(pslg) approximates, exactly: the shoelace sum over
// every half-edge of the rings of the kept faces (validate's face map).
ExactSum domain_twice_area_exact(const Pslg& pslg);

// The vertices of the convex hull of the points, counter-clockwise, without
// collinear ones (Andrew's monotone chain, every turn decided by orient2d);
// empty when they are all on one line.
std::vector<Point> convex_hull(std::vector<Point> points);

// Twice the area of the convex hull of the points, exactly (0 when they
// are all on one line).
ExactSum hull_twice_area_exact(const std::vector<Point>& points);

// Twice the total signed area of the triangles, exactly.
ExactSum triangles_twice_area_exact(const Triangulation& tri);

}  // namespace madd::detail
