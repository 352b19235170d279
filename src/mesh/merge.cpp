// Subdomain in, subdomain meshes out: the local view of one subdomain and
// the merge of all of them into one mesh.
#include "mesh/merge.hpp"
#include "mesh/mesh_pieces.hpp"

#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "kernel/fresh_memory.hpp"
#include "kernel/threads.hpp"
#include "madd/error.hpp"
#include "kernel/edge_key.hpp"

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

// The edges of each boundary or interior piece (refinement may split both),
// along its local segment: its end, the Steiner points on it by parameter,
// its other end.
void add_boundary_segments(std::vector<MeshSegment>& out, const MeshPiecesData& m, std::uint32_t k) {
  const LocalDomain& local = m.local[k];
  const SubdomainMesh& piece = m.pieces[k];
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
    std::uint32_t from = m.global_point(k, seg.a);
    for (; at < on.size() && std::get<0>(on[at]) == s; ++at) {
      const std::uint32_t v = m.global_point(k, std::get<2>(on[at]));
      out.push_back({from, v, seg.marker, local.piece[s]});
      from = v;
    }
    out.push_back({from, m.global_point(k, seg.b), seg.marker, local.piece[s]});
  }
}

// One subdomain's side of each of its separator segments: the separator
// (global id) and the edge 3 t + i (local t) of the triangle along it.
using SeparatorSides = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// Subdomain k's triangles along its separator segments (never split, so each
// is one edge with no neighbour across, between the segment's own ends).
SeparatorSides separator_sides(const LocalDomain& local, const SubdomainMesh& p) {
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
      if (it != separator.end()) sides.emplace_back(local.piece[it->second], 3 * t + i);
    }
  return sides;
}

// Triangles on the two sides of a separator edge see each other: each
// subdomain found its side; the second side found (in subdomain order)
// links the two.
void link_across_separators(MeshPiecesData& m, const std::vector<SeparatorSides>& sides) {
  constexpr std::uint64_t none = ~std::uint64_t{0};
  std::vector<std::uint64_t> first_side(m.decomposition.segments.size(), none);  // (k << 32) | local code
  m.across.assign(sides.size(), {});
  for (std::uint32_t k = 0; k < sides.size(); ++k)
    for (const auto& [j, code] : sides[k]) {
      if (first_side[j] == none) {
        first_side[j] = (std::uint64_t{k} << 32) | code;
        continue;
      }
      const auto h = static_cast<std::uint32_t>(first_side[j] >> 32);
      const auto other = static_cast<std::uint32_t>(first_side[j]);
      m.across[k].emplace_back(code, m.first_triangle[h] + other / 3);
      m.across[h].emplace_back(other, m.first_triangle[k] + code / 3);
    }
  for (auto& list : m.across) std::sort(list.begin(), list.end());
}

// Where each subdomain's Steiner points and triangles go in the merged mesh.
void place(MeshPiecesData& m, const std::vector<bool>& kept) {
  std::size_t points = m.decomposition.points.size(), triangles = 0;
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k) {
    m.first_point.push_back(static_cast<std::uint32_t>(points));
    m.first_triangle.push_back(static_cast<std::uint32_t>(triangles));
    if (!kept[k]) continue;
    points += m.pieces[k].points.size() - m.local[k].to_global.size();
    triangles += m.pieces[k].triangles.size();
  }
  if (points >= no_index || triangles >= no_index)
    throw LimitError("the merged mesh would have " + std::to_string(points) + " points and " +
                     std::to_string(triangles) + " triangles: more than 32-bit indices can number");
  m.first_point.push_back(static_cast<std::uint32_t>(points));
  m.first_triangle.push_back(static_cast<std::uint32_t>(triangles));
}

// The mesh segments in decomposition-segment order, each piece's in
// subdomain order (a stable counting sort: no list per piece).
void gather_segments(MeshPiecesData& m, const std::vector<std::vector<MeshSegment>>& segments_of,
                     const std::vector<bool>& kept, bool all) {
  const Decomposition& d = m.decomposition;
  std::vector<bool> kept_separator(d.segments.size(), all);
  std::vector<std::uint32_t> first_of(d.segments.size() + 1, 0);
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k) {
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
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k)
    for (const MeshSegment& s : segments_of[k]) m.segments[first_of[s.piece]++] = s;
}

