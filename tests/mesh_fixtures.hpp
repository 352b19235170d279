#pragma once
// Mesh options for tests, and a madd::Mesh made without the mesher, for
// testing what reads meshes (outputs, verify_mesh) independently of
// refinement: each subdomain of a
// decomposition triangulated on its own by madd::triangulate (its ring
// vertices only, no Steiner points), the pieces merged by global point index.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"

namespace madd::test {

// Mesh options for N subdomains, angle bound q and area bound `area` (0 =
// none), on one thread.
inline MeshOptions options_for(std::uint32_t n, double q, double area) {
  MeshOptions o;
  o.decomposition.subdomains = n;
  o.decomposition.threads = 1;
  o.size.min_triangle_angle_deg = q;
  o.size.max_triangle_area = area;
  return o;
}

// The subdomain's rings as a standalone Pslg; local_to_global[i] is the
// decomposition point of local point i.
inline Pslg subdomain_pslg(const Decomposition& d, const Subdomain& s, std::vector<std::uint32_t>& local_to_global) {
  Pslg p;
  local_to_global.clear();
  for (std::size_t r = 0; r < s.rings.size(); ++r) {
    const auto first = static_cast<std::uint32_t>(p.points.size());
    for (std::size_t k = 0; k < s.rings[r].size(); ++k) {
      local_to_global.push_back(s.rings[r][k]);
      p.points.push_back(d.points[s.rings[r][k]]);
      const auto here = static_cast<std::uint32_t>(p.points.size() - 1);
      const std::uint32_t next = k + 1 == s.rings[r].size() ? first : here + 1;
      p.segments.push_back({here, next, d.segments[s.ring_segments[r][k]].marker});
    }
  }
  p.holes = s.hole_points;
  return p;
}

// Per triangle of `m`: the attribute of the input region its centroid lies
// in, by Triangle's -A on the decomposition's boundary and interior pieces
// (madd::triangulate), the centroid located by brute force; 0 in none.
inline std::vector<double> region_attributes_by_centroid(const Decomposition& d, const Mesh& m) {
  Pslg whole;
  whole.points = d.points;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (!d.is_separator(j)) whole.segments.push_back(d.segments[j]);
  whole.holes = d.holes;
  whole.regions = d.regions;
  TriangulateOptions a;
  a.region_attributes = true;
  const Triangulation t = triangulate(whole, a);
  std::vector<double> out;
  for (const auto& tri : m.triangles) {
    const Point g = triangle_centroid(m.points[tri[0]], m.points[tri[1]], m.points[tri[2]]);
    double attribute = 0.0;
    for (std::size_t u = 0; u < t.triangles.size(); ++u) {
      const Point p = t.points[t.triangles[u][0]], q = t.points[t.triangles[u][1]], r = t.points[t.triangles[u][2]];
      if (orient2d(p, q, g) >= 0 && orient2d(q, r, g) >= 0 && orient2d(r, p, g) >= 0) {
        attribute = t.attributes[u];
        break;
      }
    }
    out.push_back(attribute);
  }
  return out;
}

// Every subdomain triangulated without Steiner points, merged into one Mesh
// (min_triangle_angle_deg 0: nothing is promised about angles).
inline Mesh mesh_without_steiner_points(const Decomposition& d) {
  Mesh m;
  m.decomposition = d;
  m.points = d.points;
  m.min_triangle_angle_deg = 0.0;
  m.point_markers.assign(d.points.size(), 0);
  for (std::size_t j = 0; j < d.segments.size(); ++j) {
    const Segment& s = d.segments[j];
    if (!d.is_separator(static_cast<std::uint32_t>(j))) {
      m.point_markers[s.a] = std::max(m.point_markers[s.a], s.marker);
      m.point_markers[s.b] = std::max(m.point_markers[s.b], s.marker);
    }
    m.segments.push_back(
        {s.a, s.b, d.is_separator(static_cast<std::uint32_t>(j)) ? 0 : s.marker, static_cast<std::uint32_t>(j)});
  }
  m.subdomain_first_triangle.push_back(0);
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    std::vector<std::uint32_t> to_global;
    const Triangulation t = triangulate(subdomain_pslg(d, d.subdomains[k], to_global));
    for (const auto& tri : t.triangles) {
      m.triangles.push_back({to_global[tri[0]], to_global[tri[1]], to_global[tri[2]]});
      m.triangle_subdomain.push_back(k);
    }
    m.subdomain_first_triangle.push_back(static_cast<std::uint32_t>(m.triangles.size()));
  }
  if (!d.regions.empty()) m.triangle_attribute = region_attributes_by_centroid(d, m);
  // Neighbours by matching each directed edge with its reverse.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_triangle;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) edge_triangle[{m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3]}] = t;
  }
  m.neighbours.assign(m.triangles.size(), {no_index, no_index, no_index});
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const auto it = edge_triangle.find({m.triangles[t][(i + 2) % 3], m.triangles[t][(i + 1) % 3]});
      if (it != edge_triangle.end()) m.neighbours[t][i] = it->second;
    }
  }
  return m;
}

}  // namespace madd::test
