// kept_region(): the faces of the segment graph (validate's face map, on the
// segments split at the vertices lying inside them, so that they form a
// planar graph), classified as triangulate() classifies triangles.
#include "triangulation/kept_region.hpp"

#include <algorithm>
#include <unordered_set>

#include "kernel/segment_grid.hpp"
#include "madd/intersections.hpp"
#include "madd/predicates.hpp"
#include "pslg/validate_detail.hpp"
#include "triangulation/exact_area.hpp"
#include "kernel/edge_key.hpp"

namespace madd::detail {
namespace {

bool in_closed_hull(const std::vector<Point>& hull, Point q) {
  if (hull.empty()) return false;
  for (std::size_t i = 0; i < hull.size(); ++i)
    if (orient2d(hull[i], hull[(i + 1) % hull.size()], q) < 0) return false;
  return true;
}

// The points on the boundary of the convex hull, collinear ones included, in
// order around it (the monotone chain, popping only on a strict clockwise
// turn). Precondition: not all points on one line.
std::vector<std::uint32_t> hull_boundary_cycle(const std::vector<Point>& pts) {
  std::vector<std::uint32_t> order(pts.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return pts[a].x < pts[b].x || (pts[a].x == pts[b].x && pts[a].y < pts[b].y);
  });
  std::vector<std::uint32_t> cycle;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = cycle.size();
    for (const std::uint32_t v : order) {
      while (cycle.size() >= base + 2 && orient2d(pts[cycle[cycle.size() - 2]], pts[cycle.back()], pts[v]) < 0)
        cycle.pop_back();
      cycle.push_back(v);
    }
    cycle.pop_back();
    std::reverse(order.begin(), order.end());
  }
  return cycle;
}

}  // namespace

KeptRegion kept_region(const Pslg& input, const TriangulateOptions& options) {
  KeptRegion out;
  if (input.segments.empty()) {
    out.twice_area = hull_twice_area_exact(input.points);
    return out;
  }
  ResolvedPslg resolved = resolve_intersections(input);
  const Pslg& p = resolved.pslg;
  const SegmentGrid grid(p.points, p.segments);
  const FaceMap fm = build_face_map(p, grid);
  const std::vector<bool> kept = kept_faces(fm);
  // The unbounded face (no_index): kept with the convex hull, unless a hole
  // point inside the hull lies in it; then unknown.
  enum class Outside { removed, retained, unknown } outside = Outside::removed;
  // A piece along the hull's boundary has the unbounded face on its outer
  // side outside the hull, where no triangle is: it is two consecutive points
  // of the boundary cycle (a piece holds no vertex inside it).
  std::unordered_set<std::uint64_t> on_hull;
  const std::vector<Point> hull = convex_hull(p.points);
  if (options.convex_hull && !hull.empty()) {
    outside = Outside::retained;
    const std::vector<std::uint32_t> cycle = hull_boundary_cycle(p.points);
    for (std::size_t i = 0; i < cycle.size(); ++i) on_hull.insert(edge_key(cycle[i], cycle[(i + 1) % cycle.size()]));
    for (std::size_t h = 0; h < p.holes.size(); ++h)
      if (fm.hole_face[h] == no_index && in_closed_hull(hull, p.holes[h])) outside = Outside::unknown;
  }
  const auto face_kept = [&](std::uint32_t face) {
    return face == no_index ? outside == Outside::retained : kept[face];
  };
  ExactSum twice;
  if (outside == Outside::retained) twice = hull_twice_area_exact(p.points);
  // The unbounded face's rings run clockwise around what they enclose:
  // adding them takes the bounded faces out of the hull.
  for (std::uint32_t h = 0; h < fm.ring_of.size(); ++h) {
    if (!face_kept(fm.face_of_half_edge(h))) continue;
    const Segment& s = p.segments[h >> 1];
    const bool backward = (h & 1U) != 0;
    twice.add_cross(p.points[backward ? s.b : s.a], p.points[backward ? s.a : s.b]);
  }
  if (outside != Outside::unknown) out.twice_area = twice;
  out.must_be_edge.resize(p.segments.size());
  for (std::uint32_t s = 0; s < p.segments.size(); ++s) {
    const std::uint32_t f = fm.face_of_half_edge(2 * s), g = fm.face_of_half_edge(2 * s + 1);
    const bool hull_side =
        (f == no_index) != (g == no_index) && on_hull.count(edge_key(p.segments[s].a, p.segments[s].b));
    out.must_be_edge[s] = (f != no_index && kept[f]) || (g != no_index && kept[g]) ||
                          (outside == Outside::retained && (f == no_index || g == no_index) && !hull_side);
  }
  out.pieces = std::move(resolved.pslg.segments);
  out.source = std::move(resolved.source_segment);
  return out;
}

}  // namespace madd::detail
