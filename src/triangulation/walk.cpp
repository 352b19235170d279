// The walk of the half-edge core: one loop, steered at random or along a
// line (templates, so that each walk compiles to its own tight loop: this is
// the triangulator's point location, once per point).
#include "triangulation/walk.hpp"

#include <array>
#include <cmath>

#include "madd/predicates.hpp"
#include "triangulation/cavity.hpp"

namespace madd::detail {

namespace {

// orient2d(u, v, p) from the offsets du = u - p and dv = v - p, with
// orient2d's first stage inline: the walk asks this of nearly every edge it
// meets, and nearly every answer is decided by the plain determinant and its
// forward error bound (Shewchuk's ccwerrboundA times |left| + |right|), the
// same test orient2d starts with, so the sign is orient2d's; orient2d
// decides the rest. The magnitude is twice the area of (u, v, p).
inline double side(Point du, Point dv, Point u, Point v, Point p) noexcept {
  const double l = du.x * dv.y, r = du.y * dv.x, det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound || -det > bound) return det;
  return orient2d(u, v, p);
}

inline bool strictly_right_of(Point u, Point v, Point p) noexcept { return side(u - p, v - p, u, v, p) < 0; }

// The three sides of p in triangle c (side i: of the edge opposite corner
// i), from p's offsets to the corners: p's barycentric weights, unnormalised.
inline std::array<double, 3> sides_in(const std::uint32_t* c, const Point* P, Point p) noexcept {
  const Point a = P[c[0]], b = P[c[1]], d = P[c[2]];
  const Point da = a - p, db = b - p, dd = d - p;
  return {side(db, dd, b, d, p), side(dd, da, d, a, p), side(da, db, a, b, p)};
}

// Chooses, in live triangle t, the edge to cross next among those p lies
// strictly beyond, or no_index when t holds p. `came` (the twin of the edge
// just crossed) has p on its inner side, so it is never tested. The random
// state is a local copy while the walk runs, written back at its end.
struct RandomSteering {
  static constexpr bool stops_at_segments = false;
  std::uint32_t state;
  std::uint32_t exit(const std::uint32_t* tv, const Point* P, Point p, std::uint32_t t, std::uint32_t came) {
    state = state * 1103515245u + 12345u;
    const std::uint32_t r = (state >> 16) % 3;
    const std::uint32_t* c = tv + 3 * t;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t i = (r + k) % 3;
      const std::uint32_t h = 3 * t + i;
      if (h != came && strictly_right_of(P[c[i == 2 ? 0 : i + 1]], P[c[i == 0 ? 2 : i - 1]], p)) return h;
    }
    return no_index;
  }
};

// Like RandomSteering, but with all three sides of p computed at once in
// every triangle (from shared offsets), so that where the walk ends they
// are p's weights there: point location that interpolates.
struct WeighingSteering {
  static constexpr bool stops_at_segments = false;
  std::uint32_t state;
  std::uint32_t ended_in = no_index;
  std::array<double, 3> weights{};
  std::uint32_t exit(const std::uint32_t* tv, const Point* P, Point p, std::uint32_t t, std::uint32_t came) {
    weights = sides_in(tv + 3 * t, P, p);
    unsigned beyond = 0;
    for (std::uint32_t i = 0; i < 3; ++i)
      if (weights[i] < 0 && 3 * t + i != came) beyond |= 1u << i;
    if (beyond == 0) {
      ended_in = t;
      return no_index;
    }
    std::uint32_t i = beyond == 1 ? 0 : beyond == 2 ? 1 : beyond == 4 ? 2 : 3;
    if (i == 3) {  // two edges: choose at random
      state = state * 1103515245u + 12345u;
      const std::uint32_t first = (beyond & 1u) ? 0 : 1, other = (beyond & 4u) ? 2 : 1;
      i = (state >> 16) & 1u ? other : first;
    }
    return 3 * t + i;
  }
};

struct LineSteering {
  static constexpr bool stops_at_segments = true;
  Point from;
  std::uint32_t exit(const std::uint32_t* tv, const Point* P, Point p, std::uint32_t t, std::uint32_t came) const {
    std::uint32_t beyond = no_index;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t h = 3 * t + i;
      if (h == came) continue;
      const Point u = P[tv[3 * t + (i + 1) % 3]], v = P[tv[3 * t + (i + 2) % 3]];
      if (orient2d(u, v, p) >= 0) continue;
      beyond = h;
      if (orient2d(from, p, u) <= 0 && orient2d(from, p, v) >= 0) return h;
    }
    return beyond;  // the line grazes a vertex: any edge p is beyond moves closer
  }
};

