// The coast pieces near each background triangle close to the coast
// (coast_candidates.hpp).
#include "sizing/coast_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "sizing/distance_bound.hpp"

namespace madd::detail {

// Keeps of `near` the pieces that can be nearest somewhere in triangle t.
// Each piece s bounds d on T from above by max over the corners of d_s (a
// convex function is largest at a corner); a piece farther from T than the
// least of those bounds is never nearest there. T crosses no coast piece
// (they are constrained edges of the background), so the distance between
// a piece and T is that between a corner of one and an edge of the other.
void CoastCandidates::prune(const SizeBackground& bg, std::uint32_t t, std::vector<std::uint32_t>& near) const {
  const auto& v = bg.triangles[t];
  const Point p[3] = {bg.points[v[0]], bg.points[v[1]], bg.points[v[2]]};
  double bound = std::numeric_limits<double>::infinity(), u = 0.0;
  for (const std::uint32_t s : near) {
    const auto& e = ends_[s];
    bound = std::min(bound, std::max({segment_distance(p[0], e[0], e[1], u), segment_distance(p[1], e[0], e[1], u),
                                      segment_distance(p[2], e[0], e[1], u)}));
  }
  const double scale = std::max({std::abs(p[0].x), std::abs(p[0].y), bound});
  bound = bound * (1.0 + 1e-9) + 1e-12 * scale;  // over the rounding of both sides
  std::erase_if(near, [&](std::uint32_t s) {
    const auto& e = ends_[s];
    double gap = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const Point a = p[i], b = p[(i + 1) % 3];
      gap = std::min(
          {gap, segment_distance(a, e[0], e[1], u), segment_distance(e[0], a, b, u), segment_distance(e[1], a, b, u)});
    }
    return gap > bound;
  });
}

CoastCandidates::CoastCandidates(const SizeBackground& bg, std::span<const RawSample> samples, const Coast& coast) {
  const auto n = static_cast<std::uint32_t>(bg.triangles.size());
  for (std::uint32_t s = 0; s < coast.coast_index.size(); ++s) {
    const std::array<Point, 2>& e = coast.coast_index.ends(s);
    ends_.push_back(e);
    const Point ab = e[1] - e[0];
    pieces_.push_back({e[0], ab, 1.0 / dot(ab, ab)});  // pieces have length > 0 (validate)
  }
  start_.assign(n + 1, 0);
  std::vector<std::uint32_t> near;
  for (std::uint32_t t = 0; t < n; ++t) {
    start_[t] = static_cast<std::uint32_t>(piece_.size());
    if (bg.inside[t] == 0) continue;
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
    prune(bg, t, near);
    piece_.insert(piece_.end(), near.begin(), near.end());
  }
  start_[n] = static_cast<std::uint32_t>(piece_.size());
}

std::size_t CoastCandidates::exact_triangles() const noexcept {
  std::size_t count = 0;
  for (std::uint32_t t = 0; t + 1 < start_.size(); ++t) count += exact(t) ? 1 : 0;
  return count;
}

}  // namespace madd::detail
