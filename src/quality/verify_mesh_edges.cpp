// verify_mesh, the edge pass: every triangle edge and every mesh segment
// grouped by undirected edge, with no global sort and no map. Directed edges
// are bucketed by their lower vertex (a counting sort, linear), and each
// vertex's few buckets sorted by the upper vertex, so an edge's triangles
// and segments sit together. Per edge it checks:
// - at most one triangle in each direction (so at most two in all);
// - two triangles (one each way) name each other as neighbours across it,
//   one triangle names no_index there;
// - an edge in one triangle is a boundary segment (marker != 0, not on an
//   interior piece): the free edges are exactly the boundary, so no hole and
//   no tear;
// - an edge between two subdomains is a separator segment (marker 0), and a
//   separator lies between two triangles of different subdomains;
// - a segment on an interior piece lies between two triangles of the
//   subdomain the piece is interior to (interior_segment_owners), and is
//   the only kind of segment inside a subdomain;
// - between two triangles of one subdomain, off every segment, locally
//   Delaunay (exact incircle; one test decides it, since the in-circle
//   determinant of the other triangle and this one's far vertex is the same
//   determinant under an even permutation of its four points).
// It also sums twice the triangles' area exactly: the shoelace sum over all
// triangle edges, where an edge walked once each way cancels exactly, is
// sum over edges of (forward - backward) cross(lo, hi), so only free edges
// cost exact arithmetic.
#include <algorithm>
#include <span>
#include <string>

#include "madd/decomposition.hpp"
#include "madd/predicates.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

namespace {

struct Half {
  std::uint32_t hi;    // the other (higher) vertex of the edge
  std::uint32_t code;  // 3 t + i: edge i of triangle t, opposite vertex i
  bool operator<(const Half& o) const noexcept { return hi < o.hi || (hi == o.hi && code < o.code); }
};

struct SegEnd {
  std::uint32_t hi;
  std::uint32_t segment;
  bool operator<(const SegEnd& o) const noexcept { return hi < o.hi || (hi == o.hi && segment < o.segment); }
};

// Counting sort of `count` items into buckets by key: CSR offsets, items in
// increasing order within each bucket.
template <class Key>
void bucket(std::size_t buckets, std::uint32_t count, Key key, std::vector<std::uint32_t>& start,
            std::vector<std::uint32_t>& items) {
  start.assign(buckets + 1, 0);
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t b = key(k);
    if (b != no_index) ++start[b + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  items.resize(start[buckets]);
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t b = key(k);
    if (b != no_index) items[start[b]++] = k;
  }
  // start[b] now holds the end of bucket b: shift back by one bucket.
  for (std::size_t b = buckets; b > 0; --b) start[b] = start[b - 1];
  start[0] = 0;
}

class EdgePass {
public:
  EdgePass(const Mesh& m, const std::vector<std::uint8_t>& ccw, ProblemLog& log)
      : m_(m), ccw_(ccw), log_(log), owner_(interior_segment_owners(m.decomposition)) {}

  MeshEdges run() {
    const auto& T = m_.triangles;
    const std::size_t np = m_.points.size();
    std::vector<std::uint32_t> half_start, halves, seg_start, segs;
    bucket(
        np, static_cast<std::uint32_t>(3 * T.size()),
        [&](std::uint32_t code) {
          const std::uint32_t a = from(code), b = to(code);
          return a == b ? no_index : std::min(a, b);  // a repeated vertex: reported by the orientation check
        },
        half_start, halves);
    bucket(
        np, static_cast<std::uint32_t>(m_.segments.size()),
        [&](std::uint32_t s) { return std::min(m_.segments[s].a, m_.segments[s].b); }, seg_start, segs);
    std::vector<Half> local;
    std::vector<SegEnd> local_segs;
    for (std::uint32_t v = 0; v < np; ++v) {
      local.clear();
      local_segs.clear();
      for (std::uint32_t k = half_start[v]; k < half_start[v + 1]; ++k) {
        const std::uint32_t code = halves[k];
        local.push_back({std::max(from(code), to(code)), code});
      }
      for (std::uint32_t k = seg_start[v]; k < seg_start[v + 1]; ++k) {
        const MeshSegment& g = m_.segments[segs[k]];
        local_segs.push_back({std::max(g.a, g.b), segs[k]});
      }
      std::sort(local.begin(), local.end());
      std::sort(local_segs.begin(), local_segs.end());
      std::size_t i = 0, j = 0;
      while (i < local.size() || j < local_segs.size()) {
        const std::uint32_t w =
            std::min(i < local.size() ? local[i].hi : no_index, j < local_segs.size() ? local_segs[j].hi : no_index);
        const std::size_t i0 = i, j0 = j;
        while (i < local.size() && local[i].hi == w) ++i;
        while (j < local_segs.size() && local_segs[j].hi == w) ++j;
        edge(v, w, std::span<const Half>(local.data() + i0, i - i0),
             std::span<const SegEnd>(local_segs.data() + j0, j - j0));
      }
    }
    return std::move(out_);
  }

private:
  std::uint32_t tri(std::uint32_t code) const noexcept { return code / 3; }
  std::uint32_t side(std::uint32_t code) const noexcept { return code % 3; }
  std::uint32_t from(std::uint32_t code) const noexcept { return m_.triangles[code / 3][(code % 3 + 1) % 3]; }
  std::uint32_t to(std::uint32_t code) const noexcept { return m_.triangles[code / 3][(code % 3 + 2) % 3]; }
  std::uint32_t neighbour(std::uint32_t code) const noexcept { return m_.neighbours[code / 3][code % 3]; }
  std::uint32_t subdomain(std::uint32_t code) const noexcept { return m_.triangle_subdomain[code / 3]; }

