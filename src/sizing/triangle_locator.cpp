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
    const std::uint32_t u = view.neighbours[at.triangle][edge];
    if (u != no_index && u < best) best = u;
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
        const std::uint32_t u = view.neighbours[t][(k + way) % 3];
        if (u == no_index || u == at.triangle) break;
        best = std::min(best, u);
        t = u;
      }
    }
  }
  return best == at.triangle ? at : location_in(view, p, best);
}

// A visibility walk: cross an edge p lies strictly beyond, chosen, when
// there are two, by a linear congruential generator (a fixed rule may
// circle in a constrained triangulation; this one ends with probability
// one, and the step bound only limits bad luck: a scan then decides). The
// three sides of p are computed at once from p's offsets to the corners:
// in the last triangle they are p's barycentric weights.
Location TriangleLocator::walk(const TriangleView& view, Point p, std::uint32_t t) const noexcept {
  const Point* P = view.points.data();
  const auto* tv = view.triangles.data();
  const auto* tn = view.neighbours.data();
  std::uint32_t came = no_index;
  std::uint32_t state = 12345u;
  for (std::size_t steps = 4 * view.triangles.size() + 64; steps > 0; --steps) {
    const std::array<std::uint32_t, 3>& v = tv[t];
    const std::array<std::uint32_t, 3>& n = tn[t];
    const Point a = P[v[0]], b = P[v[1]], c = P[v[2]];
    const Point da = a - p, db = b - p, dc = c - p;
    Location here{t, true, {side(db, dc, b, c, p), side(dc, da, c, a, p), side(da, db, a, b, p)}};
    // The edges p is strictly beyond, less the one just crossed (p is on its inner side).
    unsigned beyond = (here.weight[0] < 0 ? 1u : 0u) | (here.weight[1] < 0 ? 2u : 0u) | (here.weight[2] < 0 ? 4u : 0u);
    for (int i = 0; i < 3; ++i)
      if (n[i] == came && came != no_index) beyond &= ~(1u << i);
    if (beyond == 0) return here;
    int i = beyond == 1 ? 0 : beyond == 2 ? 1 : beyond == 4 ? 2 : -1;
    if (i < 0) {  // two edges: choose at random
      state = state * 1103515245u + 12345u;
      const bool second = (state >> 16) & 1u;
      const int first = (beyond & 1u) ? 0 : 1, other = (beyond & 4u) ? 2 : 1;
      i = second ? other : first;
    }
    if (n[i] == no_index) return {t, false};  // beyond a hull edge: outside the hull
    came = t;
    t = n[i];
  }
  for (std::uint32_t u = 0; u < view.triangles.size(); ++u) {
    bool in = true;
    for (std::uint32_t i = 0; i < 3 && in; ++i) in = orient2d(P[tv[u][(i + 1) % 3]], P[tv[u][(i + 2) % 3]], p) >= 0;
    if (in) {
      const Point a = P[tv[u][0]] - p, b = P[tv[u][1]] - p, c = P[tv[u][2]] - p;
      return {u, true, {cross(b, c), cross(c, a), cross(a, b)}};
    }
  }
  return {t, false};
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
