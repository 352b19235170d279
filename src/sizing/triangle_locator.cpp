// Point location by a grid of start triangles and the core's visibility
// walk (triangle_locator.hpp).
#include "sizing/triangle_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "triangulation/walk.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool finite_point(Point p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

// (b - p) x (c - p), the sign exact: orient2d(b, c, p) computed the same
// way up to its first filter, which is inline here (the walk's hot path);
// orient2d itself decides when that stage cannot. |l| + |r| bounds
// Shewchuk's detsum, so the filter is never looser than orient2d's.
inline double side(Point db, Point dc, Point b, Point c, Point p) noexcept {
  const double l = db.x * dc.y, r = db.y * dc.x, det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound || -det > bound) return det;
  return orient2d(b, c, p);
}

}  // namespace

namespace {

// The view's triangles as the core's arrays: corners in order, and each
// edge's twin found among the neighbour's edges (the same two corners the
// other way round).
HalfEdgeMesh half_edges_of(const TriangleView& view) {
  HalfEdgeMesh m;
  const auto count = static_cast<std::uint32_t>(view.triangles.size());
  m.append_slots(count);
  m.tv.resize(3 * std::size_t{count});
  m.tn.resize(3 * std::size_t{count});
  for (std::uint32_t t = 0; t < count; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) m.tv[3 * t + i] = view.triangles[t][i];
  for (std::uint32_t t = 0; t < count; ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t u = view.neighbours[t][i];
      m.tn[3 * t + i] = no_index;
      if (u == no_index) continue;
      const std::uint32_t to = view.triangles[t][(i + 2) % 3];  // the edge runs the other way in u
      for (std::uint32_t j = 0; j < 3; ++j)
        if (view.triangles[u][(j + 1) % 3] == to) m.tn[3 * t + i] = 3 * u + j;
    }
  return m;
}

}  // namespace

