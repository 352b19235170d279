// The gradation limiter (gradation.hpp).
#include "sizing/gradation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace madd::detail {

namespace {

// The inside edges and triangles around each point (CSR). Triangles wider
// than 120 degrees are not checked: their edges are held to the slope that
// makes them safe (a needle's gradient is steered by rounding-size value
// differences, and flattening it corner by corner converges too slowly to
// be worth it); the others are checked and flattened.
struct Adjacency {
  std::vector<std::uint32_t> edge_start, edge_to, tri_start, tri;
  std::vector<double> slope;          // the main pass's slope limit per edge entry
  std::vector<double> safe_slope;     // the fallback's: rate cos(alpha / 2), alpha the widest angle at the edge
  std::vector<double> triangle_safe;  // per triangle: rate cos(alpha / 2), alpha its widest angle
};

Adjacency adjacency(const SizeBackground& bg, double rate) {
  struct Edge {
    std::uint32_t to;
    double slope, safe;
  };
  const std::size_t n = bg.points.size();
  Adjacency a;
  a.triangle_safe.assign(bg.triangles.size(), rate);
  // Each inside triangle's safe slope and whether it is wide, then the
  // entries of every point counted, placed (triangles in order) and each
  // point's edges sorted by their other end, a repeated edge taking the
  // stricter of its two triangles: compressed rows, no list per point.
  std::vector<std::uint8_t> wide(bg.triangles.size(), 0);
  std::vector<std::uint32_t> edge_first(n + 1, 0), tri_first(n + 1, 0);
  for (std::uint32_t t = 0; t < bg.triangles.size(); ++t) {
    if (bg.inside[t] == 0) continue;
    const auto& v = bg.triangles[t];
    const Point p[3] = {bg.points[v[0]], bg.points[v[1]], bg.points[v[2]]};
    double widest = 0.0;
    for (int i = 0; i < 3; ++i) widest = std::max(widest, angle_at(p[i], p[(i + 1) % 3], p[(i + 2) % 3]));
    a.triangle_safe[t] = rate * std::cos(0.5 * widest);
    wide[t] = widest > radians(120.0) ? 1 : 0;
    for (const std::uint32_t u : v) {
      edge_first[u + 1] += 2;
      tri_first[u + 1] += wide[t] == 0 ? 1 : 0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    edge_first[i + 1] += edge_first[i];
    tri_first[i + 1] += tri_first[i];
  }
  std::vector<Edge> edges(edge_first[n]);
  a.tri.resize(tri_first[n]);
  std::vector<std::uint32_t> edge_at(edge_first.begin(), edge_first.end() - 1);
  std::vector<std::uint32_t> tri_at(tri_first.begin(), tri_first.end() - 1);
  for (std::uint32_t t = 0; t < bg.triangles.size(); ++t) {
    if (bg.inside[t] == 0) continue;
    const auto& v = bg.triangles[t];
    const double safe = a.triangle_safe[t];
    for (int i = 0; i < 3; ++i) {
      if (wide[t] == 0) a.tri[tri_at[v[i]]++] = t;
      for (const std::uint32_t u : {v[(i + 1) % 3], v[(i + 2) % 3]})
        edges[edge_at[v[i]]++] = {u, wide[t] != 0 ? safe : rate, safe};
    }
  }
  a.tri_start = std::move(tri_first);
  a.edge_start.reserve(n + 1);
  a.edge_start.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto begin = edges.begin() + edge_first[i], end = edges.begin() + edge_first[i + 1];
    std::sort(begin, end, [](const Edge& x, const Edge& y) { return x.to < y.to; });
    for (auto e = begin; e != end; ++e) {
      if (e != begin && e->to == (e - 1)->to) {  // the stricter of its two triangles
        a.slope.back() = std::min(a.slope.back(), e->slope);
        a.safe_slope.back() = std::min(a.safe_slope.back(), e->safe);
        continue;
      }
      a.edge_to.push_back(e->to);
      a.slope.push_back(e->slope);
      a.safe_slope.push_back(e->safe);
    }
    a.edge_start.push_back(static_cast<std::uint32_t>(a.edge_to.size()));
  }
  return a;
}

struct Gradient {
  Point g;
  Point hat[3];  // gradients of the corners' barycentric coordinates
};

Gradient gradient(const SizeBackground& bg, std::uint32_t t, const std::vector<double>& f) {
  const auto& v = bg.triangles[t];
  const Point p0 = bg.points[v[0]], p1 = bg.points[v[1]], p2 = bg.points[v[2]];
  const double det = cross(p1 - p0, p2 - p0);
  Gradient out;
  out.hat[0] = (1.0 / det) * Point{p1.y - p2.y, p2.x - p1.x};
  out.hat[1] = (1.0 / det) * Point{p2.y - p0.y, p0.x - p2.x};
  out.hat[2] = (1.0 / det) * Point{p0.y - p1.y, p1.x - p0.x};
  out.g = f[v[0]] * out.hat[0] + f[v[1]] * out.hat[1] + f[v[2]] * out.hat[2];
  return out;
}

using Queue = std::priority_queue<std::pair<double, std::uint32_t>, std::vector<std::pair<double, std::uint32_t>>,
                                  std::greater<>>;

// Lowers the corner of inside triangle t that flattens it to slope `rate`;
// returns that corner, or no_index when t is flat enough (or unbounded).
std::uint32_t flatten(const SizeBackground& bg, std::uint32_t t, std::vector<double>& f, double rate) {
  const auto& v = bg.triangles[t];
  if (!std::isfinite(f[v[0]] + f[v[1]] + f[v[2]])) return no_index;
  const Gradient gr = gradient(bg, t, f);
  const double g2 = dot(gr.g, gr.g);
  if (g2 <= rate * rate) return no_index;
  int c = 0;
  for (int i = 1; i < 3; ++i)
    if (dot(gr.g, gr.hat[i]) > dot(gr.g, gr.hat[c])) c = i;
  const double along = dot(gr.g, gr.hat[c]), hat2 = dot(gr.hat[c], gr.hat[c]);
  if (!(along > 0.0)) return no_index;
  // The smallest s > 0 with |g - s hat| = rate (or, past rounding, the flattest).
  const double disc = along * along - hat2 * (g2 - rate * rate);
  const double s = disc > 0.0 ? (along - std::sqrt(disc)) / hat2 : along / hat2;
  // Never below the lower of the other two corners: a needle whose short
  // edge is steeper than the rate asks for any depth (the Gulf of Finland's
  // background reached -0.0017 with hmin 0.12, and the field read sides of
  // 1e-5 there). What flattening cannot do, the held slopes and the final
  // edge pass do, without going below the values they start from.
  const double lowest = std::min(f[v[(c + 1) % 3]], f[v[(c + 2) % 3]]);
  const double lowered = std::max(f[v[c]] - s * (1.0 + 1e-12), lowest);
  if (!(lowered < f[v[c]])) return no_index;
  f[v[c]] = lowered;
  return v[c];
}

// Dijkstra with each edge's slope limited to its fallback slope: ends the
// limiter with a provable result.
void edge_limited(const SizeBackground& bg, const Adjacency& a, std::vector<double>& f) {
  Queue queue;
  for (std::uint32_t i = 0; i < f.size(); ++i)
    if (std::isfinite(f[i]) && a.edge_start[i + 1] > a.edge_start[i]) queue.push({f[i], i});
  while (!queue.empty()) {
    const auto [value, v] = queue.top();
    queue.pop();
    if (value != f[v]) continue;
    for (std::uint32_t k = a.edge_start[v]; k < a.edge_start[v + 1]; ++k) {
      const std::uint32_t u = a.edge_to[k];
      const double limit = f[v] + a.safe_slope[k] * (1.0 - 1e-9) * distance(bg.points[v], bg.points[u]);
      if (limit < f[u]) f[u] = limit, queue.push({limit, u});
    }
  }
}

// Holds the edges of triangle t to its safe slope from now on (it is then
// within the rate whatever its corners become) and requeues its corners so
// that the edges are enforced: the end of a triangle flattened too often.
void hold_to_safe_slope(const SizeBackground& bg, Adjacency& a, std::uint32_t t, const std::vector<double>& f,
                        Queue& queue) {
  const auto& v = bg.triangles[t];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      for (std::uint32_t k = a.edge_start[v[i]]; k < a.edge_start[v[i] + 1]; ++k)
        if (a.edge_to[k] == v[j]) a.slope[k] = std::min(a.slope[k], a.triangle_safe[t]);
    }
    queue.push({f[v[i]], v[i]});
  }
}

}  // namespace

