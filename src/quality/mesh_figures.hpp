#pragma once
// The figures of a mesh (madd/mesh_metrics.hpp), for any type with a Mesh's
// fields: a Mesh, a share's LocalMesh, the view of a mesh in pieces
// (mesh/pieces_view.hpp).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/fresh_memory.hpp"
#include "kernel/threads.hpp"
#include "madd/mesh_metrics.hpp"
#include "quality/mesh_angle.hpp"

namespace madd::detail {

// The median is found without sorting or holding every angle: each triangle's
// angle falls in one of 65,536 fine bins of 1/1024 degree (a smallest angle is
// at most 60; the last bin takes anything from 64 on, and NaN), counted on the
// threads; the bin that holds the median is found from the counts, and only the
// angles in it are measured again and selected from. One byte pair a triangle
// instead of the eight a list of angles took, and no serial pass over them.
inline constexpr std::size_t fine_bins = 1 << 16;
inline constexpr double fine_bins_per_degree = 1024.0;

inline std::uint16_t fine_bin(double angle_deg) {
  if (angle_deg >= 0.0 && angle_deg < (fine_bins - 1) / fine_bins_per_degree)
    return static_cast<std::uint16_t>(angle_deg * fine_bins_per_degree);
  return fine_bins - 1;
}

// What one part of the triangles adds to the figures: sums and a minimum,
// so the parts combine to the same figures however the triangles are cut.
struct PartFigures {
  double smallest = 180.0;
  std::array<std::uint64_t, 6> coarse{};
  std::uint64_t below = 0;
  std::vector<std::uint32_t> fine = std::vector<std::uint32_t>(fine_bins, 0);
};

template <class AnyMesh>
double angle_of(const AnyMesh& mesh, std::size_t t) {
  const auto& v = mesh.triangles[t];
  return smallest_angle_deg(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]);
}

// The upper median, element n / 2 of the sorted angles (n the triangle count).
template <class AnyMesh>
double median_angle(const AnyMesh& mesh, const std::vector<std::uint16_t>& bin_of,
                    const std::vector<std::uint32_t>& fine, std::size_t parts, unsigned threads) {
  const std::size_t n = bin_of.size();
  std::size_t rank = n / 2, bin = 0;
  while (rank >= fine[bin]) rank -= fine[bin++];  // the counts add up to n > rank: the loop stops
  std::vector<std::vector<double>> in_bin(parts);
  for_each_on_threads(parts, threads, [&](std::size_t p) {
    for (std::size_t t = n * p / parts; t < n * (p + 1) / parts; ++t)
      if (bin_of[t] == bin) in_bin[p].push_back(angle_of(mesh, t));
  });
  std::vector<double> candidates;
  for (const std::vector<double>& some : in_bin) candidates.insert(candidates.end(), some.begin(), some.end());
  const auto middle = candidates.begin() + static_cast<std::ptrdiff_t>(rank);
  std::nth_element(candidates.begin(), middle, candidates.end());
  return *middle;
}

// A Mesh and a share's LocalMesh hold the same fields a figure reads.
template <class AnyMesh>
MeshMetrics mesh_figures(const AnyMesh& mesh, const MeshSizeOptions& size, unsigned threads) {
  MeshMetrics m;
  m.subdomains =
      mesh.subdomain_first_triangle.empty() ? 0 : static_cast<std::uint32_t>(mesh.subdomain_first_triangle.size() - 1);
  m.triangles = mesh.triangles.size();
  m.vertices = mesh.points.size();
  m.min_angle_bound_deg = mesh.min_triangle_angle_deg;
  m.max_area_bound = size.max_triangle_area;
  m.shortfall = mesh.shortfall;
  const std::size_t n = mesh.triangles.size();
  if (n > 0) {
    // Parts of at least 4096 triangles, four a thread, at most 64 (each holds
    // a quarter megabyte of fine counts).
    const std::size_t parts = std::min<std::size_t>(64, 4 * std::size_t{thread_count(threads, n / 4096 + 1)});
    std::vector<PartFigures> part(parts);
    std::vector<std::uint16_t> bin_of;
    resize_on_threads(bin_of, n, threads);
    const double below = mesh.min_triangle_angle_deg - mesh_angle_slack_deg;
    for_each_on_threads(parts, threads, [&](std::size_t p) {
      PartFigures& f = part[p];
      for (std::size_t t = n * p / parts; t < n * (p + 1) / parts; ++t) {
        const double s = angle_of(mesh, t);
        f.smallest = std::min(f.smallest, s);
        ++f.coarse[std::min<std::size_t>(5, s >= 0.0 && s < 60.0 ? static_cast<std::size_t>(s / 10) : 5)];
        f.below += s < below;
        bin_of[t] = fine_bin(s);
        ++f.fine[bin_of[t]];
      }
    });
    std::vector<std::uint32_t> fine(fine_bins, 0);
    for (const PartFigures& f : part) {
      m.smallest_angle_deg = std::min(m.smallest_angle_deg, f.smallest);
      for (std::size_t b = 0; b < 6; ++b) m.smallest_angle_histogram[b] += f.coarse[b];
      m.below_bound += f.below;
      for (std::size_t b = 0; b < fine_bins; ++b) fine[b] += f.fine[b];
    }
    m.median_smallest_angle_deg = median_angle(mesh, bin_of, fine, parts, threads);
  }
  for (std::uint32_t k = 0; k < m.subdomains; ++k)
    m.largest_subdomain_triangles = std::max<std::uint64_t>(
        m.largest_subdomain_triangles, mesh.subdomain_first_triangle[k + 1] - mesh.subdomain_first_triangle[k]);
  return m;
}

}  // namespace madd::detail