  std::string edge_text(std::uint32_t v, std::uint32_t w) const {
    return "edge " + std::to_string(v) + "-" + std::to_string(w) + " " + point_text(m_.points[v]) + "-" +
           point_text(m_.points[w]);
  }
  std::string tri_text(std::uint32_t code) const { return mesh_triangle_text(m_, tri(code)); }
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

  void edge(std::uint32_t v, std::uint32_t w, std::span<const Half> halves, std::span<const SegEnd> segs) {
    // Forward halves run v -> w (v is the lower vertex), backward w -> v.
    std::uint32_t forward = 0, backward = 0, f = no_index, b = no_index;
    std::uint32_t twin = no_index, twin_of = no_index;  // two triangles with the edge the same way
    for (const Half& h : halves) {
      const bool ahead = from(h.code) == v;
      std::uint32_t& same = ahead ? f : b;
      if (same != no_index && twin == no_index) {
        twin = h.code;
        twin_of = same;
      }
      same = h.code;
      ++(ahead ? forward : backward);
    }
    // Twice the area: what this edge adds to the triangles' shoelace sums.
    for (std::uint32_t k = forward; k < backward; ++k) out_.twice_area.add_cross(m_.points[w], m_.points[v]);
    for (std::uint32_t k = backward; k < forward; ++k) out_.twice_area.add_cross(m_.points[v], m_.points[w]);
    if (segs.size() > 1)
      log_.add("mesh segments " + std::to_string(segs[0].segment) + " and " + std::to_string(segs[1].segment) +
               " are the same " + edge_text(v, w));
    if (twin != no_index) {
      log_.add(tri_text(twin_of) + " and " + tri_text(twin) + " both have " + edge_text(from(twin), to(twin)) +
               " in the same direction (" + std::to_string(forward + backward) + " triangles share it)");
      return;
    }
    const bool has_seg = !segs.empty();
    const std::uint32_t s = has_seg ? segs[0].segment : no_index;
    const bool separator = has_seg && m_.segments[s].marker == 0;
    if (forward + backward == 0) {
      log_.add(seg_text(s) + " (" + edge_text(v, w) + ") is not an edge of any triangle");
      return;
    }
    if (forward + backward == 1) {
      const std::uint32_t code = forward == 1 ? f : b;
      out_.boundary.push_back({from(code), to(code), 0});
      if (neighbour(code) != no_index)
        log_.add(tri_text(code) + " names triangle " + std::to_string(neighbour(code)) + " as its neighbour across " +
                 edge_text(v, w) + ", which no other triangle has the other way");
      if (!has_seg)
        log_.add(edge_text(v, w) + " of " + tri_text(code) +
                 " is in no other triangle but is no boundary segment: a hole or a tear in the mesh");
      else if (separator || interior_owner(s) != no_index)
        log_.add(seg_text(s) + " (" + edge_text(v, w) + ") is in one triangle only, " + tri_text(code));
      return;
    }
    // One triangle each way.
    if (neighbour(f) != tri(b) || neighbour(b) != tri(f)) {
      log_.add(tri_text(f) + " and " + tri_text(b) + " share " + edge_text(v, w) + " but name " +
               std::to_string(neighbour(f)) + " and " + std::to_string(neighbour(b)) +
               " as their neighbours across it");
    }
    const std::uint32_t kf = subdomain(f), kb = subdomain(b);
    if (kf != kb) {
      if (!separator)
        log_.add(edge_text(v, w) + " between subdomains " + std::to_string(kf) + " and " + std::to_string(kb) + " (" +
                 tri_text(f) + ", " + tri_text(b) + ") is " +
                 (has_seg ? "a boundary segment" : "no separator segment"));
      return;
    }
    if (has_seg) {
      // A constraint inside the subdomain: no Delaunay test across it.
      if (!separator && interior_owner(s) == kf) return;
      log_.add(seg_text(s) + " (" + edge_text(v, w) + ") lies inside subdomain " + std::to_string(kf) + ", between " +
               tri_text(f) + " and " + tri_text(b) +
               (interior_owner(s) != no_index
                    ? " (its piece is interior to subdomain " + std::to_string(interior_owner(s)) + ")"
                    : ""));
      return;
    }
    if (ccw_[tri(f)] == 0 || ccw_[tri(b)] == 0) return;  // already reported; the test needs CCW
    const auto& c = m_.triangles[tri(f)];
    const std::uint32_t far = m_.triangles[tri(b)][side(b)];
    if (incircle(m_.points[c[0]], m_.points[c[1]], m_.points[c[2]], m_.points[far]) > 0.0)
      log_.add(edge_text(v, w) + " of subdomain " + std::to_string(kf) + " is not locally Delaunay: vertex " +
               std::to_string(far) + " " + point_text(m_.points[far]) + " of " + tri_text(b) +
               " is strictly inside the circumcircle of " + tri_text(f));
  }

  const Mesh& m_;
  const std::vector<std::uint8_t>& ccw_;
  ProblemLog& log_;
  std::vector<std::uint32_t> owner_;  // per decomposition segment: the subdomain it is interior to
  MeshEdges out_;
};

}  // namespace

MeshEdges check_mesh_edges(const Mesh& mesh, const std::vector<std::uint8_t>& ccw, ProblemLog& log) {
  return EdgePass(mesh, ccw, log).run();
}

}  // namespace madd::detail
