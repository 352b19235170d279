// trace_domain_pieces(): the pieces of a domain's segments and the sides the
// domain lies on, shared by validate() (which reports what is wrong with
// them) and by the decomposition's subdivision (which traces its rings from
// the boundary pieces and keeps the others inside its faces).
#include <utility>

#include "pslg/validate_detail.hpp"

namespace madd::detail {

bool has_vertex_inside_segment(const Pslg& pslg) {
  if (pslg.segments.empty()) return false;
  const SegmentGrid grid(pslg.points, pslg.segments);
  return find_segment_conflict(pslg, grid, true).has_value() || lone_vertex_on_segment(pslg, grid);
}

DomainPieces trace_domain_pieces(const Pslg& domain, bool split_at_vertices) {
  DomainPieces out;
  if (split_at_vertices) {
    out.resolved = resolve_intersections(domain);
  } else {
    out.resolved.pslg = domain;
    out.resolved.source_segment.resize(domain.segments.size());
    for (std::uint32_t s = 0; s < domain.segments.size(); ++s) out.resolved.source_segment[s] = s;
  }
  Pslg& p = out.resolved.pslg;
  std::vector<std::uint32_t> degree(p.points.size(), 0);
  for (const Segment& s : p.segments) ++degree[s.a], ++degree[s.b];
  for (std::uint32_t v = 0; v < domain.points.size(); ++v)
    if (degree[v] == 0) out.isolated.push_back(v);
  // Isolated vertices are located like hole points, after the real ones;
  // only the real ones remove a face.
  out.real_holes = p.holes.size();
  for (const std::uint32_t v : out.isolated) p.holes.push_back(p.points[v]);
  if (p.segments.empty()) return out;
  const SegmentGrid grid(p.points, p.segments);
  out.faces = build_face_map(p, grid);
  out.kept.assign(out.faces.ring_count(), false);
  for (std::uint32_t r = 0; r < out.faces.ring_count(); ++r) out.kept[r] = out.faces.face_of_ring[r] == r;
  for (std::size_t h = 0; h < out.real_holes; ++h)
    if (out.faces.hole_face[h] != no_index) out.kept[out.faces.hole_face[h]] = false;
  return out;
}

}  // namespace madd::detail
