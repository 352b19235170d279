// Subdomain in, subdomain meshes out: the local view of one subdomain and
// the merge of all of them into one mesh.
#include "mesh/merge.hpp"

#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "madd/error.hpp"

namespace madd::detail {

LocalDomain local_domain(const Decomposition& d, std::uint32_t k) {
  const Subdomain& s = d.subdomains[k];
  LocalDomain out;
  for (std::size_t r = 0; r < s.rings.size(); ++r) {
    const auto first = static_cast<std::uint32_t>(out.pslg.points.size());
    const std::size_t n = s.rings[r].size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t here = first + static_cast<std::uint32_t>(i);
      const std::uint32_t next = i + 1 == n ? first : here + 1;
      const std::uint32_t j = s.ring_segments[r][i];
      out.pslg.points.push_back(d.points[s.rings[r][i]]);
      out.to_global.push_back(s.rings[r][i]);
      out.pslg.segments.push_back({here, next, d.segments[j].marker});
      out.piece.push_back(j);
      out.splittable.push_back(!d.is_separator(j));
    }
  }
  // Interior pieces and isolated vertices: constraints inside the rings. A
  // piece's end is a ring vertex (a segment from the boundary inwards) or
  // another interior vertex, listed once, after the rings.
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  for (std::uint32_t v = 0; v < out.to_global.size(); ++v) local_of.emplace(out.to_global[v], v);
  const auto local_vertex = [&](std::uint32_t g) {
    const auto [it, added] = local_of.emplace(g, static_cast<std::uint32_t>(out.to_global.size()));
    if (added) {
      out.pslg.points.push_back(d.points[g]);
      out.to_global.push_back(g);
    }
    return it->second;
  };
  for (const std::uint32_t j : s.interior_segments) {
    const Segment& g = d.segments[j];
    out.pslg.segments.push_back({local_vertex(g.a), local_vertex(g.b), g.marker});
    out.piece.push_back(j);
    out.splittable.push_back(true);
  }
  for (const std::uint32_t v : s.interior_points) local_vertex(v);
  out.pslg.holes = s.hole_points;
  return out;
}

namespace {

// Global ids of one subdomain mesh's points.
std::vector<std::uint32_t> global_ids(const LocalDomain& local, const SubdomainMesh& piece,
                                      std::uint32_t first_steiner) {
  std::vector<std::uint32_t> ids(piece.points.size());
  for (std::size_t v = 0; v < ids.size(); ++v) {
    ids[v] = v < local.to_global.size() ? local.to_global[v]
                                        : first_steiner + static_cast<std::uint32_t>(v - local.to_global.size());
  }
  return ids;
}

// The edges of each boundary or interior piece (refinement may split both),
// along its local segment: its end, the Steiner points on it by parameter,
// its other end.
void add_boundary_segments(Mesh& m, const LocalDomain& local, const SubdomainMesh& piece,
                           const std::vector<std::uint32_t>& ids) {
  std::vector<std::tuple<std::uint32_t, double, std::uint32_t>> on;  // (local segment, parameter, vertex)
  for (std::size_t v = local.to_global.size(); v < piece.points.size(); ++v) {
    if (piece.point_segment[v] != no_index)
      on.emplace_back(piece.point_segment[v], piece.point_parameter[v], static_cast<std::uint32_t>(v));
  }
  std::sort(on.begin(), on.end());
  std::size_t at = 0;
  for (std::uint32_t s = 0; s < local.pslg.segments.size(); ++s) {
    if (!local.splittable[s]) continue;
    const Segment& seg = local.pslg.segments[s];
    std::uint32_t from = ids[seg.a];
    for (; at < on.size() && std::get<0>(on[at]) == s; ++at) {
      const std::uint32_t v = ids[std::get<2>(on[at])];
      m.segments.push_back({from, v, seg.marker, local.piece[s]});
      from = v;
    }
    m.segments.push_back({from, ids[seg.b], seg.marker, local.piece[s]});
  }
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// Triangles on the two sides of a separator edge see each other: each side
// has the edge as a neighbourless edge; they are paired by their vertices.
void link_across_separators(Mesh& m) {
  std::unordered_map<std::uint64_t, std::uint64_t> open;  // edge -> 3 t + i of the first side seen
  for (const MeshSegment& s : m.segments) {
    if (s.marker == 0 && m.decomposition.is_separator(s.piece)) open.emplace(edge_key(s.a, s.b), ~std::uint64_t{0});
  }
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (m.neighbours[t][i] != no_index) continue;
      const auto it = open.find(edge_key(m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3]));
      if (it == open.end()) continue;
      if (it->second == ~std::uint64_t{0}) {
        it->second = 3 * std::uint64_t{t} + i;
        continue;
      }
      const auto u = static_cast<std::uint32_t>(it->second / 3);
      const auto j = static_cast<std::uint32_t>(it->second % 3);
      m.neighbours[t][i] = u;
      m.neighbours[u][j] = t;
    }
  }
}

}  // namespace

