#pragma once
// Which rings of a shapefile record are outer rings and which are holes,
// decided by containment. The technical description puts the polygon on the
// right of a ring's direction (outer rings clockwise, holes counter-
// clockwise), but files from many sources get the direction wrong, so the
// reader does not rely on it (include/madd/polygons.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::detail {

// The nesting tree of a record's rings.
struct RingNesting {
  std::vector<std::uint32_t> parent;  // per ring: the smallest ring holding it, or no_index
  std::vector<std::uint32_t> depth;   // per ring: how many rings hold it (0 for a root)
};

// Rings are open (first vertex not repeated) with finite coordinates. Ring i
// lies in ring j when j's bounding box holds i's and the first vertex of i
// not on j is inside j, exactly (orient2d); when every vertex of i is on j,
// the first midpoint of an edge of i not on j decides, and a ring lying
// wholly on j (a duplicate) is not in it. Rings of a valid polygon do not
// cross, so these relations nest: a ring's parent is the ring of least area
// holding it, and its depth is the number of rings holding it, whose parity
// says outer ring (even) or hole (odd). For rings that cross the answer is
// still a tree (parents have larger area, ties broken by index), only not a
// meaningful one. Candidates come from a grid over the record's box, and
// large rings answer point queries from their edges filed by rows of y, so
// the work grows with the rings and points, not with their products, unless
// rings are nested deeply (each ring meets every box that holds its own).
RingNesting nest_rings(std::span<const std::vector<Point>> rings);

}  // namespace madd::detail
