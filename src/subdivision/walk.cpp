// The planar face walk shared by the initial ring tracing and every commit.
#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

namespace {

// 0 for directions with angle in [0, pi), 1 for [pi, 2pi). The sign of a
// difference of two doubles is exact, so this needs no predicate.
int half_of(Point origin, Point to) {
  const double dy = to.y - origin.y;
  const double dx = to.x - origin.x;
  return (dy > 0.0 || (dy == 0.0 && dx > 0.0)) ? 0 : 1;
}

// Strict counter-clockwise order of the directions origin->p and origin->q,
// starting from the positive x axis.
bool before(Point origin, Point p, Point q) {
  const int hp = half_of(origin, p);
  const int hq = half_of(origin, q);
  if (hp != hq) return hp < hq;
  return orient2d(origin, p, q) > 0.0;
}

// A boundary walk passes a vertex twice where a hole ring touches the outer
// ring (or another hole) at that vertex. Cutting the walk there gives simple
// rings: the counter-clockwise one is the outer ring, the others are holes.
void split_at_repeated_vertices(const std::vector<HalfEdge>& half_edges, const std::vector<std::uint32_t>& cycle,
                                std::vector<std::vector<std::uint32_t>>& out) {
  std::vector<std::uint32_t> stack;
  std::unordered_map<std::uint32_t, std::size_t> position;  // vertex -> index in stack of the edge leaving it
  for (std::uint32_t h : cycle) {
    const std::uint32_t v = half_edges[h].from;
    auto it = position.find(v);
    if (it != position.end()) {
      const std::size_t at = it->second;
      std::vector<std::uint32_t> loop(stack.begin() + static_cast<std::ptrdiff_t>(at), stack.end());
      for (std::uint32_t e : loop) position.erase(half_edges[e].from);
      stack.resize(at);
      out.push_back(std::move(loop));
    }
    position[v] = stack.size();
    stack.push_back(h);
  }
  out.push_back(std::move(stack));
}

}  // namespace

std::vector<std::vector<std::uint32_t>> walk_faces(const std::vector<Point>& points,
                                                   const std::vector<HalfEdge>& half_edges) {
  const auto count = static_cast<std::uint32_t>(half_edges.size());
  // Outgoing half-edges grouped by origin, each group in counter-clockwise order.
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    const HalfEdge& ex = half_edges[x];
    const HalfEdge& ey = half_edges[y];
    if (ex.from != ey.from) return ex.from < ey.from;
    const Point o = points[ex.from];
    if (before(o, points[ex.to], points[ey.to])) return true;
    if (before(o, points[ey.to], points[ex.to])) return false;
    return x < y;
  });
  auto group_of = [&](std::uint32_t vertex) {
    auto lo = std::lower_bound(order.begin(), order.end(), vertex,
                               [&](std::uint32_t h, std::uint32_t v) { return half_edges[h].from < v; });
    auto hi = lo;
    while (hi != order.end() && half_edges[*hi].from == vertex) ++hi;
    return std::pair{lo, hi};
  };
  std::vector<std::uint32_t> next(count, no_index);
  for (std::uint32_t h = 0; h < count; ++h) {
    const std::uint32_t v = half_edges[h].to;
    auto [lo, hi] = group_of(v);
    if (lo == hi) throw DecompositionError("planar subdivision has a dangling edge (internal error)");
    if (hi - lo == 1) {
      next[h] = *lo;
      continue;
    }
    // First outgoing edge clockwise from the way back: the last one strictly
    // before the direction v->from in counter-clockwise order (cyclically).
    const Point o = points[v];
    const Point back = points[half_edges[h].from];
    auto pos = std::partition_point(lo, hi, [&](std::uint32_t e) { return before(o, points[half_edges[e].to], back); });
    next[h] = (pos == lo) ? *(hi - 1) : *(pos - 1);
  }
  std::vector<std::vector<std::uint32_t>> cycles;
  std::vector<std::uint8_t> used(count, 0);
  for (std::uint32_t start = 0; start < count; ++start) {
    if (used[start]) continue;
    std::vector<std::uint32_t> cycle;
    std::uint32_t h = start;
    while (!used[h]) {
      used[h] = 1;
      cycle.push_back(h);
      h = next[h];
    }
    if (h != start) throw DecompositionError("planar subdivision walk did not close (internal error)");
    split_at_repeated_vertices(half_edges, cycle, cycles);
  }
  return cycles;
}

}  // namespace madd::detail