Mesh merge(const Decomposition& d, std::vector<SubdomainMesh>& pieces, double min_triangle_angle_deg,
           const std::vector<bool>* kept) {
  const auto is_kept = [kept](std::uint32_t k) { return kept == nullptr || (*kept)[k]; };
  Mesh m;
  m.decomposition = d;
  m.min_triangle_angle_deg = min_triangle_angle_deg;
  m.points = d.points;
  m.point_markers.assign(d.points.size(), 0);
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    if (d.is_separator(j)) continue;
    const Segment& s = d.segments[j];
    m.point_markers[s.a] = std::max(m.point_markers[s.a], s.marker);
    m.point_markers[s.b] = std::max(m.point_markers[s.b], s.marker);
  }
  std::size_t triangles = 0;
  for (const SubdomainMesh& p : pieces) triangles += p.triangles.size();
  m.triangles.reserve(triangles);
  m.neighbours.reserve(triangles);
  m.triangle_subdomain.reserve(triangles);
  if (!d.regions.empty()) m.triangle_attribute.reserve(triangles);
  m.subdomain_first_triangle.push_back(0);
  std::vector<std::vector<MeshSegment>> boundary(d.segments.size());
  std::vector<bool> kept_separator(d.segments.size(), kept == nullptr);
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    if (!is_kept(k)) {
      m.subdomain_first_triangle.push_back(static_cast<std::uint32_t>(m.triangles.size()));
      continue;
    }
    for (const auto& ring : d.subdomains[k].ring_segments)
      for (const std::uint32_t j : ring) kept_separator[j] = true;
    SubdomainMesh& p = pieces[k];
    const LocalDomain local = local_domain(d, k);
    const auto first_steiner = static_cast<std::uint32_t>(m.points.size());
    const std::vector<std::uint32_t> ids = global_ids(local, p, first_steiner);
    for (std::size_t v = local.to_global.size(); v < p.points.size(); ++v) {
      m.points.push_back(p.points[v]);
      const std::uint32_t s = p.point_segment[v];
      m.point_markers.push_back(s == no_index ? 0 : local.pslg.segments[s].marker);
    }
    const auto base = static_cast<std::uint32_t>(m.triangles.size());
    for (std::size_t t = 0; t < p.triangles.size(); ++t) {
      const auto& tri = p.triangles[t];
      m.triangles.push_back({ids[tri[0]], ids[tri[1]], ids[tri[2]]});
      const auto& n = p.neighbours[t];
      m.neighbours.push_back({n[0] == no_index ? no_index : base + n[0], n[1] == no_index ? no_index : base + n[1],
                              n[2] == no_index ? no_index : base + n[2]});
      m.triangle_subdomain.push_back(k);
    }
    if (!d.regions.empty()) {
      if (p.triangle_attribute.size() == p.triangles.size())
        m.triangle_attribute.insert(m.triangle_attribute.end(), p.triangle_attribute.begin(),
                                    p.triangle_attribute.end());
      else m.triangle_attribute.resize(m.triangles.size(), 0.0);  // a subdomain in no region
    }
    m.subdomain_first_triangle.push_back(static_cast<std::uint32_t>(m.triangles.size()));
    std::vector<MeshSegment> mine;
    std::swap(m.segments, mine);
    add_boundary_segments(m, local, p, ids);
    for (const MeshSegment& s : m.segments) boundary[s.piece].push_back(s);
    std::swap(m.segments, mine);
    m.shortfall.input_angle += p.shortfall.input_angle;
    m.shortfall.separator += p.shortfall.separator;
    m.shortfall.precision += p.shortfall.precision;
    m.shortfall.limit += p.shortfall.limit;
    p = SubdomainMesh{};  // release as we go
  }
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    if (d.is_separator(j)) {
      if (kept_separator[j]) m.segments.push_back({d.segments[j].a, d.segments[j].b, 0, j});
    } else {
      m.segments.insert(m.segments.end(), boundary[j].begin(), boundary[j].end());
    }
  }
  link_across_separators(m);
  return m;
}

}  // namespace madd::detail
