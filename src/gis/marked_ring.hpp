#pragma once
// The ring the coastal stage works on (src/gis/): a closed polygon whose
// every edge carries its boundary marker (the coast's, or the open marker
// where a clip box's side closes the water) and whose every vertex
// remembers where in the file it came from, for error messages.
#include <cstdint>
#include <string>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// A vertex's place in the file: its polygon (an index into
// PolygonSet::polygons), ring (0 the outer ring, k + 1 hole k) and vertex;
// vertex is no_index for a point the clipping made.
struct VertexOrigin {
  std::uint32_t polygon = no_index;
  std::uint32_t ring = 0;
  std::uint32_t vertex = no_index;
};

// Edge k runs from points[k] to points[(k + 1) % n] and has markers[k];
// origins[k] is where points[k] came from. The water is on the left of
// every edge: outer rings counter-clockwise, holes clockwise.
struct MarkedRing {
  std::vector<Point> points;
  std::vector<int> markers;
  std::vector<VertexOrigin> origins;

  std::size_t size() const noexcept { return points.size(); }
  void push(Point p, int marker, VertexOrigin origin) {
    points.push_back(p);
    markers.push_back(marker);
    origins.push_back(origin);
  }
};

// One water body: its outer ring and its islands.
struct MarkedPolygon {
  MarkedRing outer;
  std::vector<MarkedRing> holes;
};

}  // namespace madd::detail
