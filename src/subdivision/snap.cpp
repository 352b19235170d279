// EndSnap (subdivision.hpp): whether a separator end inside a segment may
// move to a vertex of that segment at commit. Everything is checked on the
// geometry being committed, so a snap can never break a rule the split met.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "kernel/angles.hpp"
#include "kernel/containment.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

namespace {

constexpr double angle_margin_deg = 1e-6;  // above check_new_angles' tolerance
constexpr double straight_tolerance_deg = 1e-6;

// The edges of a centre in counter-clockwise order, as indices into `ends`.
std::vector<std::size_t> ccw_order(Point centre, const std::vector<Point>& ends) {
  std::vector<std::size_t> order(ends.size());
  std::iota(order.begin(), order.end(), 0);
  const auto angle = [&](std::size_t k) { return std::atan2(ends[k].y - centre.y, ends[k].x - centre.x); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return angle(a) < angle(b); });
  return order;
}

// The same cyclic sequence, up to rotation.
bool same_cycle(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  const auto start = std::find(b.begin(), b.end(), a[0]);
  if (start == b.end()) return false;
  std::vector<std::size_t> rotated(start, b.end());
  rotated.insert(rotated.end(), b.begin(), start);
  return rotated == a;
}

// The ring neighbours of vertex v in `face`: {prev, next}, or no_index.
std::array<std::uint32_t, 2> ring_neighbours(const Face& face, std::uint32_t v) {
  for (const auto& ring : face.rings) {
    const auto it = std::find(ring.begin(), ring.end(), v);
    if (it == ring.end()) continue;
    const auto k = static_cast<std::size_t>(it - ring.begin());
    return {ring[(k + ring.size() - 1) % ring.size()], ring[(k + 1) % ring.size()]};
  }
  return {no_index, no_index};
}

// The face's corner at `at` (from next round to prev, counter-clockwise) holds
// direction at -> q with both angles >= phi.
bool splits_corner(Point at, Point prev, Point next, Point q, double phi) {
  const double corner = ccw_angle_deg(at, next, prev);
  const double a1 = ccw_angle_deg(at, next, q), a2 = ccw_angle_deg(at, q, prev);
  return a1 >= phi && a2 >= phi && std::abs(a1 + a2 - corner) <= straight_tolerance_deg;
}

}  // namespace

bool Subdivision::far_angles_hold(const SnapEdge& edge, Point from, Point to, double phi) const {
  const EndRef& far = edge.far;
  if (far.kind == EndRef::centre) {
    // Its edges keep their order and every angle between two stays >= phi.
    std::vector<Point> moved = edge.far_ends;
    const auto self = std::find(moved.begin(), moved.end(), from);
    if (self == moved.end()) return false;
    *self = to;
    const std::vector<std::size_t> order = ccw_order(far.p, moved);
    if (!same_cycle(ccw_order(far.p, edge.far_ends), order)) return false;
    for (std::size_t k = 0; k < order.size() && order.size() > 1; ++k) {
      if (ccw_angle_deg(far.p, moved[order[k]], moved[order[(k + 1) % order.size()]]) < phi) return false;
    }
    return true;
  }
  if (far.kind == EndRef::vertex) {
    const auto [prev, next] = ring_neighbours(faces[edge.face], far.id);
    return prev != no_index && splits_corner(far.p, points[prev], points[next], to, phi);
  }
  // Inside a straight segment: both angles with its line.
  const Point a = points[segments[far.id].a], b = points[segments[far.id].b];
  const double one = degrees(angle_at(far.p, a, to)), other = degrees(angle_at(far.p, b, to));
  return one >= phi && other >= phi;
}

bool Subdivision::may_snap(std::uint32_t v, const EndRef& end, const SnapEdge& edge) const {
  const SplitResult& split = *edge.split;
  const Point to = points[v];
  if (!(distance(end.p, to) < split.snap.distance)) return false;
  // No other end of the split may use the vertex (two ends at one point would pinch).
  if (std::find(edge.taken.begin(), edge.taken.end(), v) != edge.taken.end()) return false;
  for (const SeparatorEdge& e : split.edges) {
    for (const EndRef* r : {&e.a, &e.b}) {
      if ((r->kind == EndRef::vertex && r->id == v) || r->p == to) return false;
    }
  }
  // The vertex is on a ring of the face where the ring runs straight, and
  // the edge splits that straight corner into two angles >= Phi0.
  const auto [prev, next] = ring_neighbours(faces[edge.face], v);
  if (prev == no_index) return false;
  if (std::abs(ccw_angle_deg(to, points[next], points[prev]) - 180.0) > straight_tolerance_deg) return false;
  const double phi = split.snap.separator_angle_deg + angle_margin_deg;
  if (!splits_corner(to, points[prev], points[next], edge.far.p, phi)) return false;
  if (!far_angles_hold(edge, end.p, to, phi)) return false;
  // Nothing in the triangle the edge sweeps: no vertex of the face, no point of the split.
  const auto in_swept = [&](Point q) { return in_closed_triangle(edge.far.p, end.p, to, q); };
  for (const auto& ring : faces[edge.face].rings) {
    for (const std::uint32_t w : ring) {
      if (w != v && points[w] != edge.far.p && in_swept(points[w])) return false;
    }
  }
  for (const SeparatorEdge& e : split.edges) {
    for (const Point q : {e.a.p, e.b.p}) {
      if (q != edge.far.p && q != end.p && in_swept(q)) return false;
    }
  }
  return !in_swept(split.interior[0]) && !in_swept(split.interior[1]);
}

}  // namespace madd::detail
