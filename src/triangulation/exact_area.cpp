// Exact twice-areas of a domain and of a triangulation (see exact_area.hpp).
#include "triangulation/exact_area.hpp"

#include "kernel/segment_grid.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {

// The same faces as domain_area() (src/pslg/validate.cpp), but each ring's shoelace sum
// is added exactly instead of its floating-point area: half-edge h runs from
// segment h/2's a to its b when h is even, back when odd, and the rings are
// walked along those half-edges.
ExactSum domain_twice_area_exact(const Pslg& pslg) {
  ExactSum twice;
  if (pslg.segments.empty()) return twice;
  const SegmentGrid grid(pslg.points, pslg.segments);
  const FaceMap fm = build_face_map(pslg, grid);
  const std::vector<bool> kept = kept_faces(fm);
  for (std::uint32_t h = 0; h < fm.ring_of.size(); ++h) {
    const std::uint32_t face = fm.face_of_half_edge(h);
    if (face == no_index || !kept[face]) continue;
    const Segment& s = pslg.segments[h >> 1];
    const bool backward = (h & 1U) != 0;
    twice.add_cross(pslg.points[backward ? s.b : s.a], pslg.points[backward ? s.a : s.b]);
  }
  return twice;
}

ExactSum triangles_twice_area_exact(const Triangulation& tri) {
  ExactSum twice;
  for (const auto& c : tri.triangles) {
    const Point a = tri.points[c[0]], b = tri.points[c[1]], d = tri.points[c[2]];
    twice.add_cross(a, b);
    twice.add_cross(b, d);
    twice.add_cross(d, a);
  }
  return twice;
}

} // namespace madd::detail
