// The figures of a mesh and of the run that made it (include/madd/mesh_metrics.hpp).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstddef>
#include <vector>

#include "madd/mesh_metrics.hpp"
#include "quality/mesh_figures.hpp"

namespace madd {

double MeshMetrics::share_below_bound() const noexcept {
  return triangles == 0 ? 0.0 : static_cast<double>(below_bound) / static_cast<double>(triangles);
}

double MeshMetrics::max_over_mean_triangles() const noexcept {
  const double mean = subdomains ? static_cast<double>(triangles) / subdomains : 0.0;
  return mean > 0 ? static_cast<double>(largest_subdomain_triangles) / mean : 0.0;
}

MeshMetrics mesh_metrics(const Mesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  return detail::mesh_figures(mesh, size, threads);
}
MeshMetrics mesh_metrics(const LocalMesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  return detail::mesh_figures(mesh, size, threads);
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
