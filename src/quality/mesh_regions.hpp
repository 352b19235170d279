#pragma once
// The regions of a mesh (Triangle's -A and -a) recomputed by a flood of the
// mesh itself, for any type with a Mesh's fields: verify_mesh reads a Mesh
// (verify_mesh_regions.cpp), the check of a mesh kept in pieces its view
// (mesh/pieces_check.cpp), so that the flood crosses the separators there
// too: from each region point in input order, across every edge but
// boundary and interior segments, the later region winning where two floods
// meet, as Triangle does.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "kernel/edge_key.hpp"
#include "kernel/number_format.hpp"
#include "kernel/threads.hpp"
#include "madd/mesh.hpp"
#include "madd/predicates.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

// The lowest triangle whose closure holds p (the triangles are known to be
// counter-clockwise by now), or no_index: the triangles scanned in parts on
// `threads` threads, each part's lowest, the lowest of those.
// Calls fn(t, corners, links) for each triangle t of subdomain k in order,
// with its corners and the triangles across its edges (a view of a mesh in
// pieces has its own, mesh/pieces_view.hpp, reading the piece directly).
template <typename AnyMesh, typename Fn>
void for_each_triangle_in(const AnyMesh& m, std::uint32_t k, const Fn& fn) {
  for (std::uint32_t t = m.subdomain_first_triangle[k]; t < m.subdomain_first_triangle[k + 1]; ++t)
    fn(t, m.triangles[t], m.neighbours[t]);
}

template <typename AnyMesh>
std::uint32_t triangle_at(const AnyMesh& m, Point p, unsigned threads) {
  const std::size_t nt = m.triangles.size();
  const std::size_t parts =
      std::clamp<std::size_t>(4 * std::size_t{thread_count(threads, nt)}, 1, std::max<std::size_t>(nt, 1));
  std::vector<std::uint32_t> found(parts, no_index);
  for_each_on_threads(parts, threads, [&](std::size_t part) {
    for (auto t = static_cast<std::uint32_t>(nt * part / parts); t < nt * (part + 1) / parts; ++t) {
      const std::array<std::uint32_t, 3> corners = m.triangles[t];
      const Point a = m.points[corners[0]], b = m.points[corners[1]], c = m.points[corners[2]];
      if (p.x < std::min({a.x, b.x, c.x}) || p.x > std::max({a.x, b.x, c.x}) || p.y < std::min({a.y, b.y, c.y}) ||
          p.y > std::max({a.y, b.y, c.y}))
        continue;
      if (orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0) {
        found[part] = t;
        return;
      }
    }
  });
  for (const std::uint32_t t : found)
    if (t != no_index) return t;
  return no_index;
}

