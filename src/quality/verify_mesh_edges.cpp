// verify_mesh, the edge pass: every edge of every triangle, in triangle
// order, against the triangle its link names across it, and every mesh
// segment against the edges it must be. In chunks of triangles on threads
// (each chunk's triangles and their neighbours are near each other in
// memory: a subdomain's triangles are numbered together), no sort and no
// map but the segments'. Per directed edge a -> b of triangle t:
// - linked (neighbour u): u has the edge the other way, b -> a, and names t
//   across it (a mutual pair); two triangles with the edge the same way, a
//   link to a triangle without the edge, or a link not returned, are
//   reported;
// - free (no neighbour): the edge is a boundary segment (marker != 0, not an
//   interior piece), so no hole and no tear;
// and per mutual pair, once, from its lower triangle:
// - between two subdomains it is a separator segment (marker 0);
// - inside a subdomain it is no segment but an interior piece of that
//   subdomain (interior_segment_owners), and off every segment it is
//   locally Delaunay (exact incircle; one test decides it, since the
//   in-circle determinant of the other triangle and this one's far vertex is
//   the same determinant under an even permutation of its four points);
// and every mesh segment is exactly one such edge: one free edge or one pair.
//
// Why this rules out an overlap without comparing every triangle with every
// other: the triangles' boundaries, added as chains, cancel on every mutual
// pair and leave the free edges; so with every triangle counter-clockwise
// (the orientation check) each point is covered by as many triangles as the
// free edges wind around it. The free edges are exactly the boundary
// segments, and the exact total area (below) equals the domain's (the cover
// check): every point of the domain is covered once and nothing else is.
// Two triangles with an edge the same way would overlap near it; a third
// triangle on a shared edge would have it free and no segment there.
//
// It also sums twice the triangles' area exactly: the shoelace sum over all
// triangle edges, where the two edges of a mutual pair cancel exactly, is the
// sum of cross(a, b) over every other directed edge, so only free (and
// broken) edges cost exact arithmetic.
#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>

#include "kernel/threads.hpp"
#include "madd/decomposition.hpp"
#include "madd/predicates.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_detail.hpp"
#include "kernel/edge_key.hpp"

namespace madd::detail {

namespace {

// The mesh segments by edge, with a flag per vertex on one, so that the
// many edges with an end on none are known to be no segment without a
// lookup. Two segments on one edge are reported here.
class SegmentsByEdge {
public:
  SegmentsByEdge(const Mesh& m, ProblemLog& log) : on_(m.points.size(), 0) {
    by_edge_.reserve(m.segments.size());
    for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
      const MeshSegment& g = m.segments[s];
      const auto [it, added] = by_edge_.emplace(edge_key(g.a, g.b), s);
      if (!added)
        log.add("mesh segments " + std::to_string(it->second) + " and " + std::to_string(s) + " are the same edge " +
                std::to_string(std::min(g.a, g.b)) + "-" + std::to_string(std::max(g.a, g.b)));
      on_[g.a] = on_[g.b] = 1;
    }
  }
  // The segment on edge {a, b} (the first, when two are), or no_index.
  std::uint32_t at(std::uint32_t a, std::uint32_t b) const {
    if (on_[a] == 0 || on_[b] == 0) return no_index;
    const auto it = by_edge_.find(edge_key(a, b));
    return it == by_edge_.end() ? no_index : it->second;
  }

private:
  std::vector<std::uint8_t> on_;
  std::unordered_map<std::uint64_t, std::uint32_t> by_edge_;
};

// What one chunk of triangles finds besides its problems.
struct ChunkEdges {
  MeshEdges edges;
  std::vector<std::uint32_t> segments;  // the segments its edges are, once per free edge or pair
};

class EdgePass {
public:
  EdgePass(const Mesh& m, const std::vector<std::uint8_t>& ccw, const std::vector<std::uint32_t>& owner,
           const SegmentsByEdge& segments, ProblemLog& log)
      : m_(m), ccw_(ccw), owner_(owner), segments_(segments), log_(log) {}

