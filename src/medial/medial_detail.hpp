#pragma once
// The medial graph's inside (src/medial/medial.cpp): how a split's working
// points are linked along the boundary and the interior segments, the
// junction test, and G_D built from such links. The split (src/split) uses
// them; the public madd/medial.hpp builds the graph of a plain boundary.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/medial.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

// A triangulation vertex's neighbours along the boundary ring it lies on,
// oriented so that the domain is on the left of prev -> vertex -> next.
// prev == no_index marks a vertex where no separator may end (for example one
// the boundary passes twice).
// A vertex inside an interior segment (two_sided) has the domain on both
// sides: prev and next are its neighbours along the segment, and a separator
// ending there makes its angles with whichever side it lies on (it crosses
// the segment there, with one partial separator on each side).
struct BoundaryLinks {
  std::uint32_t prev = no_index;
  std::uint32_t next = no_index;
  float bonus = 1.0f;  // Sec. 5.1 smoothing factor (< 1 rewards separators ending here)
  bool two_sided = false;
  // No separator may end here, and the bisection, not the contraction, sees
  // to it (a cut partial separator here is a conflict to repartition, like a
  // pinch, Sec. 4.3): the end of an interior segment, a fork of several, or a
  // ring vertex one meets. Contracting every edge here instead would fuse all
  // the triangles around the point into one G'_D vertex, a large part of the
  // face in a triangulation without interior points, and unbalance the split.
  bool no_end = false;
  // The loose end of an interior segment (prev == next: its neighbour along
  // it). A separator may pass through it: two cut partial separators, each
  // at >= Phi0 from the segment, and >= Phi0 apart on the side without it
  // (pinch_conflicts). Keeping separators off it instead would leave the fan
  // of triangles around it uncrossable, as no_end does.
  bool tip = false;
};

// The smallest angle the segment from vertex `at` towards `towards` makes
// with the boundary or interior segment through `at` (links[at]), as
// boundary_angle; for a two-sided vertex, on the side `towards` lies on; for
// a tip, the angle between the segment and `towards`.
// Returns -1 where no separator may end (prev == no_index) or outside the
// wedge; 180 at a no_end vertex (the bisection keeps separators off it).
double link_angle(std::span<const Point> points, std::span<const BoundaryLinks> links, std::uint32_t at, Point towards);

// Which side of the segment through a two-sided vertex `towards` lies on:
// 0 left of prev -> at -> next, 1 right; always 0 for a boundary vertex.
int link_side(std::span<const Point> points, std::span<const BoundaryLinks> links, std::uint32_t at, Point towards);

// Per-triangle result of the junction test (Sec. 3, properties 1-3).
struct JunctionTest {
  bool junction = false;
  Point centre;                         // circumcentre
  std::array<bool, 3> spoke_ok{};       // spoke centre -> vertex i is a candidate partial separator
  std::array<double, 3> spoke_angle{};  // smallest angle (degrees) spoke i makes (boundary, other spokes)
};

// Junction test for triangle t: it contains its circumcentre strictly (exact
// orient2d), at least two of its edges are interior, and at least two spokes
// make angles >= Phi0 with the boundary and with each other. Keeps the largest
// such set of spokes (all pairwise angles at the centre >= Phi0).
JunctionTest test_junction(const Triangulation& tri, std::uint32_t t, std::span<const BoundaryLinks> links,
                           double separator_angle_deg);

// Builds G_D and G'_D for a triangulation whose vertices all lie on the
// boundary (links has one entry per triangulation point). Deterministic.
MedialGraph build_medial_graph(const Triangulation& tri, std::span<const BoundaryLinks> links,
                               const MedialOptions& options);

// Replaces the G_D vertex weights (one per G_D vertex, e.g. density weights of
// a graded decomposition, Sec. 5.2) and recomputes G'_D's as their sums.
void set_vertex_weights(MedialGraph& graph, std::vector<double> weights);

// A partial separator must keep clear of the boundary along its middle: a
// boundary edge p-q (p = q: a point) that comes within separator_clearance
// of its length of the middle 80% of separator a-b leaves a strip of water a hair wide between the separator and the
// coast, which meshing fills with triangles of that width (on Lake Ladoga a chord 1.15 long, made by moving a
// separator's end along the coast, ran 5e-4 from a coast segment: 35,000 triangles, 8 x its subdomain's share). G_D's
// partial separators and smoothing's moves both keep to it.
// 1%: at least 0.1 sin(Phi0) from the boundary edges at its own ends, above
// it for any Phi0 >= 6 degrees.
inline constexpr double separator_clearance = 0.01;
bool hugs_separator(Point a, Point b, Point p, Point q);

// The links build_medial_graph(tri, options) reads off a triangulation's
// outer edges (madd/medial.hpp).
std::vector<BoundaryLinks> boundary_links(const Triangulation& tri);

}  // namespace madd::detail
