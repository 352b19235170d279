// Subdomain in, subdomain meshes out: the local view of one subdomain and
// the merge of all of them into one mesh.
#include "mesh/merge.hpp"

#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "kernel/fresh_memory.hpp"
#include "kernel/threads.hpp"
#include "madd/error.hpp"

namespace madd::detail {

LocalDomain local_domain(const Decomposition& d, std::uint32_t k) {
  const Subdomain& s = d.subdomains[k];
  LocalDomain out;
  // Every global vertex is one local vertex, listed where it first appears:
  // the rings' vertices in ring order, then the interior pieces' other ends
  // and the isolated vertices. A vertex may stand on a ring twice, or on two
  // rings, where they touch (an island touching the coast at a point).
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  const auto local_vertex = [&](std::uint32_t g) {
    const auto [it, added] = local_of.emplace(g, static_cast<std::uint32_t>(out.to_global.size()));
    if (added) {
      out.pslg.points.push_back(d.points[g]);
      out.to_global.push_back(g);
    }
    return it->second;
  };
  for (std::size_t r = 0; r < s.rings.size(); ++r) {
    const std::size_t n = s.rings[r].size();
    const std::uint32_t first = local_vertex(s.rings[r][0]);
    std::uint32_t here = first;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t next = i + 1 == n ? first : local_vertex(s.rings[r][i + 1]);
      const std::uint32_t j = s.ring_segments[r][i];
      out.pslg.segments.push_back({here, next, d.segments[j].marker});
      out.piece.push_back(j);
      out.splittable.push_back(!d.is_separator(j));
      here = next;
    }
  }
  // Interior pieces and isolated vertices: constraints inside the rings. A
  // piece's end is a ring vertex (a segment from the boundary inwards) or
  // another interior vertex, listed once, after the rings.
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
void add_boundary_segments(std::vector<MeshSegment>& out, const LocalDomain& local, const SubdomainMesh& piece,
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
      out.push_back({from, v, seg.marker, local.piece[s]});
      from = v;
    }
    out.push_back({from, ids[seg.b], seg.marker, local.piece[s]});
  }
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// One subdomain's side of each of its separator segments: the separator
// (global id) and the edge 3 t + i (global t) of the triangle along it.
using SeparatorSides = std::vector<std::pair<std::uint32_t, std::uint64_t>>;

// Subdomain k's triangles along its separator segments (never split, so each
// is one edge with no neighbour across, between the segment's own ends).
SeparatorSides separator_sides(const LocalDomain& local, const SubdomainMesh& p, std::uint32_t first_triangle) {
  std::unordered_map<std::uint64_t, std::uint32_t> separator;  // local edge -> local segment
  for (std::uint32_t s = 0; s < local.pslg.segments.size(); ++s)
    if (!local.splittable[s]) {
      const Segment& g = local.pslg.segments[s];
      separator.emplace(edge_key(g.a, g.b), s);
    }
  SeparatorSides sides;
  if (separator.empty()) return sides;
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      if (p.neighbours[t][i] != no_index) continue;
      const std::uint32_t a = p.triangles[t][(i + 1) % 3], b = p.triangles[t][(i + 2) % 3];
      const auto it = separator.find(edge_key(a, b));
      if (it != separator.end()) sides.emplace_back(local.piece[it->second], 3 * std::uint64_t{first_triangle + t} + i);
    }
  return sides;
}

// Triangles on the two sides of a separator edge see each other: each
// subdomain found its side; the second side found (in subdomain order)
// links the two.
void link_across_separators(Mesh& m, const std::vector<SeparatorSides>& sides) {
  std::vector<std::uint64_t> first_side(m.decomposition.segments.size(), ~std::uint64_t{0});
  for (const SeparatorSides& mine : sides)
    for (const auto& [j, code] : mine) {
      if (first_side[j] == ~std::uint64_t{0}) {
        first_side[j] = code;
        continue;
      }
      const auto t = static_cast<std::uint32_t>(code / 3), u = static_cast<std::uint32_t>(first_side[j] / 3);
      m.neighbours[t][code % 3] = u;
      m.neighbours[u][first_side[j] % 3] = t;
    }
}

// Where each subdomain's Steiner points and triangles go in the merged mesh.
struct Placement {
  std::vector<std::uint32_t> first_point, first_triangle;  // per subdomain, N + 1 entries
};

Placement place(const Decomposition& d, const std::vector<SubdomainMesh>& pieces, const std::vector<LocalDomain>& local,
                const std::vector<bool>& kept) {
  Placement at;
  std::size_t points = d.points.size(), triangles = 0;
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    at.first_point.push_back(static_cast<std::uint32_t>(points));
    at.first_triangle.push_back(static_cast<std::uint32_t>(triangles));
    if (!kept[k]) continue;
    points += pieces[k].points.size() - local[k].to_global.size();
    triangles += pieces[k].triangles.size();
  }
  if (points >= no_index || triangles >= no_index)
    throw LimitError("the merged mesh would have " + std::to_string(points) + " points and " +
                     std::to_string(triangles) + " triangles: more than 32-bit indices can number");
  at.first_point.push_back(static_cast<std::uint32_t>(points));
  at.first_triangle.push_back(static_cast<std::uint32_t>(triangles));
  return at;
}

