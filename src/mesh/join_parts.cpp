// The whole mesh from every share's part (include/madd/mesh_share.hpp,
// join_parts): each part's vertices and triangles under their global ids,
// the neighbours across shares matched by edge, the segments in mesh()'s
// order (src/mesh/merge.cpp: by piece; a separator once, unsplit; a
// boundary or interior piece's edges as the one subdomain holding it lists them).
#include <algorithm>
#include <string>
#include <unordered_map>

#include "madd/error.hpp"
#include "madd/mesh_share.hpp"
#include "kernel/edge_key.hpp"

namespace madd {

namespace {

[[noreturn]] void not_one_run(const std::string& what) {
  throw InvalidInputError(InputProblem::other, "join_parts: the parts are not those of one run: " + what);
}

std::uint32_t global_id(std::uint64_t id, std::uint64_t total, const char* what) {
  if (id >= total) not_one_run(std::string(what) + " id out of range");
  return static_cast<std::uint32_t>(id);
}

// Points, markers, triangles, subdomains, attributes and the neighbours
// within each part, at their global ids.
void place_parts(std::span<const MeshPart> parts, Mesh& m, std::vector<bool>& placed) {
  for (const MeshPart& part : parts) {
    const LocalMesh& l = part.mesh;
    if (part.point_ids.size() != l.points.size() || part.triangle_ids.size() != l.triangles.size())
      not_one_run("a part's ids do not match its mesh");
    for (std::size_t v = 0; v < l.points.size(); ++v) {
      const std::uint32_t g = global_id(part.point_ids[v], m.points.size(), "a point");
      m.points[g] = l.points[v];
      m.point_markers[g] = l.point_markers[v];
    }
    for (std::size_t t = 0; t < l.triangles.size(); ++t) {
      const std::uint32_t g = global_id(part.triangle_ids[t], m.triangles.size(), "a triangle");
      if (placed[g]) not_one_run("triangle " + std::to_string(g) + " is in two parts");
      placed[g] = true;
      for (int i = 0; i < 3; ++i) {
        m.triangles[g][i] = global_id(part.point_ids[l.triangles[t][i]], m.points.size(), "a point");
        const std::uint32_t n = l.neighbours[t][i];
        m.neighbours[g][i] =
            n == no_index ? no_index : global_id(part.triangle_ids[n], m.triangles.size(), "a triangle");
      }
      m.triangle_subdomain[g] = l.triangle_subdomain[t];
      if (!l.triangle_attribute.empty()) m.triangle_attribute[g] = l.triangle_attribute[t];
    }
  }
}

// The edges no part has a neighbour across: matched in pairs (a separator
// between two shares), the rest the domain's boundary.
void link_across_shares(Mesh& m) {
  std::unordered_map<std::uint64_t, std::uint32_t> open;  // edge -> 3 t + i
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (m.neighbours[t][i] != no_index) continue;
      const std::uint64_t key = detail::edge_key(m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3]);
      const auto [at, added] = open.emplace(key, 3 * t + i);
      if (added) continue;
      const std::uint32_t other = at->second;
      m.neighbours[t][i] = other / 3;
      m.neighbours[other / 3][other % 3] = t;
      open.erase(at);
    }
}

// mesh()'s segments: by piece of the decomposition, a separator once.
void gather_segments(std::span<const MeshPart> parts, Mesh& m) {
  const Decomposition& d = m.decomposition;
  std::vector<std::vector<MeshSegment>> by_piece(d.segments.size());
  for (const MeshPart& part : parts)
    for (const MeshSegment& s : part.mesh.segments) {
      if (s.piece >= d.segments.size()) not_one_run("a segment's piece is out of range");
      if (d.is_separator(s.piece) && !by_piece[s.piece].empty()) continue;  // the other side's copy
      by_piece[s.piece].push_back({global_id(part.point_ids.at(s.a), m.points.size(), "a point"),
                                   global_id(part.point_ids.at(s.b), m.points.size(), "a point"), s.marker, s.piece});
    }
  for (const std::vector<MeshSegment>& piece : by_piece)
    m.segments.insert(m.segments.end(), piece.begin(), piece.end());
}

}  // namespace

Mesh join_parts(std::span<const MeshPart> parts) {
  if (parts.empty()) not_one_run("there are none");
  const MeshPart& first = parts.front();
  std::vector<bool> share_seen(first.shares, false);
  for (const MeshPart& part : parts) {
    if (part.shares != first.shares || part.share >= part.shares || share_seen[part.share])
      not_one_run("a share is missing or given twice");
    share_seen[part.share] = true;
  }
  if (parts.size() != first.shares) not_one_run("a share is missing");
  Mesh m;
  m.decomposition = first.decomposition;
  m.points.resize(first.total_points);
  m.point_markers.resize(first.total_points, 0);
  m.triangles.resize(first.total_triangles);
  m.neighbours.resize(first.total_triangles);
  m.triangle_subdomain.resize(first.total_triangles, 0);
  if (!first.decomposition.regions.empty()) m.triangle_attribute.resize(first.total_triangles, 0.0);
  std::vector<bool> placed(first.total_triangles, false);
  place_parts(parts, m, placed);
  if (std::find(placed.begin(), placed.end(), false) != placed.end()) not_one_run("a triangle is in no part");
  link_across_shares(m);
  gather_segments(parts, m);
  const std::uint32_t n = static_cast<std::uint32_t>(first.owner.size());
  m.subdomain_first_triangle.assign(n + 1, 0);
  for (const std::uint32_t k : m.triangle_subdomain) ++m.subdomain_first_triangle.at(k + 1);
  for (std::uint32_t k = 0; k < n; ++k) m.subdomain_first_triangle[k + 1] += m.subdomain_first_triangle[k];
  for (const MeshPart& part : parts) {
    m.shortfall.input_angle += part.mesh.shortfall.input_angle;
    m.shortfall.separator += part.mesh.shortfall.separator;
    m.shortfall.precision += part.mesh.shortfall.precision;
    m.shortfall.limit += part.mesh.shortfall.limit;
  }
  m.min_triangle_angle_deg = first.mesh.min_triangle_angle_deg;
  return m;
}

}  // namespace madd
