// The walk of the half-edge core: one loop, steered at random or along a
// line (templates, so that each walk compiles to its own tight loop: this is
// the triangulator's point location, once per point).
#include "triangulation/walk.hpp"

#include "madd/predicates.hpp"
#include "triangulation/cavity.hpp"

namespace madd::detail {

namespace {

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
      if (h != came && orient2d(P[c[i == 2 ? 0 : i + 1]], P[c[i == 0 ? 2 : i - 1]], p) < 0) return h;
    }
    return no_index;
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

WalkResult walk_straight(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         Point from) {
  LineSteering steer{from};
  return m.ghost != no_index ? walk<true, true>(m, points.data(), p, start, steer)
                             : walk<false, true>(m, points.data(), p, start, steer);
}

}  // namespace madd::detail
