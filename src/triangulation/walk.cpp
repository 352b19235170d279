// The walk of the half-edge core: one loop, steered at random or along a line.
#include "triangulation/walk.hpp"

#include "madd/predicates.hpp"
#include "triangulation/cavity.hpp"

namespace madd::detail {

namespace {

// How the walk chooses among the edges p lies strictly beyond.
struct Steering {
  WalkRandom* random = nullptr;  // a visibility walk; nullptr: straight from `from`
  Point from{};
};

// The edge of live triangle t to cross next, or no_index when t holds p.
// `came` (the twin of the edge just crossed) has p on its inner side, so it
// is never tested.
std::uint32_t exit_edge(const HalfEdgeMesh& m, std::span<const Point> P, Point p, std::uint32_t t,
                        std::uint32_t came, Steering& steer) {
  if (steer.random) {
    const std::uint32_t r = steer.random->next_of_three();
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t h = 3 * t + (r + k) % 3;
      if (h != came && orient2d(P[m.origin(h)], P[m.dest(h)], p) < 0) return h;
    }
    return no_index;
  }
  std::uint32_t beyond = no_index;
  for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
    if (h == came) continue;
    const Point u = P[m.origin(h)], v = P[m.dest(h)];
    if (orient2d(u, v, p) >= 0) continue;
    beyond = h;
    if (orient2d(steer.from, p, u) <= 0 && orient2d(steer.from, p, v) >= 0) return h;
  }
  return beyond;  // the line grazes a vertex: any edge p is beyond moves closer
}

// The live, non-ghost triangle holding p in its closure, by a scan.
std::uint32_t scan_for(const HalfEdgeMesh& m, std::span<const Point> P, Point p) {
  for (std::uint32_t u = 0; u < m.slot_count(); ++u) {
    if (!m.alive(u) || (m.ghost != no_index && m.is_ghost(u))) continue;
    bool inside = true;
    for (std::uint32_t h = 3 * u; h < 3 * u + 3 && inside; ++h) inside = orient2d(P[m.origin(h)], P[m.dest(h)], p) >= 0;
    if (inside) return u;
  }
  return no_index;
}

WalkResult walk(const HalfEdgeMesh& m, std::span<const Point> P, Point p, std::uint32_t start, Steering steer) {
  const bool straight = steer.random == nullptr;
  std::uint32_t t = start;
  std::uint32_t came = no_index;
  // Neither walk visits a triangle twice on a Delaunay triangulation; a
  // visibility walk in a constrained one may circle, and ends with
  // probability one: this only bounds bad luck.
  const std::size_t max_steps = 16 * std::size_t{m.slot_count()} + 64;
  for (std::size_t step = 0; step < max_steps; ++step) {
    if (m.ghost != no_index && m.is_ghost(t)) {
      // Outside the hull edge, or back inside across it.
      std::uint32_t h = 3 * t;
      while (m.tv[h] != m.ghost) ++h;
      if (ghost_conflict(P[m.origin(h)], P[m.dest(h)], p)) return {t, no_index};
      came = m.tn[h];
      t = came / 3;
      continue;
    }
    const std::uint32_t h = exit_edge(m, P, p, t, came, steer);
    if (h == no_index) return {t, no_index};
    if (m.tn[h] == no_index || (straight && m.constrained() && m.seg[h] != no_index)) return {no_index, h};
    came = m.tn[h];
    t = came / 3;
  }
  if (straight) return {};
  return {scan_for(m, P, p), no_index};
}

} // namespace

WalkResult walk_visibly(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                        WalkRandom& random) {
  return walk(m, points, p, start, {&random, {}});
}

WalkResult walk_straight(const HalfEdgeMesh& m, std::span<const Point> points, Point p, std::uint32_t start,
                         Point from) {
  return walk(m, points, p, start, {nullptr, from});
}

} // namespace madd::detail
