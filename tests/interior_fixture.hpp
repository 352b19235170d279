#pragma once
// A domain with interior constraints and its decomposition, made by hand
// (decompose() does not need to support them for the mesher to be tested):
// the rectangle [0, 4] x [0, 2] split by the separator x = 2.
//
// - left half (subdomain 0): an interior polyline, a V with a 53-degree
//   apex, and a dangling segment from the boundary vertex (0, 1) into the
//   interior at 2.9 degrees to the boundary (a tiny input angle between an
//   interior segment and the boundary);
// - right half (subdomain 1): a closed interior square loop with a region
//   inside it (attribute 5, area bound 0.002), an isolated vertex inside the
//   loop and one outside it;
// - two more region points in the face outside the loop, one in each half:
//   the later (attribute 3, right half) wins over the whole face, across the
//   separator (Triangle's rule).
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::test {

struct InteriorFixture {
  Pslg domain;
  Decomposition decomposition;
  // The loop, counter-clockwise, for point-in-polygon tests.
  std::vector<Point> loop;
  std::vector<std::uint32_t> interior_input_segments;  // input segments inside the domain
  std::vector<std::uint32_t> isolated;                 // input isolated vertices
};

inline InteriorFixture interior_fixture() {
  InteriorFixture f;
  Pslg& p = f.domain;
  p.first_index = 0;
  p.points = {{0, 0},     {2, 0},     {4, 0},     {4, 2},      {2, 2}, {0, 2}, {0, 1},  // 0-6: boundary
              {0.3, 0.6}, {1, 1.5},   {1.7, 0.6}, {0.04, 1.8},                          // 7-10: V, dangling end
              {2.5, 0.5}, {3.5, 0.5}, {3.5, 1.5}, {2.5, 1.5},                           // 11-14: loop
              {3.0, 1.1}, {3.8, 0.2}};                                                  // 15-16: isolated
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 2},  {3, 4, 1},   {4, 5, 1},   {5, 6, 3},   {6, 0, 3},
                {7, 8, 5}, {8, 9, 5}, {6, 10, 6}, {11, 12, 7}, {12, 13, 7}, {13, 14, 7}, {14, 11, 7}};
  p.has_segment_markers = true;
  p.regions = {{{1.0, 0.3}, 2.0, -1.0}, {{3.0, 0.8}, 5.0, 0.002}, {{3.8, 1.0}, 3.0, -1.0}};
  f.loop = {p.points[11], p.points[12], p.points[13], p.points[14]};
  f.interior_input_segments = {7, 8, 9, 10, 11, 12, 13};
  f.isolated = {15, 16};

  Decomposition& d = f.decomposition;
  d.points = p.points;
  d.segments = p.segments;
  for (std::uint32_t j = 0; j < p.segments.size(); ++j) d.segment_origin.push_back(j);
  const auto separator = static_cast<std::uint32_t>(d.segments.size());
  d.segments.push_back({1, 4, 0});
  d.segment_origin.push_back(no_index);
  d.regions = p.regions;
  d.separator_angle_deg = 60.0;
  Subdomain left;
  left.rings = {{0, 1, 4, 5, 6}};
  left.ring_segments = {{0, separator, 4, 5, 6}};
  left.area = left.weight = 4.0;
  left.interior_point = {1.0, 0.25};
  left.interior_segments = {7, 8, 9};
  Subdomain right;
  right.rings = {{1, 2, 3, 4}};
  right.ring_segments = {{1, 2, 3, separator}};
  right.area = right.weight = 4.0;
  right.interior_point = {3.0, 0.25};
  right.interior_segments = {10, 11, 12, 13};
  right.interior_points = {15, 16};
  d.subdomains = {left, right};
  return f;
}

// Strictly inside the convex counter-clockwise polygon `ring` (floating
// point; the tests ask it of centroids, never near the edges by rounding).
inline bool inside_convex(const std::vector<Point>& ring, Point q) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    if (cross(b - a, q - a) <= 0) return false;
  }
  return true;
}

}  // namespace madd::test
