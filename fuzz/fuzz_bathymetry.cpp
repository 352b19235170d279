// libFuzzer target: both bathymetry parsers (Esri ASCII grid, x y z scatter)
// on the same text, and the depth field of whatever parses, read at points
// in and around it. Any exception other than madd::Error, any crash or
// sanitizer report is a bug; so is a depth outside the range of the samples
// where the interpolant can only average them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "madd/bathymetry.hpp"
#include "madd/error.hpp"

namespace {

// depths_at gives depth_at's values, on any number of threads; NaN only
// where the point is not finite. The depth at each point is within [lo, hi]
// up to rounding, with a gradient (when the samples are small enough that
// sums of them cannot overflow).
void check_field(const madd::DepthField& field, const std::vector<madd::Point>& points, double lo, double hi) {
  const std::vector<double> all = madd::depths_at(field, points, 2);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double d = field.depth_at(points[k]);
    if (!(all[k] == d || (std::isnan(all[k]) && std::isnan(d)))) std::abort();
  }
  if (!std::isnan(field.depth_at({std::nan(""), 0.0}))) std::abort();
  if (!(std::max(std::abs(lo), std::abs(hi)) < 1e150)) return;
  const double slack = 1e-9 * std::max({std::abs(lo), std::abs(hi), 1e-200});
  for (const madd::Point p : points) {
    const double d = field.depth_at(p);
    const madd::Point g = field.gradient_at(p);
    if (!(d >= lo - slack && d <= hi + slack)) std::abort();
    if (std::isnan(g.x) || std::isnan(g.y)) std::abort();
  }
}

void read_grid(std::string_view text) {
  madd::DepthGrid grid;
  try {
    grid = madd::parse_esri_ascii_grid(text, "fuzz.asc");
  } catch (const madd::Error&) {
    return;
  }
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t k = 0; k < grid.values.size(); ++k)
    if (grid.has_value(k)) lo = std::min(lo, grid.values[k]), hi = std::max(hi, grid.values[k]);
  const double x1 = grid.x0 + static_cast<double>(grid.cols - 1) * grid.dx;
  const double y1 = grid.y0 + static_cast<double>(grid.rows - 1) * grid.dy;
  std::vector<madd::Point> points = {{grid.x0, grid.y0}, {x1, y1}, {grid.x0 - 1e9, y1 + 1.0}, {0.0, 0.0}};
  for (int k = 0; k <= 8; ++k) {
    const double t = k / 8.0;
    points.push_back({grid.x0 + t * (x1 - grid.x0), grid.y0 + (1 - t) * (y1 - grid.y0)});
  }
  try {
    const madd::DepthField field(madd::Bathymetry{std::move(grid)});
    check_field(field, points, lo, hi);
  } catch (const madd::Error&) {
    std::abort();  // a parsed grid is always accepted
  }
}

void read_scatter(std::string_view text) {
  std::vector<madd::ValuedPoint> samples;
  try {
    samples = madd::parse_xyz(text, "fuzz.xyz");
  } catch (const madd::Error&) {
    return;
  }
  double lo = INFINITY, hi = -INFINITY;
  std::vector<madd::Point> points = {{0.0, 0.0}, {1e60, -1e60}};
  for (const madd::ValuedPoint& s : samples) {
    lo = std::min(lo, s.value), hi = std::max(hi, s.value);
    if (points.size() < 64) points.push_back(s.at);
  }
  for (std::size_t k = 2; k + 1 < std::min<std::size_t>(points.size(), 64); ++k)
    points.push_back(madd::midpoint(points[k], points[k + 1]));
  try {
    const madd::DepthField field(madd::Bathymetry{std::move(samples)});
    check_field(field, points, lo, hi);
  } catch (const madd::Error&) {
    std::abort();  // a parsed scatter is always accepted
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  read_grid(text);
  read_scatter(text);
  return 0;
}
