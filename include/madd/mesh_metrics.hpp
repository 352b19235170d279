#pragma once
// The quality figures of a mesh (docs/mesh.md, "The report"): every
// triangle's smallest angle against the bound, why triangles stayed below it,
// and the balance of the subdomains' triangle counts; and the figures of the
// run that made it. format_mesh_report_json (madd/mesh_output.hpp) writes
// them as `madd mesh --report` and `madd-mpi mesh --report` do, as the
// decomposition's Metrics (madd/metrics.hpp) are written by format_report_json.
#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/mesh_share.hpp"

namespace madd {

// The figures of one mesh: the same for every run with the same options.
// Angles in degrees; a triangle's angle is its smallest, measured as
// verify_mesh measures it. The counts add up over the parts of a mesh
// (MeshPart, madd/mesh_share.hpp) and smallest_angle_deg is the minimum over them,
// so a distributed driver combines its parts' figures; the median does not
// combine (NaN then).
struct MeshMetrics {
  std::uint32_t subdomains = 0;
  std::uint64_t triangles = 0;
  std::uint64_t vertices = 0;
  double min_angle_bound_deg = 0.0;  // the bound the mesh was refined to (Mesh::min_triangle_angle_deg)
  double max_area_bound = 0.0;  // the largest triangle area asked for (MeshSizeOptions::max_triangle_area; 0 = none)
  double smallest_angle_deg = 180.0;       // the smallest angle of any triangle (180 without triangles)
  double median_smallest_angle_deg = 0.0;  // the upper median over the triangles; NaN: not known
  // Triangles in 10-degree bins of their angle: [0, 10), ..., [40, 50), and [50, 60] last.
  std::array<std::uint64_t, 6> smallest_angle_histogram{};
  // Triangles below the bound (by more than the slack verify_mesh allows),
  // and why the mesher left them there.
  std::uint64_t below_bound = 0;
  MeshShortfall shortfall;
  std::uint64_t largest_subdomain_triangles = 0;  // the triangles of the subdomain that has most

  // below_bound over the triangles (0 without triangles).
  double share_below_bound() const noexcept;
  // largest_subdomain_triangles over the mean per subdomain (0 without triangles): the
  // balance of work the decomposition aimed for.
  double max_over_mean_triangles() const noexcept;
  friend bool operator==(const MeshMetrics&, const MeshMetrics&) = default;
};

// Every figure of `mesh`; max_area_bound from `size`. The angles are measured
// on `threads` threads (0: one per core), the same figures for any count.
MeshMetrics mesh_metrics(const Mesh& mesh, const MeshSizeOptions& size = {}, unsigned threads = 1);
// The same figures of one share's triangles (MeshPart::mesh): subdomains is
// the whole count, largest_subdomain_triangles that of the share's largest.
MeshMetrics mesh_metrics(const LocalMesh& mesh, const MeshSizeOptions& size = {}, unsigned threads = 1);
// The figures of a mesh kept in pieces: those of join(mesh).
MeshMetrics mesh_metrics(const MeshPieces& mesh, const MeshSizeOptions& size = {}, unsigned threads = 1);

// One figure of a run beside the mesh's own, as a report writes it after
// them: a number, a list of seconds, or named seconds. Run figures (times,
// thread and rank counts) vary from run to run; MeshMetrics never does.
struct RunFigure {
  std::string name;
  std::variant<double, std::vector<double>, std::vector<PhaseTime>> value;
  friend bool operator==(const RunFigure&, const RunFigure&) = default;
};

// The figures of one call of mesh(): "threads", "thread_imbalance" (the
// busiest thread's seconds over the mean, 0 when none was busy),
// "thread_seconds", "phase_seconds", "predicted_triangles" (the work
// estimate of the whole mesh) and "subdomain_predicted_triangles" (of each
// subdomain; docs/mesh.md, "Balance by work").
std::vector<RunFigure> run_figures(const MeshReport& report);

}  // namespace madd
