// The coast pieces near each background triangle close to the coast
// (coast_candidates.hpp).
#include "sizing/coast_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "kernel/threads.hpp"
#include "sizing/distance_bound.hpp"

namespace madd::detail {

// Keeps of `near` the pieces that can be nearest somewhere in triangle p.
// Each piece s bounds d on T from above by max over the corners of d_s (a
// convex function is largest at a corner); a piece farther from T than the
// least of those bounds is never nearest there. T crosses no coast piece
// (they are constrained edges of the background), so the distance between
// a piece and T is that between a corner of one and an edge of the other.
void CoastCandidates::prune(const Point (&p)[3], std::vector<std::uint32_t>& near) const {
  if (near.empty()) return;
  // The bound from the pieces nearest to the centroid (any piece gives one;
  // these give about the least), then the cheap test of a piece's distance
  // to the centroid less the centroid's reach, then the exact one.
  const Point g = triangle_centroid(p[0], p[1], p[2]);
  const double reach = std::max({madd::distance(g, p[0]), madd::distance(g, p[1]), madd::distance(g, p[2])});
  std::vector<std::pair<double, std::uint32_t>> by_centre;
  by_centre.reserve(near.size());
  for (const std::uint32_t s : near) by_centre.push_back({segment_distance(g, ends_[s][0], ends_[s][1]), s});
  const std::size_t few = std::min<std::size_t>(4, by_centre.size());
  std::partial_sort(by_centre.begin(), by_centre.begin() + static_cast<std::ptrdiff_t>(few), by_centre.end());
  double bound = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < few; ++k) {
    const auto& e = ends_[by_centre[k].second];
    bound = std::min(bound, std::max({segment_distance(p[0], e[0], e[1]), segment_distance(p[1], e[0], e[1]),
                                      segment_distance(p[2], e[0], e[1])}));
  }
  const double scale = std::max({std::abs(p[0].x), std::abs(p[0].y), bound});
  bound = bound * (1.0 + 1e-9) + 1e-12 * scale;  // over the rounding of both sides
  const double margin = 1e-9 * (reach + bound) + 1e-12 * scale;
  near.clear();
  for (const auto& [to_centre, s] : by_centre) {
    if (to_centre - reach > bound + margin) continue;  // every point of T is within `reach` of g
    const auto& e = ends_[s];
    double gap = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const Point a = p[i], b = p[(i + 1) % 3];
      gap =
          std::min({gap, segment_distance(a, e[0], e[1]), segment_distance(e[0], a, b), segment_distance(e[1], a, b)});
    }
    if (gap <= bound) near.push_back(s);
  }
  std::sort(near.begin(), near.end());
}

namespace {

// Per point: the inside triangles with a corner there.
std::vector<std::vector<std::uint32_t>> inside_triangles_around(const SizeBackground& bg) {
  std::vector<std::vector<std::uint32_t>> out(bg.points.size());
  for (std::uint32_t t = 0; t < bg.triangles.size(); ++t)
    if (bg.inside[t] != 0)
      for (const std::uint32_t v : bg.triangles[t]) out[v].push_back(t);
  return out;
}

// list(t, near) for every triangle t < n, `near` cleared before each: the
// lists joined in triangle order, count[t] the length of t's. In chunks of
// triangles on `threads` threads, each chunk into its own list: the same
// result for any count.
template <typename List>
std::vector<std::uint32_t> in_chunks(std::uint32_t n, unsigned threads, std::vector<std::uint32_t>& count,
                                     const List& list) {
  constexpr std::uint32_t chunk = 2048;
  const std::uint32_t chunks = (n + chunk - 1) / chunk;
  std::vector<std::vector<std::uint32_t>> joined(chunks);
  for_each_on_threads(chunks, threads, [&](std::size_t c) {
    std::vector<std::uint32_t> near;
    const auto begin = static_cast<std::uint32_t>(c * chunk);
    const std::uint32_t end = std::min(n, begin + chunk);
    for (std::uint32_t t = begin; t < end; ++t) {
      near.clear();
      list(t, near);
      count[t] = static_cast<std::uint32_t>(near.size());
      joined[c].insert(joined[c].end(), near.begin(), near.end());
    }
  });
  std::size_t total = 0;
  for (const std::vector<std::uint32_t>& part : joined) total += part.size();
  std::vector<std::uint32_t> out;
  out.reserve(total);
  for (const std::vector<std::uint32_t>& part : joined) out.insert(out.end(), part.begin(), part.end());
  return out;
}

}  // namespace