GradationReport limit_gradation(SizeBackground& bg, double rate) {
  GradationReport report;
  Adjacency a = adjacency(bg, rate);
  // Flattening a needle can ping-pong with its neighbour across the short
  // edge, each lowering the shared corners by a shrinking fraction: after
  // this many flattenings a triangle is held to its safe slope instead.
  constexpr std::uint8_t max_flattenings = 4;
  std::vector<std::uint8_t> flattened(bg.triangles.size(), 0);
  std::vector<double>& f = bg.edge;
  const double headroom = 1.0 - 1e-9;  // against the rounding of a gradient
  const double slope = rate * headroom;
  Queue queue;
  for (std::uint32_t i = 0; i < f.size(); ++i)
    if (std::isfinite(f[i]) && a.edge_start[i + 1] > a.edge_start[i]) queue.push({f[i], i});
  const std::size_t max_pops = 64 * f.size() + 1024;
  while (!queue.empty()) {
    if (++report.pops > max_pops) {
      report.fell_back = true;
      edge_limited(bg, a, f);
      return report;
    }
    const auto [value, v] = queue.top();
    queue.pop();
    if (value != f[v]) continue;  // lowered since it was queued
    for (std::uint32_t k = a.edge_start[v]; k < a.edge_start[v + 1]; ++k) {
      const std::uint32_t u = a.edge_to[k];
      const double limit = f[v] + a.slope[k] * headroom * distance(bg.points[v], bg.points[u]);
      if (limit < f[u]) f[u] = limit, queue.push({limit, u});
    }
    for (std::uint32_t k = a.tri_start[v]; k < a.tri_start[v + 1]; ++k) {
      const std::uint32_t t = a.tri[k];
      if (flattened[t] > max_flattenings) continue;  // held to its safe slope
      if (flattened[t] == max_flattenings) {
        const auto& c = bg.triangles[t];
        if (!std::isfinite(f[c[0]] + f[c[1]] + f[c[2]]) || length(gradient(bg, t, f).g) <= slope) continue;
        ++flattened[t];
        ++report.held_triangles;
        hold_to_safe_slope(bg, a, t, f, queue);
        continue;
      }
      const std::uint32_t lowered = flatten(bg, t, f, slope);
      if (lowered == no_index) continue;
      ++flattened[t];
      ++report.triangle_fixes;
      queue.push({f[lowered], lowered});
    }
  }
  // The queue ran dry: every edge is within the slope, and every triangle was
  // flattened when its last corner left the queue. Rounding can still leave a
  // hair too steep a triangle: the provable pass then finishes.
  if (steepest_gradient(bg) > rate) {
    report.fell_back = true;
    edge_limited(bg, a, f);
  }
  return report;
}

double steepest_gradient(const SizeBackground& bg) {
  double steepest = 0.0;
  for (std::uint32_t t = 0; t < bg.triangles.size(); ++t) {
    const auto& v = bg.triangles[t];
    if (bg.inside[t] == 0 || !std::isfinite(bg.edge[v[0]] + bg.edge[v[1]] + bg.edge[v[2]])) continue;
    steepest = std::max(steepest, length(gradient(bg, t, bg.edge).g));
  }
  return steepest;
}

}  // namespace madd::detail