// Subdomain k's points and triangles into their places (its own ranges:
// any number of subdomains at once).
void copy_piece(Mesh& out, const MeshPiecesData& m, std::uint32_t k) {
  const LocalDomain& local = m.local[k];
  const SubdomainMesh& p = m.pieces[k];
  for (std::uint32_t v = static_cast<std::uint32_t>(local.to_global.size()); v < p.points.size(); ++v) {
    const std::uint32_t g = m.global_point(k, v);
    out.points[g] = p.points[v];
    out.point_markers[g] = m.steiner_marker(k, v);
  }
  const std::uint32_t base = m.first_triangle[k];
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t) {
    const auto& tri = p.triangles[t];
    out.triangles[base + t] = {m.global_point(k, tri[0]), m.global_point(k, tri[1]), m.global_point(k, tri[2])};
    const auto& n = p.neighbours[t];
    for (std::uint32_t i = 0; i < 3; ++i)
      out.neighbours[base + t][i] = n[i] == no_index ? m.global_neighbour(k, t, i) : base + n[i];
    out.triangle_subdomain[base + t] = k;
  }
  if (!m.decomposition.regions.empty() && p.triangle_attribute.size() == p.triangles.size())
    std::copy(p.triangle_attribute.begin(), p.triangle_attribute.end(), out.triangle_attribute.begin() + base);
}

}  // namespace

namespace {

// The range of `first` (offsets, one more than the ranges) holding i: the
// last whose start is at or before i (empty ones skipped). Readers go
// through the mesh in order, so each thread first tries the range it found
// last (for the same offsets), then searches.
std::uint32_t range_of(const std::vector<std::uint32_t>& first, std::uint32_t i) {
  thread_local const std::vector<std::uint32_t>* last_offsets = nullptr;
  thread_local std::uint32_t last = 0;
  if (last_offsets == &first && last + 1 < first.size() && first[last] <= i && i < first[last + 1]) return last;
  last = static_cast<std::uint32_t>(std::upper_bound(first.begin(), first.end() - 1, i) - first.begin() - 1);
  last_offsets = &first;
  return last;
}

}  // namespace

std::uint32_t MeshPiecesData::subdomain_of_triangle(std::uint32_t t) const { return range_of(first_triangle, t); }

std::uint32_t MeshPiecesData::subdomain_of_point(std::uint32_t v) const { return range_of(first_point, v); }

std::uint32_t MeshPiecesData::global_neighbour(std::uint32_t k, std::uint32_t t, std::uint32_t i) const {
  const std::uint32_t n = pieces[k].neighbours[t][i];
  if (n != no_index) return first_triangle[k] + n;
  const auto& list = across[k];
  const auto it = std::lower_bound(list.begin(), list.end(), std::pair{3 * t + i, std::uint32_t{0}});
  return it != list.end() && it->first == 3 * t + i ? it->second : no_index;
}

int MeshPiecesData::point_marker(std::uint32_t v) const {
  if (v < point_markers.size()) return point_markers[v];
  const std::uint32_t k = subdomain_of_point(v);
  return steiner_marker(k, v - first_point[k] + static_cast<std::uint32_t>(local[k].to_global.size()));
}

// Every subdomain's local view and segments on the threads, then the short
// serial steps: the placement by prefix sums, the segments in decomposition
// order and the links across separators.
MeshPiecesData assemble(Decomposition d, std::vector<SubdomainMesh>&& pieces, double min_triangle_angle_deg,
                        const std::vector<bool>* kept_or_all, unsigned threads) {
  const std::vector<bool> kept = kept_or_all != nullptr ? *kept_or_all : std::vector<bool>(pieces.size(), true);
  MeshPiecesData m;
  m.decomposition = std::move(d);
  m.pieces = std::move(pieces);
  m.min_triangle_angle_deg = min_triangle_angle_deg;
  m.local.resize(m.pieces.size());
  for_each_on_threads(m.pieces.size(), threads, [&](std::size_t k) {
    if (kept[k]) m.local[k] = local_domain(m.decomposition, static_cast<std::uint32_t>(k));
  });
  place(m, kept);
  m.point_markers.assign(m.decomposition.points.size(), 0);
  for (std::uint32_t j = 0; j < m.decomposition.segments.size(); ++j) {
    if (m.decomposition.is_separator(j)) continue;
    const Segment& s = m.decomposition.segments[j];
    m.point_markers[s.a] = std::max(m.point_markers[s.a], s.marker);
    m.point_markers[s.b] = std::max(m.point_markers[s.b], s.marker);
  }
  for (std::uint32_t k = 0; k < m.pieces.size(); ++k) {
    if (!kept[k]) continue;
    m.shortfall.input_angle += m.pieces[k].shortfall.input_angle;
    m.shortfall.separator += m.pieces[k].shortfall.separator;
    m.shortfall.precision += m.pieces[k].shortfall.precision;
    m.shortfall.limit += m.pieces[k].shortfall.limit;
  }
  std::vector<std::vector<MeshSegment>> segments_of(m.pieces.size());
  std::vector<SeparatorSides> sides(m.pieces.size());
  for_each_on_threads(m.pieces.size(), threads, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    if (!kept[k]) return;
    add_boundary_segments(segments_of[k], m, k);
    sides[k] = separator_sides(m.local[k], m.pieces[k]);
  });
  gather_segments(m, segments_of, kept, kept_or_all == nullptr);
  link_across_separators(m, sides);
  return m;
}

