#pragma once
// Cutting water polygons to a box (`--clip`), exactly in the sense that
// every piece of the result is a piece of an input ring or of the box's
// sides: the ring pieces inside the box are kept, and each one leaving the
// box is joined to the next one entering it by the box's sides between them,
// counter-clockwise, which become open boundary (docs/coastal.md, "Clipping").
#include <span>
#include <vector>

#include "gis/marked_ring.hpp"
#include "madd/coast.hpp"

namespace madd::detail {

// The box with each side moved outwards, by as few units in the last place
// as it takes, off every vertex of `polygons` lying exactly on it: then no
// vertex is on the box, every ring edge meeting the box crosses it, and the
// clipping has no ties to break (a side through a vertex would ask which
// side of the box the vertex's two edges are on).
ClipBox box_off_vertices(std::span<const MarkedPolygon> polygons, ClipBox box);

// Each polygon (rings with the water on their left) cut to `box`, which no
// vertex may lie on (box_off_vertices): the water bodies inside it, each an
// outer ring (counter-clockwise) and the holes inside it. The box's sides
// that bound water get `open_marker`; when no ring meets the box and the
// box lies in a polygon's water, the whole box is a body.
std::vector<MarkedPolygon> clip_to_box(std::span<const MarkedPolygon> polygons, ClipBox box, int open_marker);

}  // namespace madd::detail