// The flood of each region reaches the triangles connected to its first
// one across edges that are no constraint: a component of that adjacency
// (the mesh's links are mutual, or the edge pass has said otherwise). The
// components are found per subdomain on `threads` threads (by union-find
// inside its triangle range, numbered in its order there), joined across the links
// that leave a subdomain (separators, mostly) by union-find, and each
// region colours its component, in input order, the later winning.
template <typename AnyMesh>
std::vector<std::uint32_t> mesh_regions_of(const AnyMesh& m, unsigned threads) {
  const std::vector<Region>& regions = m.decomposition.regions;
  std::vector<std::uint32_t> label(m.triangles.size(), 0);
  if (regions.empty()) return label;
  // The edges a flood does not cross; an edge is looked up only when both
  // its ends lie on one (most edges have neither).
  std::unordered_set<std::uint64_t> constraint;
  std::vector<std::uint8_t> on_constraint(m.points.size(), 0);
  for (const MeshSegment& s : m.segments)
    if (!m.decomposition.is_separator(s.piece)) {
      constraint.insert(edge_key(s.a, s.b));
      on_constraint[s.a] = on_constraint[s.b] = 1;
    }
  const auto crosses = [&](const std::array<std::uint32_t, 3>& corners, int i) {
    const std::uint32_t a = corners[(i + 1) % 3], b = corners[(i + 2) % 3];
    return on_constraint[a] == 0 || on_constraint[b] == 0 || constraint.count(edge_key(a, b)) == 0;
  };
  // label[t] first holds t's component, numbered within its subdomain.
  const auto& first = m.subdomain_first_triangle;
  const std::size_t n = first.size() - 1;
  std::vector<std::uint32_t> components(n, 0);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> leaving(n);  // links out of each subdomain
  // Within a subdomain by union-find in triangle order (the arrays read in
  // order, not in a flood's jumps): every crossable link joins its two
  // triangles, the lower the root, so a component's root is its lowest
  // triangle and the components are numbered in the order of their lowest
  // triangles, as a flood from each unvisited triangle in turn numbers them.
  for_each_on_threads(n, threads, [&](std::size_t k) {
    const std::uint32_t begin = first[k], count = first[k + 1] - first[k];
    std::vector<std::uint32_t> parent(count);
    for (std::uint32_t i = 0; i < count; ++i) parent[i] = i;
    const auto root = [&](std::uint32_t c) {
      while (parent[c] != c) c = parent[c] = parent[parent[c]];
      return c;
    };
    for_each_triangle_in(
        m, static_cast<std::uint32_t>(k),
        [&](std::uint32_t t, const std::array<std::uint32_t, 3>& corners, const std::array<std::uint32_t, 3>& links) {
          const std::uint32_t i = t - begin;
          for (int e = 0; e < 3; ++e) {
            const std::uint32_t u = links[e];
            if (u == no_index || !crosses(corners, e)) continue;
            if (u < begin || u >= begin + count) {
              leaving[k].emplace_back(t, u);
            } else if (u < t) {  // each link inside once, from its higher end
              const std::uint32_t a = root(i), b = root(u - begin);
              if (a != b) parent[std::max(a, b)] = std::min(a, b);
            }
          }
        });
    for (std::uint32_t i = 0; i < count; ++i) {  // a root comes before the rest of its component
      const std::uint32_t r = root(i);
      label[begin + i] = r == i ? components[k]++ : label[begin + r];
    }
  });
  // The components numbered across subdomains, joined along the links that
  // leave them by union-find (the lower number the root).
  std::vector<std::uint32_t> base(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) base[k + 1] = base[k] + components[k];
  const auto component = [&](std::uint32_t t) { return base[m.triangle_subdomain[t]] + label[t]; };
  std::vector<std::uint32_t> parent(base[n]);
  for (std::uint32_t c = 0; c < parent.size(); ++c) parent[c] = c;
  const auto root = [&](std::uint32_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  for (const auto& links : leaving)
    for (const auto& [t, u] : links) {
      const std::uint32_t a = root(component(t)), b = root(component(u));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::uint32_t> region_of(base[n], 0);  // per root: 1 + its region, 0 for none
  for (std::uint32_t r = 0; r < regions.size(); ++r) {
    const std::uint32_t t0 = triangle_at(m, regions[r].at, threads);
    if (t0 != no_index) region_of[root(component(t0))] = r + 1;  // in a hole or outside: no region (as Triangle)
  }
  for (std::uint32_t c = 0; c < region_of.size(); ++c) region_of[c] = region_of[root(c)];
  for_each_on_threads(n, threads, [&](std::size_t k) {
    for (std::uint32_t t = first[k]; t < first[k + 1]; ++t) label[t] = region_of[base[k] + label[t]];
  });
  return label;
}

template <typename AnyMesh, typename Text>
void check_region_attributes_of(const AnyMesh& m, const std::vector<std::uint32_t>& label, ProblemLog& log,
                                unsigned threads, const Text& triangle_text) {
  const std::vector<Region>& regions = m.decomposition.regions;
  if (regions.empty()) return;  // check_mesh_shape: no attributes then
  const std::size_t nt = m.triangles.size();
  log_in_parts(nt, 4 * std::size_t{thread_count(threads, nt)}, threads, log,
               [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& mine) {
                 for (auto t = static_cast<std::uint32_t>(begin); t < end; ++t) {
                   const double want = label[t] == 0 ? 0.0 : regions[label[t] - 1].attribute;
                   const double have = m.triangle_attribute[t];
                   if (have == want || (std::isnan(have) && std::isnan(want))) continue;
                   mine.add(triangle_text(t) + " has region attribute " + number_text(have) + ", but " +
                            (label[t] == 0
                                 ? std::string("no region's flood reaches it (attribute 0)")
                                 : "the flood from region " + std::to_string(label[t] - 1) + " " +
                                       point_text(regions[label[t] - 1].at) + " gives it " + number_text(want)));
                 }
               });
}

}  // namespace madd::detail
