#pragma once
// What real coastlines need before they can be a domain (docs/coastal.md,
// "Cleaning"): rings turned so that the water is on their left, duplicate
// and nearly duplicate vertices merged, spikes (a ring doubling back on
// itself) cut off, and rings sorted into water bodies.
#include <cstddef>
#include <vector>

#include "gis/marked_ring.hpp"

namespace madd::detail {

// Signed area (positive counter-clockwise), by kernel/rings.hpp.
double signed_area_of(const MarkedRing& ring);

// Fewer than three vertices, or all on one line (exact): a ring that
// bounds nothing. A ring whose signed area is 0 need not be one: a
// figure of eight whose loops are equal bounds both.
bool flat(const MarkedRing& ring);

// Turns the outer ring counter-clockwise and the holes clockwise (GeoJSON
// asks for that order, shapefiles the opposite, and real files mix them).
void orient_for_water(MarkedPolygon& polygon);

struct RingCleaning {
  std::size_t merged = 0;  // vertices merged into the one before them
  std::size_t spikes = 0;  // vertices removed where the ring doubled back
};

// Merges every vertex within `merge_distance` of the one before it (equal
// ones when it is 0) and removes every vertex where the ring turns back
// along itself (collinear, reversing: exact orient2d), until neither is left,
// round the ring's end too. The edge that stays takes the marker of the
// longer of the two it replaces. The ring may be left with fewer than three
// vertices, or flat (see flat()): the caller drops it.
RingCleaning clean_ring(MarkedRing& ring, double merge_distance);

// Sorts closed rings (water on their left) into water bodies: each ring of
// positive area is an outer ring, each of negative area a hole of the
// smallest outer ring holding it (holes in no outer ring are dropped).
std::vector<MarkedPolygon> bodies_of(std::vector<MarkedRing> rings);

}  // namespace madd::detail
