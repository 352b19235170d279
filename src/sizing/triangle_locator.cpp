// Point location by a grid of start triangles and a visibility walk
// (triangle_locator.hpp).
#include "sizing/triangle_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/predicates.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool finite_point(Point p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

TriangleLocator::TriangleLocator(const TriangleView& view) {
  if (view.triangles.empty()) return;
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

Location TriangleLocator::locate(const TriangleView& view, Point p) const noexcept {
  if (start_.empty() || !finite_point(p)) return {};
  return walk(view, p, start_[std::size_t{frame_.row_of(p.y)} * frame_.cols() + frame_.col_of(p.x)]);
}

// orient2d with its first, floating-point stage inline (the walk's hot
// path: a call per edge test cost half the query); exact whenever that
// stage cannot decide. |l| + |r| bounds Shewchuk's detsum, so the bound is
// never looser than orient2d's own first stage.
inline double orient(Point a, Point b, Point c) noexcept {
  const double l = (a.x - c.x) * (b.y - c.y), r = (a.y - c.y) * (b.x - c.x), det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound || -det > bound) return det;
  return orient2d(a, b, c);
}

// A visibility walk: cross an edge p lies strictly beyond, chosen in an
// order a linear congruential generator rotates (a fixed order may circle
// in a constrained triangulation; this one ends with probability one, and
// the step bound only limits bad luck: a scan then decides).
Location TriangleLocator::walk(const TriangleView& view, Point p, std::uint32_t t) const noexcept {
  const Point* P = view.points.data();
  const auto* tv = view.triangles.data();
  const auto* tn = view.neighbours.data();
  std::uint32_t came = no_index;
  std::uint32_t state = 12345u;
  for (std::size_t steps = 4 * view.triangles.size() + 64; steps > 0; --steps) {
    const std::array<std::uint32_t, 3>& v = tv[t];
    const std::array<std::uint32_t, 3>& n = tn[t];
    const Point corner[3] = {P[v[0]], P[v[1]], P[v[2]]};
    state = state * 1103515245u + 12345u;
    std::uint32_t i = (((state >> 16) & 0xffffu) * 3u) >> 16;  // 0, 1 or 2
    std::uint32_t next = no_index;
    for (int k = 0; k < 3; ++k, i = i == 2 ? 0 : i + 1) {
      if (n[i] == came && came != no_index) continue;  // p is on this side of the edge just crossed
      if (orient(corner[i == 2 ? 0 : i + 1], corner[i == 0 ? 2 : i - 1], p) < 0) {
        if (n[i] == no_index) return {t, false};  // beyond a hull edge: outside the hull
        next = n[i];
        break;
      }
    }
    if (next == no_index) return {t, true};
    came = t;
    t = next;
  }
  for (std::uint32_t u = 0; u < view.triangles.size(); ++u) {
    bool in = true;
    for (std::uint32_t i = 0; i < 3 && in; ++i) in = orient2d(P[tv[u][(i + 1) % 3]], P[tv[u][(i + 2) % 3]], p) >= 0;
    if (in) return {u, true};
  }
  return {t, false};
}

double interpolate(const TriangleView& view, std::span<const double> values, Location at, Point p) noexcept {
  if (at.triangle == no_index) return std::numeric_limits<double>::quiet_NaN();
  const auto& v = view.triangles[at.triangle];
  const Point a = view.points[v[0]], b = view.points[v[1]], c = view.points[v[2]];
  double w0 = cross(b - p, c - p), w1 = cross(c - p, a - p), w2 = cross(a - p, b - p);
  if (!at.inside) w0 = std::max(w0, 0.0), w1 = std::max(w1, 0.0), w2 = std::max(w2, 0.0);
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
