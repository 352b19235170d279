#pragma once
// The local half-width of the water at a point (the feature-size term of the
// size field, h <= 2 width / R with --cells-across R; docs/mesh.md, "Size
// field").
//
// Definition: from x's nearest coast point q, the chord of the water along
// the ray from q through x, to the first boundary piece beyond x: width(x)
// is half its length. When that piece is not coast (a box side: open water
// goes on) or there is none, the width is infinite. For a point on the
// coast, the ray runs along the inward normal there (at a vertex, the sum of
// its coast pieces' inward normals: into the water).
//
// Why this and not the medial axis: in a channel of width W the chord is W
// wherever x is in it (banks included), so width = W/2, the medial radius
// there; in a disc basin of radius r it is a diameter, width = r, again the
// medial radius (the distance from the medial point on the chord to the
// boundary). Where they differ the chord is the steadier one: the medial
// axis sends a branch into every concave coast vertex, however shallow, and
// the medial radius (or d + distance to the medial axis, ADMESH's and
// OceanMesh2D's local feature size) goes to zero along each; a chord only
// shortens within a segment length of such a vertex, where the distance term
// is at its smallest anyway. It is also cheap: one ray through the segment
// grid per background point, cut short at the length beyond which the term
// cannot bind. Its known weakness: near the closed end of an inlet, x's
// nearest coast point is on the end wall and the chord runs along the inlet
// (the width there is overestimated within half a width of the end).
#include "madd/geometry.hpp"
#include "sizing/coast.hpp"

namespace madd::detail {

// `nearest`: x's nearest coast point (coast.coast_index.nearest(x));
// `inward`: the direction into the water when x is on the coast ((0, 0):
// the nearest piece's inward normal); chords longer than `t_max` count as
// open (+infinity). `scale`: the domain's extent, for the tolerance that
// keeps the ray from meeting the piece it starts on.
double feature_width(const Coast& coast, Point x, const SegmentIndex::Nearest& nearest, Point inward, double t_max,
                     double scale) noexcept;

}  // namespace madd::detail