CoastCandidates::CoastCandidates(const SizeBackground& bg, std::span<const RawSample> samples, const Coast& coast,
                                 unsigned threads) {
  const auto n = static_cast<std::uint32_t>(bg.triangles.size());
  for (std::uint32_t s = 0; s < coast.coast_index.size(); ++s) {
    const std::array<Point, 2>& e = coast.coast_index.ends(s);
    ends_.push_back(e);
    const Point ab = e[1] - e[0];
    pieces_.push_back({e[0], ab, 1.0 / dot(ab, ab)});  // pieces have length > 0 (validate)
  }
  // The inside triangles' lists (pass 1), then the outside ones' with a
  // corner on an inside triangle (pass 2), each in chunks of triangles on
  // the threads, the chunks' lists joined in triangle order.
  std::vector<std::uint32_t> count(n, 0);
  const std::vector<std::uint32_t> pieces = in_chunks(n, threads, count, [&](std::uint32_t t, auto& near) {
    if (bg.inside[t] == 0) return;
    const auto& v = bg.triangles[t];
    const TriangleBound bound = triangle_bound(bg, samples, t);
    double reach = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const Point p = bg.points[v[i]];
      const double longest =
          std::max(madd::distance(p, bg.points[v[(i + 1) % 3]]), madd::distance(p, bg.points[v[(i + 2) % 3]]));
      reach = std::min(reach, samples[v[i]].distance + longest);
    }
    // A relative margin over the rounding of the distances and the circle.
    const double radius = (reach + bound.rho) * (1.0 + 1e-9) + 1e-12 * length(bound.centre);
    coast.coast_index.within(bound.centre, radius, ends_.size(), near);
    const Point c[3] = {bg.points[v[0]], bg.points[v[1]], bg.points[v[2]]};
    prune(c, near);
  });
  std::vector<std::uint32_t> first(std::size_t{n} + 1, 0);
  for (std::uint32_t t = 0; t < n; ++t) first[t + 1] = first[t] + count[t];
  // An outside triangle with a corner on the water reads the pieces of the
  // inside triangles around its water corners. A point on the coast, or a
  // rounding off it onto the land (the decoupling's split points, a
  // separator's end), is within that rounding e of one of them, and its
  // distance from their pieces is within 2 e of d: it reads hmin + G d as
  // from the water beside it. (The linear part alone, which the land does
  // not grade, read hmax at a separator's end on the coast: its first piece
  // was 45 x too long for the triangles beside it, and refinement stopped
  // there.) Deeper in the land the value is of no use and no harm.
  const std::vector<std::vector<std::uint32_t>> water_around = inside_triangles_around(bg);
  piece_ = in_chunks(n, threads, count, [&](std::uint32_t t, auto& near) {
    if (bg.inside[t] != 0) {
      near.assign(pieces.begin() + first[t], pieces.begin() + first[t + 1]);
      return;
    }
    for (const std::uint32_t v : bg.triangles[t])
      for (const std::uint32_t u : water_around[v])
        near.insert(near.end(), pieces.begin() + first[u], pieces.begin() + first[u + 1]);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
  });
  start_.assign(std::size_t{n} + 1, 0);
  for (std::uint32_t t = 0; t < n; ++t) start_[t + 1] = start_[t] + count[t];
}

std::size_t CoastCandidates::exact_triangles() const noexcept {
  std::size_t count = 0;
  for (std::uint32_t t = 0; t + 1 < start_.size(); ++t) count += exact(t) ? 1 : 0;
  return count;
}

}  // namespace madd::detail
