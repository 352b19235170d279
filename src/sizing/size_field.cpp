// The size field: its options, its construction on the background, and its
// evaluation (size_field.hpp).
#include "sizing/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernel/stopwatch.hpp"
#include "madd/error.hpp"
#include "sizing/background.hpp"
#include "sizing/coast.hpp"
#include "sizing/distance_bound.hpp"
#include "sizing/gradation.hpp"
#include "sizing/raw_field.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

void check_length(const char* field, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) throw OptionError(field, "must be finite and >= 0");
}

// The background's cell size over h. The background is coarse against the
// mesh (a few % of its triangles), but the safety bound lowers the distance
// term by up to G rho at the coast (rho ~ 0.7 cell), so the cells there
// shrink as G grows: at most about 0.5 / G times h.
double cell_over_h(const MeshSizeOptions& size) {
  constexpr double k = 4.0;
  return size.distance_rate > 0.0 ? std::min(k, 0.5 / size.distance_rate) : k;
}

}  // namespace

double edge_of_area(double a) noexcept { return a > 0.0 ? std::sqrt(a / 0.4330127018922193) : infinity; }

void check_field_options(const MeshSizeOptions& size) {
  check_length("min_edge_length", size.min_edge_length);
  check_length("max_edge_length", size.max_edge_length);
  check_length("distance_rate", size.distance_rate);
  check_length("cells_across", size.cells_across);
  check_length("size_gradation", size.size_gradation);
  if (size.min_edge_length > 0.0 && size.max_edge_length > 0.0 && size.min_edge_length > size.max_edge_length)
    throw OptionError("min_edge_length", "must be at most max_edge_length");
  if ((size.distance_rate > 0.0 || size.cells_across > 0.0) && !(size.min_edge_length > 0.0))
    throw OptionError(size.distance_rate > 0.0 ? "distance_rate" : "cells_across",
                      "needs min_edge_length (the edge length at the coast) > 0");
}

SizeField::SizeField(const Pslg& domain, const MeshSizeOptions& size) {
  check_field_options(size);
  if (!size.has_field_terms()) {
    if (!size.coast_markers.empty()) trace_coast(domain, size.coast_markers);  // checked all the same
    return;
  }
  Stopwatch clock;
  const Coast coast = trace_coast(domain, size.coast_markers);
  const RawField raw(coast, size);
  BackgroundOptions options;
  options.cell_over_h = cell_over_h(size);
  BackgroundBuild built = build_background(coast, raw, options);
  background_ = std::move(built.background);
  report_.steiner_points = built.steiner_points;
  for (const std::uint8_t in : background_.inside) report_.inside_triangles += in;
  const std::vector<double> safe =
      safe_distance_values(background_, built.samples, size.min_edge_length, size.distance_rate);
  for (std::size_t v = 0; v < safe.size(); ++v) {
    if (!(safe[v] < background_.edge[v])) continue;
    // Never reached on the backgrounds measured (docs/mesh.md): a value
    // the bound takes to <= 0 would be no size at all; a hair above 0 keeps
    // the field usable (and the mesh far finer than asked there).
    if (safe[v] <= 0.0) ++report_.floored_points;
    background_.edge[v] = std::max(safe[v], 1e-3 * size.min_edge_length);
  }
  if (size.size_gradation > 0.0) {
    const GradationReport g = limit_gradation(background_, size.size_gradation);
    report_.gradation_pops = g.pops;
    report_.gradation_fixes = g.triangle_fixes;
    report_.gradation_fell_back = g.fell_back;
  }
  locator_ = TriangleLocator(view());
  report_.seconds = clock.lap();
}

double SizeField::edge_at(Point p) const {
  if (empty()) return infinity;
  const Location at = locator_.locate(view(), p);
  return interpolate(view(), background_.edge, at, p);
}

}  // namespace madd::detail