  ChunkEdges run(std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t t = begin; t < end; ++t)
      for (std::uint32_t i = 0; i < 3; ++i) edge(t, i);
    return std::move(out_);
  }

private:
  std::uint32_t from(std::uint32_t t, std::uint32_t i) const noexcept { return m_.triangles[t][(i + 1) % 3]; }
  std::uint32_t to(std::uint32_t t, std::uint32_t i) const noexcept { return m_.triangles[t][(i + 2) % 3]; }
  // The side of triangle u that runs a -> b, or 3.
  std::uint32_t side_of(std::uint32_t u, std::uint32_t a, std::uint32_t b) const noexcept {
    std::uint32_t j = 0;
    while (j < 3 && !(from(u, j) == a && to(u, j) == b)) ++j;
    return j;
  }

  std::string edge_text(std::uint32_t v, std::uint32_t w) const {
    if (v > w) std::swap(v, w);
    return "edge " + std::to_string(v) + "-" + std::to_string(w) + " " + point_text(m_.points[v]) + "-" +
           point_text(m_.points[w]);
  }
  std::string tri_text(std::uint32_t t) const { return mesh_triangle_text(m_, t); }
  // The subdomain mesh segment s is an interior segment of, or no_index.
  std::uint32_t interior_owner(std::uint32_t s) const noexcept {
    const std::uint32_t piece = m_.segments[s].piece;
    return piece < owner_.size() ? owner_[piece] : no_index;
  }
  std::string seg_text(std::uint32_t s) const {
    return (m_.segments[s].marker == 0      ? "separator segment "
            : interior_owner(s) != no_index ? "interior segment "
                                            : "boundary segment ") +
           std::to_string(s);
  }

  void edge(std::uint32_t t, std::uint32_t i) {
    const std::uint32_t a = from(t, i), b = to(t, i);
    if (a == b) return;  // a repeated vertex: reported by the orientation check
    const std::uint32_t u = m_.neighbours[t][i];
    if (u == no_index) return free_edge(t, a, b);
    const std::uint32_t j = side_of(u, b, a);
    if (j == 3 || m_.neighbours[u][j] != t) return broken_link(t, u, j, a, b);
    if (u < t) return;  // the pair, once, from its lower triangle
    pair(t, u, j, a, b);
  }

  void free_edge(std::uint32_t t, std::uint32_t a, std::uint32_t b) {
    out_.edges.boundary.push_back({a, b, 0});
    out_.edges.twice_area.add_cross(m_.points[a], m_.points[b]);
    const std::uint32_t s = segments_.at(a, b);
    if (s == no_index) {
      log_.add(edge_text(a, b) + " of " + tri_text(t) +
               " is in no other triangle but is no boundary segment: a hole or a tear in the mesh");
      return;
    }
    out_.segments.push_back(s);
    if (m_.segments[s].marker == 0 || interior_owner(s) != no_index)
      log_.add(seg_text(s) + " (" + edge_text(a, b) + ") is in one triangle only, " + tri_text(t));
  }

  // t names u across a -> b, but u has no side b -> a naming t back (j: u's
  // side b -> a, or 3). This side's edge counts in the area as a free one.
  void broken_link(std::uint32_t t, std::uint32_t u, std::uint32_t j, std::uint32_t a, std::uint32_t b) {
    out_.edges.twice_area.add_cross(m_.points[a], m_.points[b]);
    if (j != 3) {
      log_.add(tri_text(t) + " and " + tri_text(u) + " share " + edge_text(a, b) + " but name " + std::to_string(u) +
               " and " + std::to_string(m_.neighbours[u][j]) + " as their neighbours across it");
    } else if (side_of(u, a, b) != 3) {
      log_.add(tri_text(t) + " and " + tri_text(u) + " both have " + edge_text(a, b) + " in the same direction (and " +
               std::to_string(t) + " names " + std::to_string(u) + " as its neighbour across it)");
    } else {
      log_.add(tri_text(t) + " names triangle " + std::to_string(u) + " as its neighbour across " + edge_text(a, b) +
               ", which that triangle does not have the other way");
    }
  }

