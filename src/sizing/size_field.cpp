// The size field: its options, its construction on the background, and its
// evaluation (size_field.hpp).
#include "sizing/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

// The background's cell size over h (background.hpp). The distance term is
// exact (coast_candidates.hpp), so the background only carries the other
// terms and the gradation, and this trades its size against the time of a
// query (the coast pieces a triangle keeps grow with it). Measured on the
// real coastlines at the settings (docs/mesh.md, "Size field"):
// 6 gives a background of 2-5% of the mesh's triangles. When the distance
// term is linear (graded below its rate), its safety bound lowers it by up
// to G rho at the coast, rho ~ 0.7 cell: the cells there shrink to 0.5 / G
// h, so that the bound takes at most about a third of hmin.
double cell_over_h(const MeshSizeOptions& size, bool exact_distance) {
  constexpr double k = 6.0;
  return exact_distance || !(size.distance_rate > 0.0) ? k : std::min(k, 0.5 / size.distance_rate);
}

// The feature-size term at each point, taken down to the smallest raw term
// of its inside neighbours (one ring). The chord jumps where a channel
// opens into a basin (and at a channel's closed end, feature_width.hpp),
// and a linear interpolant spreads a jump over a whole triangle, half into
// the channel; after this step every corner of a triangle is at most the
// raw term at each of its corners, so a triangle with one corner on a
// channel's bank reads at most that bank's 2 width / R everywhere.
std::vector<double> eroded_feature_term(const SizeBackground& bg, const std::vector<RawSample>& samples) {
  std::vector<double> out(samples.size(), infinity);
  for (std::size_t t = 0; t < bg.triangles.size(); ++t) {
    if (bg.inside[t] == 0) continue;
    const auto& v = bg.triangles[t];
    const double least = std::min({samples[v[0]].feature_term, samples[v[1]].feature_term, samples[v[2]].feature_term});
    for (const std::uint32_t i : v) out[i] = std::min(out[i], least);
  }
  return out;
}

// The point values of every term but the distance term (the feature term
// eroded).
std::vector<double> other_terms(const SizeBackground& bg, const std::vector<RawSample>& samples) {
  std::vector<double> out(samples.size());
  for (std::size_t v = 0; v < samples.size(); ++v) out[v] = samples[v].other;
  const std::vector<double> feature = eroded_feature_term(bg, samples);
  for (std::size_t v = 0; v < samples.size(); ++v) out[v] = std::min(out[v], feature[v]);
  return out;
}

}  // namespace

double edge_of_area(double a) noexcept { return a > 0.0 ? std::sqrt(a / 0.4330127018922193) : infinity; }

void check_field_options(const MeshSizeOptions& size) {
  check_length("min_edge_length", size.min_edge_length);
  check_length("max_edge_length", size.max_edge_length);
  check_length("distance_rate", size.distance_rate);
  check_length("cells_across", size.cells_across);
  check_length("size_gradation", size.size_gradation);
  check_length("wavelength_cells", size.wavelength_cells);
  check_length("slope_cells", size.slope_cells);
  if (size.has_depth_terms() && !size.depth) throw OptionError("wavelength_cells", "needs a depth (bathymetry)");
  if (size.min_edge_length > 0.0 && size.max_edge_length > 0.0 && size.min_edge_length > size.max_edge_length)
    throw OptionError("min_edge_length", "must be at most max_edge_length");
  if ((size.distance_rate > 0.0 || size.cells_across > 0.0) && !(size.min_edge_length > 0.0))
    throw OptionError(size.distance_rate > 0.0 ? "distance_rate" : "cells_across",
                      "needs min_edge_length (the edge length at the coast) > 0");
}

SizeField::SizeField(const Pslg& domain, const MeshSizeOptions& size, unsigned threads) {
  check_field_options(size);
  if (!size.has_field_terms()) {
    if (!size.coast_markers.empty()) trace_coast(domain, size.coast_markers);  // checked all the same
    return;
  }
  Stopwatch clock;
  const Coast coast = trace_coast(domain, size.coast_markers);
  const RawField raw(coast, size);
  // The exact distance (coast_candidates.hpp), unless the gradation is
  // below the distance rate: the distance term must then be graded too,
  // which only its point values can be.
  const bool exact =
      size.distance_rate > 0.0 && (size.size_gradation == 0.0 || size.distance_rate <= size.size_gradation);
  BackgroundOptions options;
  options.cell_over_h = cell_over_h(size, exact);
  options.threads = threads;
  BackgroundBuild built = build_background(coast, raw, options);
  background_ = std::move(built.background);
  report_.steiner_points = built.steiner_points;
  for (const std::uint8_t in : background_.inside) report_.inside_triangles += in;
  hmin_ = size.min_edge_length;
  rate_ = size.distance_rate;
  background_.edge = other_terms(background_, built.samples);
  if (exact) {
    exact_ = CoastCandidates(background_, built.samples, coast, threads);
    for (std::uint32_t t = 0; t < background_.triangles.size(); ++t)
      report_.exact_triangles += background_.inside[t] != 0 && exact_.exact(t) ? 1 : 0;
    report_.coast_candidates = exact_.candidates();
  } else if (rate_ > 0.0) {
    lower_to_safe_distance(built.samples);
  }
  if (size.size_gradation > 0.0) {
    const GradationReport g = limit_gradation(background_, size.size_gradation);
    report_.gradation_pops = g.pops;
    report_.gradation_fixes = g.triangle_fixes;
    report_.gradation_held = g.held_triangles;
    report_.gradation_fell_back = g.fell_back;
  }
  graded_ = background_.edge;
  // background().edge: h at each point, the distance term exactly there.
  if (exact_.exact_triangles() > 0)
    for (std::size_t v = 0; v < graded_.size(); ++v)
      background_.edge[v] = std::min(graded_[v], exact_term(built.samples[v].distance));
  locator_ = TriangleLocator(view());
  report_.seconds = clock.lap();
}

// The linear distance term, each point value lowered by the safety bound
// (distance_bound.hpp): when the distance term must be graded.
void SizeField::lower_to_safe_distance(const std::vector<RawSample>& samples) {
  const std::vector<double> safe = safe_distance_values(background_, samples, hmin_, rate_);
  for (std::size_t v = 0; v < safe.size(); ++v) {
    if (!(safe[v] < background_.edge[v])) continue;
    // A value the bound takes to <= 0 would be no size at all; a hair above
    // 0 keeps the field usable (and the mesh far finer than asked there).
    // Only a background far coarser than the field (the budget) does it.
    if (safe[v] <= 0.0) ++report_.floored_points;
    background_.edge[v] = std::max(safe[v], 1e-3 * hmin_);
  }
}

double SizeField::edge_at(Point p, WalkHint* hint) const {
  if (empty()) return infinity;
  const Location at = locator_.locate(view(), p, hint);
  // Every term of the field is hmin or more, so the field is too: where the
  // background is far coarser than hmin, the distance term's safety bound
  // (lower_to_safe_distance) takes point values of the linear part below it
  // (to 0.53 hmin on the bundled archipelago at hmin = extent / 1000). hmin
  // is the exact term at distance 0, so the field stays below that term.
  const double h = std::max(interpolate(view(), graded_, at, p), exact_term(0.0));
  // Beyond the hull (a rounding off a coast on it), the triangle the walk
  // stopped in: its coast pieces are those near p.
  if (at.triangle == no_index || !exact_.exact(at.triangle)) return h;
  return std::min(h, exact_term(exact_.distance(at.triangle, p)));
}

}  // namespace madd::detail
