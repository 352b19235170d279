// Exact twice-areas of a domain and of a triangulation (see exact_area.hpp).
#include "triangulation/exact_area.hpp"

#include <algorithm>

#include "kernel/segment_grid.hpp"
#include "madd/predicates.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {

// The same faces as domain_area() (src/pslg/validate.cpp), but each ring's shoelace sum
// is added exactly instead of its floating-point area: half-edge h runs from
// segment h/2's a to its b when h is even, back when odd, and the rings are
// walked along those half-edges.
ExactSum domain_twice_area_exact(const Pslg& pslg) {
  ExactSum twice;
  if (pslg.segments.empty()) return twice;
  // Both sides of an interior piece are kept: its two half-edges cancel exactly.
  const DomainPieces dp = trace_domain_pieces(pslg, has_vertex_inside_segment(pslg));
  const Pslg& pieces = dp.resolved.pslg;
  for (std::uint32_t h = 0; h < dp.faces.ring_of.size(); ++h) {
    if (!dp.is_kept(dp.faces.face_of_half_edge(h))) continue;
    const Segment& s = pieces.segments[h >> 1];
    const bool backward = (h & 1U) != 0;
    twice.add_cross(pieces.points[backward ? s.b : s.a], pieces.points[backward ? s.a : s.b]);
  }
  return twice;
}

std::vector<Point> convex_hull(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return {};
  std::vector<Point> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point& q : pts) {
      while (hull.size() >= base + 2 && orient2d(hull[hull.size() - 2], hull.back(), q) <= 0) hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(pts.begin(), pts.end());
  }
  return hull.size() >= 3 ? hull : std::vector<Point>{};
}

ExactSum hull_twice_area_exact(const std::vector<Point>& points) {
  ExactSum twice;
  const std::vector<Point> hull = convex_hull(points);
  for (std::size_t i = 0; i < hull.size(); ++i) twice.add_cross(hull[i], hull[(i + 1) % hull.size()]);
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

}  // namespace madd::detail