  // t and u, t < u, glued mutually along t's side a -> b (u's side j, b -> a).
  void pair(std::uint32_t t, std::uint32_t u, std::uint32_t j, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t s = segments_.at(a, b);
    const bool separator = s != no_index && m_.segments[s].marker == 0;
    if (s != no_index) out_.segments.push_back(s);
    const std::uint32_t kt = m_.triangle_subdomain[t], ku = m_.triangle_subdomain[u];
    if (kt != ku) {
      if (!separator)
        log_.add(edge_text(a, b) + " between subdomains " + std::to_string(kt) + " and " + std::to_string(ku) + " (" +
                 tri_text(t) + ", " + tri_text(u) + ") is " +
                 (s != no_index ? "a boundary segment" : "no separator segment"));
      return;
    }
    if (s != no_index) {
      // A constraint inside the subdomain: no Delaunay test across it.
      if (!separator && interior_owner(s) == kt) return;
      log_.add(seg_text(s) + " (" + edge_text(a, b) + ") lies inside subdomain " + std::to_string(kt) + ", between " +
               tri_text(t) + " and " + tri_text(u) +
               (interior_owner(s) != no_index
                    ? " (its piece is interior to subdomain " + std::to_string(interior_owner(s)) + ")"
                    : ""));
      return;
    }
    if (ccw_[t] == 0 || ccw_[u] == 0) return;  // already reported; the test needs CCW
    const auto& c = m_.triangles[t];
    const std::uint32_t far = m_.triangles[u][j];
    if (incircle(m_.points[c[0]], m_.points[c[1]], m_.points[c[2]], m_.points[far]) > 0.0)
      log_.add(edge_text(a, b) + " of subdomain " + std::to_string(kt) + " is not locally Delaunay: vertex " +
               std::to_string(far) + " " + point_text(m_.points[far]) + " of " + tri_text(u) +
               " is strictly inside the circumcircle of " + tri_text(t));
  }

  const Mesh& m_;
  const std::vector<std::uint8_t>& ccw_;
  const std::vector<std::uint32_t>& owner_;  // per decomposition segment: the subdomain it is interior to
  const SegmentsByEdge& segments_;
  ProblemLog& log_;
  ChunkEdges out_;
};

// Every mesh segment is exactly one free edge or one mutual pair: `found`
// lists the segment of each (chunk by chunk, in triangle order).
void check_segments_found(const Mesh& m, const std::vector<ChunkEdges>& found, ProblemLog& log) {
  std::vector<std::uint32_t> times(m.segments.size(), 0);
  for (const ChunkEdges& chunk : found)
    for (const std::uint32_t s : chunk.segments) ++times[s];
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
    if (times[s] == 1) continue;
    const MeshSegment& g = m.segments[s];
    const std::string which = (g.marker == 0 ? "separator segment " : "mesh segment ") + std::to_string(s) + " (edge " +
                              std::to_string(std::min(g.a, g.b)) + "-" + std::to_string(std::max(g.a, g.b)) + ")";
    if (times[s] == 0) log.add(which + " is not an edge of any triangle");
    else
      log.add(which + " is an edge of " + std::to_string(times[s]) +
              " places of the mesh: two triangles lie on one side of it");
  }
}

}  // namespace

// In chunks of triangles (four per thread), their problems, areas, free
// edges and segments joined in chunk order: the same report for any count.
MeshEdges check_mesh_edges(const Mesh& mesh, const std::vector<std::uint8_t>& ccw, ProblemLog& log, unsigned threads) {
  const std::vector<std::uint32_t> owner = interior_segment_owners(mesh.decomposition);
  const SegmentsByEdge segments(mesh, log);
  const std::size_t nt = mesh.triangles.size();
  const std::size_t parts = 4 * std::size_t{thread_count(threads, nt)};
  std::vector<ChunkEdges> found(std::clamp<std::size_t>(parts, 1, std::max<std::size_t>(nt, 1)));
  log_in_parts(nt, parts, threads, log, [&](std::size_t part, std::size_t begin, std::size_t end, ProblemLog& mine) {
    found[part] = EdgePass(mesh, ccw, owner, segments, mine)
                      .run(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end));
  });
  check_segments_found(mesh, found, log);
  MeshEdges edges;
  for (ChunkEdges& chunk : found) {
    edges.twice_area.add(chunk.edges.twice_area);
    edges.boundary.insert(edges.boundary.end(), chunk.edges.boundary.begin(), chunk.edges.boundary.end());
  }
  return edges;
}

}  // namespace madd::detail
