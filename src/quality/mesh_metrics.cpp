// The figures of a mesh and of the run that made it (include/madd/mesh_metrics.hpp).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "madd/mesh_metrics.hpp"
#include "kernel/threads.hpp"
#include "quality/mesh_angle.hpp"

namespace madd {

double MeshMetrics::share_below_bound() const noexcept {
  return triangles == 0 ? 0.0 : static_cast<double>(below_bound) / static_cast<double>(triangles);
}

double MeshMetrics::max_over_mean_triangles() const noexcept {
  const double mean = subdomains ? static_cast<double>(triangles) / subdomains : 0.0;
  return mean > 0 ? static_cast<double>(largest_subdomain_triangles) / mean : 0.0;
}

namespace {

// A Mesh and a share's LocalMesh hold the same fields a figure reads.
template <class AnyMesh>
MeshMetrics figures_of(const AnyMesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  MeshMetrics m;
  m.subdomains =
      mesh.subdomain_first_triangle.empty() ? 0 : static_cast<std::uint32_t>(mesh.subdomain_first_triangle.size() - 1);
  m.triangles = mesh.triangles.size();
  m.vertices = mesh.points.size();
  m.min_angle_bound_deg = mesh.min_triangle_angle_deg;
  m.max_area_bound = size.max_triangle_area;
  m.shortfall = mesh.shortfall;
  // The angles on the threads, in chunks into their own slots; the figures
  // from them in one pass.
  constexpr std::size_t chunk = 1 << 14;
  std::vector<double> smallest(mesh.triangles.size());
  detail::for_each_on_threads((smallest.size() + chunk - 1) / chunk, threads, [&](std::size_t c) {
    for (std::size_t t = c * chunk; t < std::min(smallest.size(), (c + 1) * chunk); ++t) {
      const auto& v = mesh.triangles[t];
      smallest[t] = detail::smallest_angle_deg(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]);
    }
  });
  for (const double s : smallest) {
    m.smallest_angle_deg = std::min(m.smallest_angle_deg, s);
    ++m.smallest_angle_histogram[std::min<std::size_t>(5, static_cast<std::size_t>(s / 10))];
    m.below_bound += s < mesh.min_triangle_angle_deg - detail::mesh_angle_slack_deg;
  }
  if (!smallest.empty()) {
    const auto middle = smallest.begin() + static_cast<std::ptrdiff_t>(smallest.size() / 2);
    std::nth_element(smallest.begin(), middle, smallest.end());
    m.median_smallest_angle_deg = *middle;
  }
  for (std::uint32_t k = 0; k < m.subdomains; ++k)
    m.largest_subdomain_triangles = std::max<std::uint64_t>(
        m.largest_subdomain_triangles, mesh.subdomain_first_triangle[k + 1] - mesh.subdomain_first_triangle[k]);
  return m;
}

}  // namespace

MeshMetrics mesh_metrics(const Mesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  return figures_of(mesh, size, threads);
}
MeshMetrics mesh_metrics(const LocalMesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  return figures_of(mesh, size, threads);
}

std::vector<RunFigure> run_figures(const MeshReport& report) {
  double busiest = 0, busy = 0;
  for (const double s : report.thread_seconds) {
    busiest = std::max(busiest, s);
    busy += s;
  }
  const auto threads = static_cast<double>(report.thread_seconds.size());
  double predicted = 0;
  for (const double t : report.expected_triangles) predicted += t;
  return {{"threads", threads},
          {"thread_imbalance", busy > 0 ? busiest * threads / busy : 0.0},
          {"thread_seconds", report.thread_seconds},
          {"phase_seconds", report.phases},
          {"predicted_triangles", predicted},
          {"subdomain_predicted_triangles", report.expected_triangles}};
}

}  // namespace madd
