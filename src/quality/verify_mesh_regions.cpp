// verify_mesh, what lies inside the subdomains: the isolated input vertices
// as mesh vertices of their subdomain, and the regions (Triangle's -A and
// -a) recomputed by a flood of the mesh itself, from each region point in
// input order, across every edge but boundary and interior segments
// (separators are crossed: they are no constraint of the input), the later
// region winning where two floods meet, as Triangle does.
#include <cmath>
#include <string>
#include <unordered_set>
#include <utility>

#include "kernel/number_format.hpp"
#include "madd/predicates.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

namespace {

std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

// The lowest triangle whose closure holds p (the triangles are known to be
// counter-clockwise by now), or no_index.
std::uint32_t triangle_at(const Mesh& m, Point p) {
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const Point a = m.points[m.triangles[t][0]], b = m.points[m.triangles[t][1]], c = m.points[m.triangles[t][2]];
    if (p.x < std::min({a.x, b.x, c.x}) || p.x > std::max({a.x, b.x, c.x}) || p.y < std::min({a.y, b.y, c.y}) ||
        p.y > std::max({a.y, b.y, c.y}))
      continue;
    if (orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0) return t;
  }
  return no_index;
}

}  // namespace

void check_interior_points(const Mesh& m, ProblemLog& log) {
  const Decomposition& d = m.decomposition;
  std::vector<std::uint32_t> used_by(m.points.size(), no_index);  // a subdomain using each vertex (any one)
  std::vector<std::uint8_t> in_k;
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    const auto& points = d.subdomains[k].interior_points;
    if (points.empty()) continue;
    in_k.assign(m.points.size(), 0);
    for (std::uint32_t t = m.subdomain_first_triangle[k]; t < m.subdomain_first_triangle[k + 1]; ++t)
      for (const std::uint32_t v : m.triangles[t]) in_k[v] = 1;
    for (const std::uint32_t v : points) {
      if (v < m.points.size() && in_k[v] != 0) continue;
      // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive)
      // on "literal" + a temporary string inside the conditional.
      std::string text = "isolated input vertex " + std::to_string(v);
      if (v < m.points.size()) text.append(" ").append(point_text(m.points[v]));
      text.append(" is no vertex of subdomain ").append(std::to_string(k)).append("'s triangles");
      log.add(std::move(text));
    }
  }
}

std::vector<std::uint32_t> mesh_regions(const Mesh& m) {
  const std::vector<Region>& regions = m.decomposition.regions;
  std::vector<std::uint32_t> label(m.triangles.size(), 0);
  if (regions.empty()) return label;
  std::unordered_set<std::uint64_t> constraint;
  for (const MeshSegment& s : m.segments)
    if (!m.decomposition.is_separator(s.piece)) constraint.insert(key(s.a, s.b));
  // Per triangle the last flood that reached it, so that each flood visits
  // its face once.
  std::vector<std::uint32_t> seen(m.triangles.size(), no_index), stack;
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    const std::uint32_t t0 = triangle_at(m, regions[r].at);
    if (t0 == no_index) continue;  // in a hole or outside: no region (Triangle ignores it too)
    seen[t0] = r;
    stack.assign(1, t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      label[t] = r + 1;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t u = m.neighbours[t][i];
        if (u == no_index || seen[u] == r) continue;
        if (constraint.count(key(m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3])) != 0) continue;
        seen[u] = r;
        stack.push_back(u);
      }
    }
  }
  return label;
}

void check_region_attributes(const Mesh& m, const std::vector<std::uint32_t>& label, ProblemLog& log) {
  const std::vector<Region>& regions = m.decomposition.regions;
  if (regions.empty()) return;  // check_mesh_shape: no attributes then
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const double want = label[t] == 0 ? 0.0 : regions[label[t] - 1].attribute;
    const double have = m.triangle_attribute[t];
    if (have == want || (std::isnan(have) && std::isnan(want))) continue;
    log.add(mesh_triangle_text(m, t) + " has region attribute " + number_text(have) + ", but " +
            (label[t] == 0 ? std::string("no region's flood reaches it (attribute 0)")
                           : "the flood from region " + std::to_string(label[t] - 1) + " " +
                                 point_text(regions[label[t] - 1].at) + " gives it " + number_text(want)));
  }
}

}  // namespace madd::detail