// The live, non-ghost triangle holding p in its closure, by a scan.
std::uint32_t scan_for(const HalfEdgeMesh& m, const Point* P, Point p) {
  for (std::uint32_t u = 0; u < m.slot_count(); ++u) {
    if (!m.alive(u) || (m.ghost != no_index && m.is_ghost(u))) continue;
    bool inside = true;
    for (std::uint32_t h = 3 * u; h < 3 * u + 3 && inside; ++h) inside = orient2d(P[m.origin(h)], P[m.dest(h)], p) >= 0;
    if (inside) return u;
  }
  return no_index;
}

// `Closed`: the mesh is closed by ghosts (every edge has a twin).
// `Bounded`: give up after a step count no walk needs. A visibility walk on
// a Delaunay triangulation always ends (Edelsbrunner), and an unconstrained
// mesh of the core is one (Bowyer-Watson makes it); on a constrained one it
// may circle, and ends with probability one: the bound only limits bad luck.
template <bool Closed, bool Bounded, class Steering>
WalkResult walk(const HalfEdgeMesh& m, const Point* P, Point p, std::uint32_t start, Steering& steer) {
  const std::uint32_t* tv = m.tv.data();
  const std::uint32_t* tn = m.tn.data();
  const std::uint32_t* seg = Steering::stops_at_segments && m.constrained() ? m.seg.data() : nullptr;
  const std::uint32_t ghost = m.ghost;
  std::uint32_t t = start;
  std::uint32_t came = no_index;
  std::size_t steps_left = 16 * std::size_t{m.slot_count()} + 64;
  while (!Bounded || steps_left-- > 0) {
    if (Closed) {
      const std::uint32_t* c = tv + 3 * t;
      const std::uint32_t gi = c[0] == ghost ? 0 : c[1] == ghost ? 1 : c[2] == ghost ? 2 : 3;
      if (gi < 3) {
        // Outside the hull edge (stop), or back inside across it.
        const std::uint32_t h = 3 * t + gi;
        if (ghost_conflict(P[tv[next_half_edge(h)]], P[tv[prev_half_edge(h)]], p)) return {t, no_index};
        came = tn[h];
        t = came / 3;
        continue;
      }
    }
    const std::uint32_t h = steer.exit(tv, P, p, t, came);
    if (h == no_index) return {t, no_index};
    if ((!Closed && tn[h] == no_index) || (seg && seg[h] != no_index)) return {no_index, h};
    came = tn[h];
    t = came / 3;
  }
  if (Steering::stops_at_segments) return {};
  return {scan_for(m, P, p), no_index};
}

}  // namespace

WalkResult walk_visibly(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                        WalkRandom& random) {
  RandomSteering steer{random.state};
  const WalkResult result = m.ghost == no_index ? walk<false, true>(m, points.data(), p, start, steer)
                            : m.constrained()   ? walk<true, true>(m, points.data(), p, start, steer)
                                                : walk<true, false>(m, points.data(), p, start, steer);
  random.state = steer.state;
  return result;
}

WalkResult walk_weighing(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         WalkRandom& random, std::array<double, 3>& weights) {
  WeighingSteering steer{random.state};
  const WalkResult result = m.ghost == no_index ? walk<false, true>(m, points.data(), p, start, steer)
                            : m.constrained()   ? walk<true, true>(m, points.data(), p, start, steer)
                                                : walk<true, false>(m, points.data(), p, start, steer);
  random.state = steer.state;
  if (result.triangle != no_index)
    weights =
        result.triangle == steer.ended_in ? steer.weights : sides_in(&m.tv[3 * result.triangle], points.data(), p);
  return result;
}

WalkResult walk_straight(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         Point from) {
  LineSteering steer{from};
  return m.ghost != no_index ? walk<true, true>(m, points.data(), p, start, steer)
                             : walk<false, true>(m, points.data(), p, start, steer);
}

}  // namespace madd::detail
