// Ring geometry: the one implementation of ring area, orientation and point
// location that every stage uses.
#include "kernel/rings.hpp"

#include "kernel/containment.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

// What edge a -> b adds to the winding number around p: the crossings of the
// ray from p towards +x. Half-open in y (an end at p's height counts as above
// the ray), so a vertex the ray passes through is counted once; orient2d
// decides on which side of the edge p lies, and an edge through p is not
// crossed (see winding_number for what that means).
int crossing(Point a, Point b, Point p) noexcept {
  if (a.y <= p.y) return b.y > p.y && orient2d(a, b, p) > 0.0 ? 1 : 0;   // upward, p on its left
  return b.y <= p.y && orient2d(a, b, p) < 0.0 ? -1 : 0;                  // downward, p on its right
}

bool lower_then_lefter(Point a, Point b) noexcept { return a.y < b.y || (a.y == b.y && a.x < b.x); }

} // namespace

double ring_signed_area(RingView ring) noexcept {
  if (ring.size() < 3) return 0.0;
  const Point o = ring[0];
  double twice = 0.0;
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) twice += cross(ring[k] - o, ring[k + 1] - o);
  return 0.5 * twice;
}

double rings_area(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) noexcept {
  double area = 0.0;
  for (const auto& ring : rings) area += ring_signed_area(RingView(points, ring));
  return area;
}

Orientation ring_orientation(RingView ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3) return Orientation::degenerate;
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < n; ++k) {
    if (lower_then_lefter(ring[k], ring[lowest])) lowest = k;
  }
  const double turn = orient2d(ring[(lowest + n - 1) % n], ring[lowest], ring.after(lowest));
  if (turn > 0.0) return Orientation::counter_clockwise;
  return turn < 0.0 ? Orientation::clockwise : Orientation::degenerate;
}

int winding_number(RingView ring, Point p) noexcept {
  int winding = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) winding += crossing(ring[k], ring.after(k), p);
  return winding;
}

RingLocation locate_in_ring(RingView ring, Point p) noexcept {
  int winding = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k], b = ring.after(k);
    if (on_segment(a, b, p)) return RingLocation::on_ring;
    winding += crossing(a, b, p);
  }
  return winding != 0 ? RingLocation::inside : RingLocation::outside;
}

} // namespace madd::detail
