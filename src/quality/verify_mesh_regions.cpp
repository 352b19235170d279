// verify_mesh, what lies inside the subdomains: the isolated input vertices
// as mesh vertices of their subdomain, and the regions (Triangle's -A and
// -a) recomputed by a flood of the mesh itself (quality/mesh_regions.hpp;
// separators are crossed: they are no constraint of the input).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "kernel/number_format.hpp"
#include "kernel/threads.hpp"
#include "madd/predicates.hpp"
#include "quality/parallel_log.hpp"
#include "quality/mesh_regions.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

void check_interior_points(const Mesh& m, ProblemLog& log, unsigned threads) {
  const Decomposition& d = m.decomposition;
  // Per subdomain with isolated vertices, on the threads: which of them its
  // triangles use (a flag per isolated vertex, not per mesh point).
  log_in_parts(d.subdomains.size(), d.subdomains.size(), threads, log,
               [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
                 for (auto k = static_cast<std::uint32_t>(begin); k < end; ++k) {
                   const auto& points = d.subdomains[k].interior_points;
                   if (points.empty()) continue;
                   std::vector<std::uint32_t> wanted(points.begin(), points.end());
                   std::sort(wanted.begin(), wanted.end());
                   std::vector<std::uint8_t> used(wanted.size(), 0);
                   for (std::uint32_t t = m.subdomain_first_triangle[k]; t < m.subdomain_first_triangle[k + 1]; ++t)
                     for (const std::uint32_t v : m.triangles[t]) {
                       const auto it = std::lower_bound(wanted.begin(), wanted.end(), v);
                       if (it != wanted.end() && *it == v) used[static_cast<std::size_t>(it - wanted.begin())] = 1;
                     }
                   for (const std::uint32_t v : points) {
                     const auto at =
                         static_cast<std::size_t>(std::lower_bound(wanted.begin(), wanted.end(), v) - wanted.begin());
                     if (v < m.points.size() && used[at] != 0) continue;
                     // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive)
                     // on "literal" + a temporary string inside the conditional.
                     std::string text = "isolated input vertex " + std::to_string(v);
                     if (v < m.points.size()) text.append(" ").append(point_text(m.points[v]));
                     text.append(" is no vertex of subdomain ").append(std::to_string(k)).append("'s triangles");
                     mine.add(std::move(text));
                   }
                 }
               });
}

std::vector<std::uint32_t> mesh_regions(const Mesh& m, unsigned threads) { return mesh_regions_of(m, threads); }

void check_region_attributes(const Mesh& m, const std::vector<std::uint32_t>& label, ProblemLog& log,
                             unsigned threads) {
  check_region_attributes_of(m, label, log, threads, [&m](std::uint32_t t) { return mesh_triangle_text(m, t); });
}

}  // namespace madd::detail
