// The depth between the samples of a bathymetry (include/madd/bathymetry.hpp):
// bilinear on a grid, with the nearest cell with a depth where a cell's
// corners have none; linear over the Delaunay triangulation of a scatter,
// with the nearest point outside its hull. And the two depth rules of a
// coastal mesh's edge length.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "kernel/coordinate_range.hpp"
#include "kernel/threads.hpp"
#include "madd/bathymetry.hpp"
#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "sizing/nearest_sample.hpp"
#include "sizing/triangle_locator.hpp"
#include "triangulation/hilbert.hpp"

namespace madd::detail {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

struct DepthAndGradient {
  double depth = nan;
  Point gradient{nan, nan};
};

[[noreturn]] void refuse(const std::string& message) {
  throw InvalidInputError(InputProblem::other, "bathymetry: " + message);
}

// What parse_esri_ascii_grid guarantees, for a grid built by hand.
void check_grid(const DepthGrid& g) {
  if (g.cols == 0 || g.rows == 0) refuse("a grid needs at least one column and one row");
  if (g.cols >= (std::size_t{1} << 31) || g.rows >= (std::size_t{1} << 31) ||
      std::uint64_t{g.cols} * g.rows >= std::numeric_limits<std::uint32_t>::max())
    refuse("the grid has more than 2^32 - 2 cells");
  if (g.values.size() != g.cols * g.rows)
    refuse("the grid has " + std::to_string(g.values.size()) + " values for " + std::to_string(g.cols) + " x " +
           std::to_string(g.rows) + " cells");
  if (!(g.dx > 0.0) || !(g.dy > 0.0) || !std::isfinite(g.dx) || !std::isfinite(g.dy))
    refuse("the cell width and height must be finite and > 0");
  const double width = static_cast<double>(g.cols) * g.dx, height = static_cast<double>(g.rows) * g.dy;
  for (const double v : {g.x0, g.y0, width, height, g.x0 - g.dx, g.y0 - g.dy, g.x0 + width, g.y0 + height})
    if (!std::isfinite(v)) refuse("the grid's origin and extent must be finite");
  bool any = false;
  for (std::size_t k = 0; k < g.values.size(); ++k) {
    if (!g.has_value(k)) continue;
    if (!std::isfinite(g.values[k])) refuse("the grid's value " + std::to_string(k) + " is not finite");
    any = true;
  }
  if (!any) refuse("the grid holds no depth (every value is the NODATA value)");
}

// What parse_xyz guarantees, for a scatter built by hand (a point given
// twice is delaunay's InvalidInputError).
void check_scatter(std::span<const ValuedPoint> points) {
  if (points.size() < 3) refuse("a scatter needs at least 3 points, it has " + std::to_string(points.size()));
  if (points.size() >= none) refuse("a scatter has at most 2^32 - 2 points");
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!in_exact_range(points[k].at.x) || !in_exact_range(points[k].at.y) || !std::isfinite(points[k].value))
      refuse("scatter point " + std::to_string(k) +
             " has a coordinate that is not 0 or of magnitude within [1e-40, 1e70], or a value that is not finite");
  // Some point off the line of two distinct ones.
  std::size_t second = 1;
  while (second < points.size() && points[second].at == points[0].at) ++second;
  for (std::size_t k = second + 1; k < points.size(); ++k)
    if (orient2d(points[0].at, points[second].at, points[k].at) != 0.0) return;
  refuse("the scatter's points all lie on one line");
}

// Per cell, the row of the cell with a depth nearest to it in its column
// (the lower one of two as near), or none when the column has none: one
// sweep up and one down, row by row (the grid's memory order).
std::vector<std::uint32_t> nearest_rows(const DepthGrid& g) {
  const std::size_t cols = g.cols, rows = g.rows;
  std::vector<std::uint32_t> row_of(cols * rows, none);  // first the nearest at or below
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c)
      row_of[r * cols + c] = g.has_value(r * cols + c) ? static_cast<std::uint32_t>(r)
                             : r > 0                   ? row_of[(r - 1) * cols + c]
                                                       : none;
  std::vector<std::uint32_t> above(cols, none);  // the nearest at or above, in the sweep down
  for (std::size_t r = rows; r-- > 0;)
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t k = r * cols + c;
      if (g.has_value(k)) above[c] = static_cast<std::uint32_t>(r);
      if (above[c] != none && (row_of[k] == none || above[c] - r < r - row_of[k])) row_of[k] = above[c];
    }
  return row_of;
}

