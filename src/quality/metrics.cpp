// The C1-C3 figures of docs/quality.md (paper Sec. 1 criteria, Sec. 7 figures).
#include "madd/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/rings.hpp"
#include "quality/decile.hpp"
#include "quality/metrics_detail.hpp"

namespace madd {

namespace {

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

double median_of(const std::vector<double>& sorted) {
  const std::size_t n = sorted.size();
  if (n == 0) return nan_value;
  return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

void fill_angles(const Decomposition& d, Metrics& m) {
  // A corner is on the original boundary when a boundary piece ends there.
  std::vector<std::uint8_t> on_boundary(d.points.size(), 0);
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    if (d.is_separator(s)) continue;
    on_boundary[d.segments[s].a] = 1;
    on_boundary[d.segments[s].b] = 1;
  }
  std::vector<double> all;
  std::vector<double> at_boundary;
  detail::for_each_new_angle(d, [&](std::uint32_t s, std::uint32_t r, std::uint32_t k, double angle) {
    all.push_back(angle);
    if (on_boundary[d.subdomains[s].rings[r][k]] != 0) at_boundary.push_back(angle);
  });
  std::sort(all.begin(), all.end());
  std::sort(at_boundary.begin(), at_boundary.end());
  m.new_angles = static_cast<std::uint32_t>(all.size());
  m.angle_min = all.empty() ? nan_value : all.front();
  m.angle_p10 = detail::decile(all, 1);
  m.angle_median = median_of(all);
  m.angle_p90 = detail::decile(all, 9);
  m.boundary_angles = static_cast<std::uint32_t>(at_boundary.size());
  m.boundary_angle_min = at_boundary.empty() ? nan_value : at_boundary.front();
  m.boundary_angle_median = median_of(at_boundary);
}

// Pieces of a split input segment are new; a whole input segment is not.
double shortest_new_segment(const Decomposition& d) {
  std::vector<std::uint32_t> pieces;
  for (std::uint32_t origin : d.segment_origin) {
    if (origin == no_index) continue;
    if (origin >= pieces.size()) pieces.resize(std::size_t{origin} + 1, 0);
    ++pieces[origin];
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    const std::uint32_t origin = d.segment_origin[s];
    if (origin != no_index && pieces[origin] < 2) continue;
    shortest = std::min(shortest, distance(d.points[d.segments[s].a], d.points[d.segments[s].b]));
  }
  return std::isinf(shortest) ? nan_value : shortest;
}

void fill_separators(const Decomposition& d, const std::vector<double>& areas, Metrics& m) {
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    if (!d.is_separator(s)) continue;
    ++m.separator_segments;
    m.separator_length += distance(d.points[d.segments[s].a], d.points[d.segments[s].b]);
  }
  m.separator_length_norm = m.domain_area > 0.0 ? m.separator_length / std::sqrt(m.domain_area) : nan_value;
  double sum = 0.0;
  double max_ratio = nan_value;
  for (std::size_t i = 0; i < d.subdomains.size(); ++i) {
    double own = 0.0;
    for (const auto& ring_segments : d.subdomains[i].ring_segments)
      for (std::uint32_t s : ring_segments)
        if (d.is_separator(s)) own += distance(d.points[d.segments[s].a], d.points[d.segments[s].b]);
    sum += own;
    if (areas[i] > 0.0 && !(own / areas[i] <= max_ratio)) max_ratio = own / areas[i];
  }
  m.mean_separator_per_subdomain = d.subdomains.empty() ? nan_value : sum / static_cast<double>(d.subdomains.size());
  m.max_separator_over_area_norm = max_ratio * std::sqrt(m.mean_area);
}

}  // namespace

namespace detail {

double decile(const std::vector<double>& sorted, int q) {
  // Python's statistics.quantiles(data, n=10, method="exclusive").
  const long n = static_cast<long>(sorted.size());
  if (n < 2) return nan_value;
  const long m = n + 1;
  long j = q * m / 10;
  j = std::clamp(j, 1L, n - 1);
  const long delta = q * m - j * 10;
  return (sorted[j - 1] * static_cast<double>(10 - delta) + sorted[j] * static_cast<double>(delta)) / 10.0;
}

}  // namespace detail

namespace {
// Sec. 5.2's stopping rule, checked from the result: area / required area per
// subdomain against the bound the decomposition was split to.
void fill_required_area(const Decomposition& d, const std::vector<double>& areas, Metrics& m) {
  m.max_area_over_required = nan_value;
  m.subdomain_area_ratio = nan_value;
  if (!(d.subdomain_area_ratio > 0.0)) return;
  m.subdomain_area_ratio = d.subdomain_area_ratio;
  m.max_area_over_required = 0.0;
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const double required = d.subdomains[k].required_area;
    const double ratio = std::isfinite(required) && required > 0.0 ? areas[k] / required : 0.0;
    m.max_area_over_required = std::max(m.max_area_over_required, ratio);
    if (ratio > d.subdomain_area_ratio) ++m.subdomains_over_area_bound;
  }
}
}  // namespace

Metrics metrics(const Decomposition& d, std::vector<PhaseTime> times) {
  Metrics m;
  m.subdomains = static_cast<std::uint32_t>(d.subdomains.size());
  m.points = static_cast<std::uint32_t>(d.points.size());
  m.segments = static_cast<std::uint32_t>(d.segments.size());
  m.min_angle_bound_deg = d.separator_angle_deg;
  m.times = std::move(times);

  std::vector<double> areas;
  double weight_sum = 0.0;
  for (const Subdomain& sub : d.subdomains) {
    const double area = detail::rings_area(d.points, sub.rings);
    areas.push_back(area);
    m.domain_area += area;
    weight_sum += sub.weight;
  }
  const double n = static_cast<double>(d.subdomains.size());
  m.mean_area = n > 0 ? m.domain_area / n : nan_value;
  fill_angles(d, m);
  fill_separators(d, areas, m);

  const double mean_weight = n > 0 ? weight_sum / n : nan_value;
  m.max_area_over_mean = m.min_area_over_mean = nan_value;
  m.max_weight_over_mean = m.min_weight_over_mean = nan_value;
  if (!areas.empty()) {
    const auto [lo, hi] = std::minmax_element(areas.begin(), areas.end());
    m.max_area_over_mean = *hi / m.mean_area;
    m.min_area_over_mean = *lo / m.mean_area;
    const auto [wlo, whi] =
        std::minmax_element(d.subdomains.begin(), d.subdomains.end(),
                            [](const Subdomain& a, const Subdomain& b) { return a.weight < b.weight; });
    m.max_weight_over_mean = whi->weight / mean_weight;
    m.min_weight_over_mean = wlo->weight / mean_weight;
  }
  m.shortest_new_segment_norm = shortest_new_segment(d) / std::sqrt(m.mean_area);
  fill_required_area(d, areas, m);
  return m;
}

}  // namespace madd
