#pragma once
// The background triangulation of the size field (size_field.hpp): what it
// is piecewise linear on, and what the work estimate integrates over.
#include <array>
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// The triangulation the field is piecewise linear on: the constrained
// Delaunay triangulation of the domain's vertices and Steiner points,
// covering the convex hull of the domain (holes and the outside included, so
// that a walk can always reach a point); `inside` marks the domain's
// triangles, over which the work estimate integrates.
struct SizeBackground {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;   // counterclockwise
  std::vector<std::array<std::uint32_t, 3>> neighbours;  // across edge i (opposite corner i); no_index on the hull
  std::vector<std::uint8_t> inside;                      // per triangle: 1 in the domain
  std::vector<double> edge;                              // per point: h there (+infinity: no bound)
};

}  // namespace madd::detail