// Along one row, for every column j the column c minimising (j - c)^2 + f[c]
// (distances in units of dx; f = infinity: no site): the lower envelope of
// the parabolas, left to right. v and z are scratch of cols and cols + 1.
void envelope(std::span<const double> f, std::span<std::uint32_t> v, std::span<double> z,
              std::span<std::uint32_t> site) {
  const std::size_t cols = f.size();
  // Where the parabolas of columns p < q cross.
  const auto cross = [&](std::size_t p, std::size_t q) {
    const double a = static_cast<double>(p), b = static_cast<double>(q);
    return ((f[q] - f[p]) / (b - a) + a + b) / 2.0;
  };
  std::size_t k = 0, first = 0;
  while (f[first] == infinity) ++first;  // the caller's row has a site
  v[0] = static_cast<std::uint32_t>(first);
  z[0] = -infinity;
  z[1] = infinity;
  for (std::size_t q = first + 1; q < cols; ++q) {
    if (f[q] == infinity) continue;
    double s = cross(v[k], q);
    while (k > 0 && s <= z[k]) s = cross(v[--k], q);
    v[++k] = static_cast<std::uint32_t>(q);
    z[k] = s;
    z[k + 1] = infinity;
  }
  for (std::size_t j = 0, e = 0; j < cols; ++j) {
    while (e < k && z[e + 1] < static_cast<double>(j)) ++e;
    site[j] = v[e];
  }
}

// For every cell of the grid, the cell with a depth nearest to its centre
// (Euclidean, with the grid's dx and dy): Felzenszwalb and Huttenlocher's
// distance transform, exact up to rounding. First the nearest row with a
// depth in each column, then along each row the lower envelope of the
// parabolas (dx*(j - c))^2 + f(c), f(c) the squared vertical distance found
// for column c. Ties go to the lower column, within a column to the lower
// row. Empty when every cell has a depth. O(cols*rows) time and memory.
std::vector<std::uint32_t> nearest_cells(const DepthGrid& g) {
  const std::size_t cols = g.cols, rows = g.rows, n = cols * rows;
  bool all = true;
  for (std::size_t k = 0; k < n && all; ++k) all = g.has_value(k);
  if (all) return {};
  const std::vector<std::uint32_t> row_of = nearest_rows(g);
  // In units of dx: f(c) = (ratio*(r - row))^2, the ratio kept within 1e100
  // of square cells so that no square overflows.
  const double ratio = std::clamp(g.dy / g.dx, 1e-100, 1e100);
  std::vector<std::uint32_t> nearest(n), v(cols), site(cols);
  std::vector<double> f(cols), z(cols + 1);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      const std::uint32_t at = row_of[r * cols + c];
      const double d = at == none ? 0.0 : std::abs(static_cast<double>(r) - at) * ratio;
      f[c] = at == none ? infinity : d * d;
    }
    // Some column has a depth, so every row has a site.
    envelope(f, v, z, site);
    for (std::size_t j = 0; j < cols; ++j)
      nearest[r * cols + j] = static_cast<std::uint32_t>(row_of[r * cols + site[j]] * cols + site[j]);
  }
  return nearest;
}

// One axis of the bilinear: the point's place clamped onto the centres
// [0, n - 1] (in cells), the lower corner i and the fraction t beyond it.
struct Axis {
  std::size_t i = 0, nearest = 0;
  double t = 0.0;
  bool moved = false;  // p was outside the centres and clamped onto them
};

Axis axis_of(double x, double x0, double d, std::size_t n) {
  Axis a;
  const double last = static_cast<double>(n - 1);
  double u = (x - x0) / d;
  a.moved = !(u >= 0.0 && u <= last);
  u = std::clamp(u, 0.0, last);
  a.i = n == 1 ? 0 : std::min(static_cast<std::size_t>(u), n - 2);
  a.t = n == 1 ? 0.0 : std::clamp(u - static_cast<double>(a.i), 0.0, 1.0);
  a.nearest = std::min(static_cast<std::size_t>(u + 0.5), n - 1);
  return a;
}

