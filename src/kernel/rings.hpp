#pragma once
// Ring geometry, written once: signed area, orientation and exact point
// location. A ring is a closed polygon, its first vertex not repeated at the
// end. Signs are decided by orient2d (madd/predicates.hpp), as
// madd/geometry.hpp asks; only the area itself is floating point.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::detail {

// A ring read in place, in either of the two forms madd keeps rings in: a
// cycle of indices into a point array (subdivision faces, Subdomain::rings)
// or a sequence of points. Cheap to copy; it must not outlive what it views.
class RingView {
public:
  // Vertex k is points[cycle[k]].
  RingView(std::span<const Point> points, std::span<const std::uint32_t> cycle) noexcept
      : points_(points), cycle_(cycle.data()), size_(cycle.size()) {}
  // Vertex k is vertices[k].
  explicit RingView(std::span<const Point> vertices) noexcept : points_(vertices), size_(vertices.size()) {}

  std::size_t size() const noexcept { return size_; }
  Point operator[](std::size_t k) const noexcept { return cycle_ != nullptr ? points_[cycle_[k]] : points_[k]; }
  // The vertex after vertex k, wrapping round to vertex 0.
  Point after(std::size_t k) const noexcept { return (*this)[k + 1 == size_ ? 0 : k + 1]; }

private:
  std::span<const Point> points_;
  const std::uint32_t* cycle_ = nullptr;  // null: the points are the vertices
  std::size_t size_ = 0;
};

// Signed area, positive when the ring runs counter-clockwise; 0 for fewer
// than three vertices. The shoelace sum is taken as a fan of triangles from
// vertex 0, so the products are of coordinate differences, not of (possibly
// large) absolute coordinates: far less cancellation.
double ring_signed_area(RingView ring) noexcept;

// Area of a polygon with holes whose rings index `points` (outer ring
// counter-clockwise, holes clockwise): the sum of the rings' signed areas.
double rings_area(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) noexcept;

// Upper bounds on the rounding error of the two functions above:
// |ring_signed_area(ring) - the exact signed area| <= ring_signed_area_error(ring),
// and likewise for rings_area. Derived in rings.cpp; they let a check compare a
// stored floating-point area with the exact one (kernel/exact_sum.hpp) without
// a tolerance picked by hand. Valid for rings of fewer than 2^32 vertices with
// coordinates in validate()'s range (no underflow or overflow).
double ring_signed_area_error(RingView ring) noexcept;
double rings_area_error(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) noexcept;

enum class Orientation : std::int8_t { clockwise = -1, degenerate = 0, counter_clockwise = 1 };

// Exact orientation of a simple ring (no self-intersection, no repeated
// vertex): the turn at its lowest-then-leftmost vertex, which is convex, as
// orient2d decides it. Degenerate for fewer than three vertices or when that
// turn is straight (a ring of collinear points).
Orientation ring_orientation(RingView ring) noexcept;

// Exact winding number of the ring around p: how many times the ring turns
// counter-clockwise about p (negative for clockwise turns). For p on the ring
// the answer is that of a point an infinitesimal step to the right of p (and
// a yet smaller step up): the faces of a planar subdivision, their outer
// rings counter-clockwise and holes clockwise, then share out the points they
// cover, each to exactly one face (the one on its right). Use locate_in_ring
// to tell points on the ring apart.
int winding_number(RingView ring, Point p) noexcept;

// The winding number of many points about the same rings (a face and its
// holes: the sum over its rings), as winding_number gives it, edge for edge
// the same crossing rule, but each point meets only the edges whose span in
// y holds its height: the edges are filed by rows of y. For the samples of
// a graded decomposition, tested against faces of thousands of coast
// vertices on every split.
class WindingIndex {
public:
  WindingIndex(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings);
  int winding(Point p) const noexcept;

private:
  std::size_t row_of(double y) const noexcept;
  double y0_ = 0.0, y1_ = 0.0, row_height_ = 1.0;
  std::size_t rows_ = 1;
  std::vector<std::uint32_t> first_;  // per row: where its edges start in edges_ (rows_ + 1)
  std::vector<Point> edges_;          // the ends of each filed edge, a then b
};

enum class RingLocation : std::int8_t { outside, on_ring, inside };

// Exact: on_ring when p lies on a vertex or an edge, else inside when the
// winding number is nonzero, outside when it is zero.
RingLocation locate_in_ring(RingView ring, Point p) noexcept;

}  // namespace madd::detail
