#pragma once
// Figures of separator smoothing (paper Sec. 5.1), shared by the smoothing
// test and the `smoothing` benchmark.
#include <algorithm>
#include <cmath>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"

namespace madd::test {

struct SmoothingFigures {
  double shortest_norm = 0.0;          // shortest new segment / sqrt(mean area)
  std::uint32_t short_count = 0;       // new segments shorter than 5% of sqrt(mean area)
  std::uint32_t short_separators = 0;  // of which separators
  std::uint32_t ends = 0;              // separator ends: vertices with a separator and degree >= 3
  double on_existing = 0.0;            // share of ends at an input vertex or where >= 2 separators
                                       // meet the same point from both sides (degree >= 4)
  double median_angle = 0.0;
  double min_angle = 0.0;
};

inline SmoothingFigures smoothing_figures(const Decomposition& d, std::size_t input_points) {
  SmoothingFigures f;
  double area = 0.0;
  for (const auto& s : d.subdomains) area += s.area;
  const double scale = std::sqrt(area / static_cast<double>(d.subdomains.size()));
  std::vector<std::uint32_t> degree(d.points.size(), 0), separators(d.points.size(), 0), pieces;
  for (std::size_t k = 0; k < d.segments.size(); ++k) {
    if (d.is_separator(static_cast<std::uint32_t>(k))) continue;
    if (pieces.size() <= d.segment_origin[k]) pieces.resize(d.segment_origin[k] + 1, 0);
    ++pieces[d.segment_origin[k]];
  }
  f.shortest_norm = INFINITY;
  for (std::size_t k = 0; k < d.segments.size(); ++k) {
    const auto& s = d.segments[k];
    const bool sep = d.is_separator(static_cast<std::uint32_t>(k));
    ++degree[s.a];
    ++degree[s.b];
    if (sep) ++separators[s.a], ++separators[s.b];
    if (!sep && pieces[d.segment_origin[k]] < 2) continue;  // an untouched input segment is not new
    const double len = std::hypot(d.points[s.a].x - d.points[s.b].x, d.points[s.a].y - d.points[s.b].y) / scale;
    f.shortest_norm = std::min(f.shortest_norm, len);
    if (len < 0.05) ++f.short_count;
    if (len < 0.05 && sep) ++f.short_separators;
  }
  std::uint32_t existing = 0;
  for (std::size_t v = 0; v < d.points.size(); ++v) {
    if (separators[v] == 0 || degree[v] < 3) continue;
    ++f.ends;
    if (v < input_points || degree[v] >= 4) ++existing;
  }
  f.on_existing = f.ends == 0 ? 0.0 : static_cast<double>(existing) / f.ends;
  const Metrics m = metrics(d);
  f.median_angle = m.angle_median;
  f.min_angle = m.angle_min;
  return f;
}

}  // namespace madd::test