TriangleLocator::TriangleLocator(const TriangleView& view) {
  if (view.triangles.empty()) return;
  mesh_ = half_edges_of(view);
  Point lo{infinity, infinity}, hi{-infinity, -infinity};
  for (const auto& t : view.triangles)
    for (const std::uint32_t v : t) {
      const Point p = view.points[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  // Square cells, about one per triangle: a walk from a cell's triangle to
  // any point of the cell then crosses a few triangles where they are of
  // even size (graded regions cost more steps: still few, measured in
  // tests/bench/bench_size_field.cpp).
  const double width = hi.x - lo.x, height = hi.y - lo.y;
  const double count = static_cast<double>(view.triangles.size()) * 4;
  double cell = std::max(std::sqrt(width * height / count), std::max(width, height) / count);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::max({width, height, 1.0});
  const auto cols = static_cast<std::uint32_t>(std::clamp(std::floor(width / cell) + 1.0, 1.0, count + 1.0));
  const auto rows = static_cast<std::uint32_t>(std::clamp(std::floor(height / cell) + 1.0, 1.0, count + 1.0));
  frame_ = UniformGrid(lo, cell, cell, cols, rows);
  start_.assign(std::size_t{cols} * rows, 0);
  // Serpentine order: each cell's walk starts from its neighbour's triangle.
  std::uint32_t t = 0;
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t k = 0; k < cols; ++k) {
      const std::uint32_t c = r % 2 == 0 ? k : cols - 1 - k;
      const Point centre{lo.x + (c + 0.5) * cell, lo.y + (r + 0.5) * cell};
      t = walk(view, centre, t).triangle;
      start_[std::size_t{r} * cols + c] = t;
    }
}

Location TriangleLocator::locate(const TriangleView& view, Point p, WalkHint* hint) const noexcept {
  if (start_.empty() || !finite_point(p)) return {};
  const std::uint32_t col = frame_.col_of(p.x), row = frame_.row_of(p.y);
  const std::uint32_t from_grid = start_[std::size_t{row} * frame_.cols() + col];
  const auto near = [](std::uint32_t i, std::uint32_t j) { return i <= j + 1 && j <= i + 1; };
  const bool hinted =
      hint != nullptr && hint->triangle < view.triangles.size() && near(col, hint->col) && near(row, hint->row);
  Location at = walk(view, p, hinted ? hint->triangle : from_grid);
  if (!at.inside && hinted) at = walk(view, p, from_grid);
  if (at.inside) at = lowest_holding(view, p, at);
  if (hint != nullptr) *hint = {at.triangle, col, row};
  return at;
}

namespace {

Location location_in(const TriangleView& view, Point p, std::uint32_t t) noexcept {
  const auto& v = view.triangles[t];
  const Point a = view.points[v[0]], b = view.points[v[1]], c = view.points[v[2]];
  const Point da = a - p, db = b - p, dc = c - p;
  return {t, true, {side(db, dc, b, c, p), side(dc, da, c, a, p), side(da, db, a, b, p)}};
}

}  // namespace

// p on an edge (one weight exactly 0: side() is exact in sign and gives 0
// only when p is on the line) or on a corner (two): the lowest-numbered
// triangle around. On an edge the two triangles are at and its neighbour
// across; on a corner the fan of triangles around it, walked both ways
// across the edges that meet there (its weights are 0 in each).
Location TriangleLocator::lowest_holding(const TriangleView& view, Point p, Location at) const noexcept {
  int zeros = 0, edge = -1;
  for (int i = 0; i < 3; ++i)
    if (at.weight[i] == 0.0) ++zeros, edge = i;
  if (zeros == 0 || zeros == 3) return at;
  std::uint32_t best = at.triangle;
  if (zeros == 1) {
    const std::uint32_t h = mesh_.tn[3 * at.triangle + edge];
    if (h != no_index && h / 3 < best) best = h / 3;
  } else {
    int corner = 0;  // the corner p is on: its weight is the nonzero one
    while (at.weight[corner] == 0.0) ++corner;
    const std::uint32_t v = view.triangles[at.triangle][corner];
    // Across each edge at v, one way round and then the other, until the fan closes or meets the hull.
    for (int way = 1; way <= 2; ++way) {
      std::uint32_t t = at.triangle;
      for (std::size_t guard = 0; guard < view.triangles.size(); ++guard) {
        const auto& tv = view.triangles[t];
        const int k = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        const std::uint32_t h = mesh_.tn[3 * t + (k + way) % 3];
        if (h == no_index || h / 3 == at.triangle) break;
        const std::uint32_t u = h / 3;
        best = std::min(best, u);
        t = u;
      }
    }
  }
  return best == at.triangle ? at : location_in(view, p, best);
}

// The core's visibility walk from t (a fresh random state at every query,
// so that a query's answer never depends on the ones before it), which
// leaves p's weights in the triangle it ends in. Beyond a hull edge p is
// outside: the triangle behind that edge is the one to clamp to.
Location TriangleLocator::walk(const TriangleView& view, Point p, std::uint32_t t) const noexcept {
  WalkRandom random;
  std::array<double, 3> weights{};
  const WalkResult end = walk_weighing(mesh_, view.points, p, t, random, weights);
  if (end.triangle != no_index) return {end.triangle, true, {weights[0], weights[1], weights[2]}};
  return {end.blocked_by != no_index ? end.blocked_by / 3 : t, false};
}

double interpolate(const TriangleView& view, std::span<const double> values, Location at, Point p) noexcept {
  if (at.triangle == no_index) return std::numeric_limits<double>::quiet_NaN();
  const auto& v = view.triangles[at.triangle];
  double w0 = at.weight[0], w1 = at.weight[1], w2 = at.weight[2];
  if (!at.inside) {
    const Point a = view.points[v[0]] - p, b = view.points[v[1]] - p, c = view.points[v[2]] - p;
    w0 = std::max(cross(b, c), 0.0), w1 = std::max(cross(c, a), 0.0), w2 = std::max(cross(a, b), 0.0);
  }
  const double sum = w0 + w1 + w2;
  if (!(sum > 0.0)) return std::min({values[v[0]], values[v[1]], values[v[2]]});  // p on a corner, rounded
  const double h = (w0 * values[v[0]] + w1 * values[v[1]] + w2 * values[v[2]]) / sum;
  if (!std::isnan(h)) return h;
  // An infinite corner whose weight rounded to zero: the other corners decide.
  double finite = 0.0, weight = 0.0;
  const double ws[3] = {w0, w1, w2};
  for (int i = 0; i < 3; ++i) {
    if (ws[i] > 0.0 && std::isinf(values[v[i]])) return infinity;
    if (std::isfinite(values[v[i]])) finite += ws[i] * values[v[i]], weight += ws[i];
  }
  return weight > 0.0 ? finite / weight : infinity;
}

}  // namespace madd::detail
