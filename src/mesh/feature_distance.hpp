#pragma once
// Local feature size along the segments of a subdivision (Ruppert 1995): for
// a point on segment j, the distance to the nearest feature not incident to
// j, that is every vertex other than j's ends and every segment sharing no
// end with j. Segments meeting j at an end are left out on purpose: their
// distance goes to zero at the shared vertex, where the angle between them,
// not their distance, is what refinement must handle (docs/mesh.md).
#include <cstdint>
#include <vector>

#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

class FeatureDistance {
public:
  FeatureDistance(const std::vector<Point>& points, const std::vector<Segment>& segments);
  // Distance from p to the nearest feature not incident to the segment from
  // vertex a to vertex b (+infinity when there is none). The segment need not
  // be among this object's segments.
  double to_nonincident(Point p, std::uint32_t a, std::uint32_t b) const;

private:
  const std::vector<Point>& points_;
  const std::vector<Segment>& segments_;
  UniformGrid grid_;  // square cells of about the mean segment length; items are segments
};

}  // namespace madd::detail