// The bilinear of the corners with a depth, renormalised, and its gradient
// (the quotient rule on sum(w v) / sum(w)).
DepthAndGradient grid_depth(const DepthGrid& g, std::span<const std::uint32_t> nearest, Point p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {};
  const Axis ax = axis_of(p.x, g.x0, g.dx, g.cols), ay = axis_of(p.y, g.y0, g.dy, g.rows);
  const std::size_t i1 = std::min(ax.i + 1, g.cols - 1), j1 = std::min(ay.i + 1, g.rows - 1);
  const std::size_t corner[4] = {ay.i * g.cols + ax.i, ay.i * g.cols + i1, j1 * g.cols + ax.i, j1 * g.cols + i1};
  const double s = ax.t, t = ay.t;
  const double w[4] = {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
  const double ws[4] = {-(1 - t), 1 - t, -t, t}, wt[4] = {-(1 - s), -s, 1 - s, s};  // d w / d s, d w / d t
  double sum = 0, weight = 0, sum_s = 0, weight_s = 0, sum_t = 0, weight_t = 0;
  for (int k = 0; k < 4; ++k) {
    if (!g.has_value(corner[k])) continue;
    const double v = g.values[corner[k]];
    sum += w[k] * v, weight += w[k];
    sum_s += ws[k] * v, weight_s += ws[k];
    sum_t += wt[k] * v, weight_t += wt[k];
  }
  if (!(weight > 0.0)) {  // only where a corner has no depth, so nearest is there
    const std::size_t k = ay.nearest * g.cols + ax.nearest;
    return {g.values[nearest.empty() ? k : nearest[k]], {0.0, 0.0}};
  }
  const double depth = sum / weight;
  const double gx = ax.moved || g.cols == 1 ? 0.0 : (sum_s - depth * weight_s) / weight / g.dx;
  const double gy = ay.moved || g.rows == 1 ? 0.0 : (sum_t - depth * weight_t) / weight / g.dy;
  return {depth, {gx, gy}};
}

}  // namespace

// The scatter's interpolant: the Delaunay triangulation of its points, the
// locator over it, and the nearest point outside the hull.
class ScatterDepth {
public:
  explicit ScatterDepth(std::span<const ValuedPoint> points) : points_(points), nearest_(points) {
    std::vector<Point> at(points.size());
    values_.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      at[k] = points[k].at, values_[k] = points[k].value;
      x0_ = std::min(x0_, at[k].x), x1_ = std::max(x1_, at[k].x), y0_ = std::min(y0_, at[k].y),
      y1_ = std::max(y1_, at[k].y);
    }
    triangulation_ = delaunay(at);
    locator_ = TriangleLocator(view());
  }

  // The hint only shortens the walk: the result is the same without it.
  DepthAndGradient at(Point p, WalkHint* hint) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {};
    // Off the points' box is off the hull: the nearest point, with no walk
    // (whose exact predicates hold only for coordinates within [1e-40, 1e70]).
    if (!(p.x >= x0_ && p.x <= x1_ && p.y >= y0_ && p.y <= y1_))
      return {points_[nearest_.nearest(p)].value, {0.0, 0.0}};
    p = {flush_below_range(p.x), flush_below_range(p.y)};
    const Location where = locator_.locate(view(), p, hint);
    if (!where.inside) return {points_[nearest_.nearest(p)].value, {0.0, 0.0}};
    return {interpolate(view(), values_, where, p), gradient_of(where.triangle)};
  }

private:
  double x0_ = std::numeric_limits<double>::infinity(), x1_ = -x0_, y0_ = x0_, y1_ = -x0_;  // the points' box
  TriangleView view() const noexcept {
    return {triangulation_.points, triangulation_.triangles, triangulation_.neighbours};
  }
  // The constant gradient of the linear function through the triangle's corners.
  Point gradient_of(std::uint32_t t) const {
    const auto& v = triangulation_.triangles[t];
    const Point a = triangulation_.points[v[0]];
    const Point e1 = triangulation_.points[v[1]] - a, e2 = triangulation_.points[v[2]] - a;
    const double d1 = values_[v[1]] - values_[v[0]], d2 = values_[v[2]] - values_[v[0]];
    const double det = cross(e1, e2);
    if (!(det != 0.0)) return {0.0, 0.0};
    return {(d1 * e2.y - d2 * e1.y) / det, (d2 * e1.x - d1 * e2.x) / det};
  }

  std::span<const ValuedPoint> points_;
  NearestSample nearest_;
  Triangulation triangulation_;
  std::vector<double> values_;
  TriangleLocator locator_;
};

// What a DepthField shares between its copies: the bathymetry and its
// interpolant, never changed once built (so read from any thread).
struct DepthModel {
  explicit DepthModel(Bathymetry b) : bathymetry(std::move(b)) {
    if (const DepthGrid* g = std::get_if<DepthGrid>(&bathymetry.data)) {
      check_grid(*g);
      nearest = nearest_cells(*g);
    } else {
      const auto& points = std::get<std::vector<ValuedPoint>>(bathymetry.data);
      check_scatter(points);
      scatter.emplace(points);
    }
  }
  DepthModel(const DepthModel&) = delete;  // the interpolant holds views of the bathymetry
  DepthModel& operator=(const DepthModel&) = delete;