namespace {

// One piece whose own points are the decomposition's, in order (a subdomain
// checked alone: mesh/subdomain_check.hpp): numbered already as the mesh.
bool numbered_as_is(const MeshPiecesData& m) {
  if (m.pieces.size() != 1 || !m.across[0].empty()) return false;
  const std::vector<std::uint32_t>& ids = m.local[0].to_global;
  if (ids.size() != m.decomposition.points.size()) return false;
  for (std::uint32_t v = 0; v < ids.size(); ++v)
    if (ids[v] != v) return false;
  return true;
}

// Such a piece's arrays taken as the mesh's, not copied; its own points
// written over with the decomposition's, as copy_piece leaves them.
void take_piece(Mesh& out, MeshPiecesData& m) {
  SubdomainMesh& p = m.pieces[0];
  const std::uint32_t points = m.point_count(), triangles = m.triangle_count();
  out.point_markers = m.point_markers;
  out.point_markers.resize(points, 0);
  for (auto v = static_cast<std::uint32_t>(m.decomposition.points.size()); v < points; ++v)
    out.point_markers[v] = m.steiner_marker(0, v);
  out.points = std::move(p.points);
  std::copy(m.decomposition.points.begin(), m.decomposition.points.end(), out.points.begin());
  out.triangles = std::move(p.triangles);
  out.neighbours = std::move(p.neighbours);
  out.triangle_subdomain.assign(triangles, 0);
  if (m.has_regions())
    out.triangle_attribute = p.triangle_attribute.size() == triangles ? std::move(p.triangle_attribute)
                                                                      : std::vector<double>(triangles, 0.0);
  p = SubdomainMesh{};
}

// Every subdomain on its own thread into its own ranges.
void copy_pieces(Mesh& out, MeshPiecesData& m, unsigned threads) {
  const std::uint32_t points = m.point_count(), triangles = m.triangle_count();
  // The merged arrays' pages are faulted in on the threads that fill them
  // (kernel/fresh_memory.hpp): on one thread they were most of the merge.
  out.points = m.decomposition.points;
  resize_on_threads(out.points, points, threads);
  assign_on_threads(out.point_markers, points, 0, threads);
  std::copy(m.point_markers.begin(), m.point_markers.end(), out.point_markers.begin());
  resize_on_threads(out.triangles, triangles, threads);
  resize_on_threads(out.neighbours, triangles, threads);
  resize_on_threads(out.triangle_subdomain, triangles, threads);
  if (m.has_regions()) assign_on_threads(out.triangle_attribute, triangles, 0.0, threads);  // 0: in no region
  for_each_on_threads(m.pieces.size(), threads, [&](std::size_t k) {
    copy_piece(out, m, static_cast<std::uint32_t>(k));
    m.pieces[k] = SubdomainMesh{};  // release as we go
  });
}

}  // namespace

// The pieces copied into one mesh, or, one piece numbered as the mesh
// already, taken.
Mesh join(MeshPiecesData&& m, unsigned threads) {
  Mesh out;
  if (numbered_as_is(m)) take_piece(out, m);
  else copy_pieces(out, m, threads);
  out.subdomain_first_triangle = std::move(m.first_triangle);
  out.segments = std::move(m.segments);
  out.shortfall = m.shortfall;
  out.min_triangle_angle_deg = m.min_triangle_angle_deg;
  out.decomposition = std::move(m.decomposition);
  return out;
}

Mesh merge(const Decomposition& d, std::vector<SubdomainMesh>& pieces, double min_triangle_angle_deg,
           const std::vector<bool>* kept, unsigned threads) {
  return join(assemble(d, std::move(pieces), min_triangle_angle_deg, kept, threads), threads);
}

}  // namespace madd::detail
