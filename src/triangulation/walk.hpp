#pragma once
// Point location on the half-edge core: a walk from a triangle towards p
// across the edges p lies strictly beyond, with exact orientation tests,
// until a triangle holds p in its closure.
//
// Two ways to choose among the edges p is beyond, for two needs:
// - at random (a stochastic visibility walk, Devillers et al.): locates a
//   point in a Delaunay triangulation or a constrained one, where any path
//   will do; the rotating first edge only avoids the pathological orders of
//   a fixed rule. It enters a ghost triangle (and stops there) when p lies
//   outside the convex hull. walk_weighing steers the same way but computes
//   all three sides of p in every triangle, so that it ends with p's
//   barycentric weights: point location that interpolates.
// - along the straight line from a point of the first triangle to p:
//   refinement needs to know whether p is visible from a triangle, and if
//   not, which segment is in the way (the segment whose diametral circle p
//   then encroaches).
#include <array>
#include <cstdint>
#include <span>

#include "madd/geometry.hpp"
#include "triangulation/half_edge_mesh.hpp"

namespace madd::detail {

struct WalkResult {
  std::uint32_t triangle = no_index;  // holds p in its closure (a ghost: p outside the hull)
  // The half-edge the walk could not cross: a segment (straight walk), or
  // the outside of a mesh without ghosts.
  std::uint32_t blocked_by = no_index;
};

// The random state of a visibility walk: a caller that locates many nearby
// points keeps one across them.
struct WalkRandom {
  std::uint32_t state = 12345;  // a linear congruential generator's
};

// A visibility walk from `start` (a live triangle, or a ghost). A walk that
// does not end within a step count no walk needs gives up to a scan of every
// triangle; triangle is no_index only when no live triangle holds p.
WalkResult walk_visibly(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                        WalkRandom& random);

// walk_visibly that also gives p's weights in the triangle it ends in:
// weights[i] is twice the signed area of p with the edge opposite corner i
// (its sign exact: orient2d's), p's barycentric weights unnormalised. For a
// mesh without ghosts, the point location of a fixed triangulation that
// interpolates over it (src/sizing/triangle_locator.hpp).
WalkResult walk_weighing(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         WalkRandom& random, std::array<double, 3>& weights);

// A walk along the straight line from `from` (a point inside the live
// triangle `start`) to p, crossing only unconstrained edges: blocked_by is
// the first segment half-edge the line meets, or triangle holds p. Both are
// no_index when the walk gives up (after a step count no walk needs).
WalkResult walk_straight(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         Point from);

}  // namespace madd::detail