  DepthAndGradient at(Point p, WalkHint* hint = nullptr) const {
    if (const DepthGrid* g = std::get_if<DepthGrid>(&bathymetry.data)) return grid_depth(*g, nearest, p);
    return scatter->at(p, hint);
  }

  Bathymetry bathymetry;
  std::vector<std::uint32_t> nearest;  // grid: nearest_cells
  std::optional<ScatterDepth> scatter;
};

}  // namespace madd::detail

namespace madd {

DepthField::DepthField(Bathymetry bathymetry)
    : model_(std::make_shared<const detail::DepthModel>(std::move(bathymetry))) {}

double DepthField::depth_at(Point p) const noexcept {
  return model_ ? model_->at(p).depth : std::numeric_limits<double>::quiet_NaN();
}

Point DepthField::gradient_at(Point p) const noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return model_ ? model_->at(p).gradient : Point{nan, nan};
}

const Bathymetry& DepthField::bathymetry() const noexcept {
  static const Bathymetry empty{std::vector<ValuedPoint>{}};
  return model_ ? model_->bathymetry : empty;
}

bool operator==(const DepthField& a, const DepthField& b) noexcept {
  return a.model_ == b.model_ || (a.model_ && b.model_ && a.model_->bathymetry == b.model_->bathymetry);
}

namespace {

// The points' indices in the order of the cells of a 256 x 256 grid over
// their bounding box along a Hilbert curve (a counting sort; in a cell, the
// input order; the non-finite points last), so that consecutive queries
// touch nearby memory and the scatter's walks start next to where the last
// one ended.
std::vector<std::uint32_t> spatial_order(std::span<const Point> points) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  constexpr int bits = 8;
  constexpr std::uint32_t cells = 1u << (2 * bits), last = (1u << bits) - 1;
  double x0 = infinity, y0 = infinity, x1 = -infinity, y1 = -infinity;
  for (const Point p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const double sx = x1 > x0 ? (last + 1) / (x1 - x0) : 0.0, sy = y1 > y0 ? (last + 1) / (y1 - y0) : 0.0;
  // NaN (an infinite width times a zero scale) to 0, as any value below.
  const auto cell = [](double t) { return !(t > 0.0) ? 0u : t >= last ? last : static_cast<std::uint32_t>(t); };
  std::vector<std::uint32_t> key(points.size()), start(cells + 2, 0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point p = points[k];
    key[k] = std::isfinite(p.x) && std::isfinite(p.y)
                 ? detail::hilbert_index(cell((p.x - x0) * sx), cell((p.y - y0) * sy), bits)
                 : cells;
    ++start[key[k] + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) order[start[key[k]]++] = static_cast<std::uint32_t>(k);
  return order;
}

}  // namespace

std::vector<double> depths_at(const DepthField& field, std::span<const Point> points, unsigned threads) {
  std::vector<double> out(points.size(), std::numeric_limits<double>::quiet_NaN());
  if (field.empty() || points.empty()) return out;
  if (points.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InvalidInputError(InputProblem::other, "depths_at: more than 2^32 - 2 points");
  // A grid is read in the points' order: a query costs a few reads, and the
  // indirection of a spatial order would cost more than it saves (measured:
  // 2 M random points on a 2000 x 2000 grid). A scatter's walk is long from
  // a far start: there the spatial order pays (4x on random points).
  const bool grid = std::holds_alternative<DepthGrid>(field.bathymetry().data);
  const std::vector<std::uint32_t> order = grid ? std::vector<std::uint32_t>{} : spatial_order(points);
  constexpr std::size_t chunk = 1 << 14;  // each task writes the slots of its own run of points
  detail::for_each_on_threads((points.size() + chunk - 1) / chunk, threads, [&](std::size_t task) {
    detail::WalkHint hint;
    const std::size_t end = std::min(points.size(), (task + 1) * chunk);
    for (std::size_t k = task * chunk; k < end; ++k) {
      const std::size_t i = grid ? k : order[k];
      out[i] = field.model_->at(points[i], &hint).depth;
    }
  });
  return out;
}

double wavelength_edge(double depth, double cells) noexcept {
  if (!(depth > 0.0) || !(cells > 0.0)) return std::numeric_limits<double>::infinity();
  return m2_period_seconds * std::sqrt(gravity * depth) / cells;
}

double slope_edge(double depth, double gradient_length, double cells) noexcept {
  if (!(depth > 0.0) || !(gradient_length > 0.0) || !(cells > 0.0)) return std::numeric_limits<double>::infinity();
  return 2.0 * std::numbers::pi * depth / (cells * gradient_length);
}

}  // namespace madd