// Subdomain k's points and triangles into their places (its own ranges:
// any number of subdomains at once); ids: its points' global ids, base: its
// first triangle.
void copy_piece(Mesh& m, const LocalDomain& local, const SubdomainMesh& p, const std::vector<std::uint32_t>& ids,
                std::uint32_t k, std::uint32_t base) {
  for (std::size_t v = local.to_global.size(); v < p.points.size(); ++v) {
    const std::uint32_t g = ids[v];
    m.points[g] = p.points[v];
    const std::uint32_t s = p.point_segment[v];
    m.point_markers[g] = s == no_index ? 0 : local.pslg.segments[s].marker;
  }
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t) {
    const auto& tri = p.triangles[t];
    m.triangles[base + t] = {ids[tri[0]], ids[tri[1]], ids[tri[2]]};
    const auto& n = p.neighbours[t];
    m.neighbours[base + t] = {n[0] == no_index ? no_index : base + n[0], n[1] == no_index ? no_index : base + n[1],
                              n[2] == no_index ? no_index : base + n[2]};
    m.triangle_subdomain[base + t] = k;
  }
  if (!m.decomposition.regions.empty() && p.triangle_attribute.size() == p.triangles.size())
    std::copy(p.triangle_attribute.begin(), p.triangle_attribute.end(), m.triangle_attribute.begin() + base);
}

}  // namespace

// Every subdomain on its own thread into its own ranges (placed by prefix
// sums in subdomain order), then the short serial steps: the segments in
// decomposition order and the links across separators.
Mesh merge(const Decomposition& d, std::vector<SubdomainMesh>& pieces, double min_triangle_angle_deg,
           const std::vector<bool>* kept_or_all, unsigned threads) {
  const std::vector<bool> kept = kept_or_all != nullptr ? *kept_or_all : std::vector<bool>(pieces.size(), true);
  std::vector<LocalDomain> local(pieces.size());
  for_each_on_threads(pieces.size(), threads, [&](std::size_t k) {
    if (kept[k]) local[k] = local_domain(d, static_cast<std::uint32_t>(k));
  });
  const Placement at = place(d, pieces, local, kept);
  Mesh m;
  m.decomposition = d;
  m.min_triangle_angle_deg = min_triangle_angle_deg;
  // The merged arrays' pages are faulted in on the threads that fill them
  // (kernel/fresh_memory.hpp): on one thread they were most of the merge.
  m.points = d.points;
  resize_on_threads(m.points, at.first_point.back(), threads);
  assign_on_threads(m.point_markers, at.first_point.back(), 0, threads);
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    if (d.is_separator(j)) continue;
    const Segment& s = d.segments[j];
    m.point_markers[s.a] = std::max(m.point_markers[s.a], s.marker);
    m.point_markers[s.b] = std::max(m.point_markers[s.b], s.marker);
  }
  const std::uint32_t triangles = at.first_triangle.back();
  resize_on_threads(m.triangles, triangles, threads);
  resize_on_threads(m.neighbours, triangles, threads);
  resize_on_threads(m.triangle_subdomain, triangles, threads);
  if (!d.regions.empty()) assign_on_threads(m.triangle_attribute, triangles, 0.0, threads);  // 0: in no region
  m.subdomain_first_triangle = at.first_triangle;
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    if (!kept[k]) continue;
    m.shortfall.input_angle += pieces[k].shortfall.input_angle;
    m.shortfall.separator += pieces[k].shortfall.separator;
    m.shortfall.precision += pieces[k].shortfall.precision;
    m.shortfall.limit += pieces[k].shortfall.limit;
  }
  std::vector<std::vector<MeshSegment>> segments_of(pieces.size());
  std::vector<SeparatorSides> sides(pieces.size());
  for_each_on_threads(pieces.size(), threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    if (!kept[k]) return;
    SubdomainMesh& p = pieces[k];
    const std::vector<std::uint32_t> ids = global_ids(local[k], p, at.first_point[k]);
    add_boundary_segments(segments_of[k], local[k], p, ids);
    sides[k] = separator_sides(local[k], p, at.first_triangle[k]);
    copy_piece(m, local[k], p, ids, k, at.first_triangle[k]);
    p = SubdomainMesh{};  // release as we go
  });
  // The mesh segments in decomposition-segment order, each piece's in
  // subdomain order (a stable counting sort: no list per piece).
  std::vector<bool> kept_separator(d.segments.size(), kept_or_all == nullptr);
  std::vector<std::uint32_t> first_of(d.segments.size() + 1, 0);
  for (std::uint32_t k = 0; k < pieces.size(); ++k) {
    if (!kept[k]) continue;
    for (const auto& ring : d.subdomains[k].ring_segments)
      for (const std::uint32_t j : ring) kept_separator[j] = true;
    for (const MeshSegment& s : segments_of[k]) ++first_of[s.piece + 1];
  }
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    first_of[j + 1] += first_of[j] + (d.is_separator(j) && kept_separator[j] ? 1 : 0);
  m.segments.resize(first_of.back());
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (d.is_separator(j) && kept_separator[j]) m.segments[first_of[j]++] = {d.segments[j].a, d.segments[j].b, 0, j};
  for (std::uint32_t k = 0; k < pieces.size(); ++k)
    for (const MeshSegment& s : segments_of[k]) m.segments[first_of[s.piece]++] = s;
  link_across_separators(m, sides);
  return m;
}

}  // namespace madd::detail
