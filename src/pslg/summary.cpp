// summarize_pslg(): what `madd check` says about a PSLG that is not (only) a
// domain. The segments are first split at every vertex lying inside one
// (resolve_intersections, which then inserts nothing), so that they form a
// planar graph whose faces validate's face map can trace; the isolated
// vertices are located in those faces like hole points.
#include <algorithm>

#include "kernel/segment_grid.hpp"
#include "madd/intersections.hpp"
#include "madd/pslg.hpp"
#include "pslg/validate_detail.hpp"

namespace madd {
namespace {

// How many sides of a piece of segment have the kept region.
enum Side : unsigned { none = 0, one = 1, both = 2 };

}  // namespace

PslgSummary summarize_pslg(const Pslg& input) {
  PslgSummary out;
  const ResolvedPslg resolved = resolve_intersections(input);
  Pslg p = resolved.pslg;
  std::vector<std::uint32_t> degree(p.points.size(), 0);
  for (const Segment& s : p.segments) ++degree[s.a], ++degree[s.b];
  std::vector<std::uint32_t> lone;
  for (std::uint32_t v = 0; v < p.points.size(); ++v) {
    if (degree[v] == 0) lone.push_back(v);
    if (degree[v] == 1) ++out.dangling_ends;
  }
  out.isolated_vertices = lone.size();
  std::vector<char> inside(input.points.size(), 0);
  for (std::uint32_t k = 0; k < p.segments.size(); ++k) {
    const Segment& whole = input.segments[resolved.source_segment[k]];
    for (const std::uint32_t v : {p.segments[k].a, p.segments[k].b})
      if (v != whole.a && v != whole.b) inside[v] = 1;
  }
  out.vertices_inside_segments = static_cast<std::size_t>(std::count(inside.begin(), inside.end(), 1));
  if (p.segments.empty()) return out;

  // The isolated vertices are located as extra hole points after the real
  // ones; only the real ones remove a face.
  const std::size_t holes = p.holes.size();
  for (const std::uint32_t v : lone) p.holes.push_back(p.points[v]);
  const detail::SegmentGrid grid(p.points, p.segments);
  const detail::FaceMap fm = detail::build_face_map(p, grid);
  std::vector<bool> kept(fm.ring_count(), false);
  for (std::uint32_t r = 0; r < fm.ring_count(); ++r) kept[r] = fm.face_of_ring[r] == r;
  for (std::size_t h = 0; h < holes; ++h)
    if (fm.hole_face[h] != no_index) kept[fm.hole_face[h]] = false;
  const auto is_kept = [&](std::uint32_t f) { return f != no_index && kept[f]; };
  for (std::size_t k = holes; k < p.holes.size(); ++k)
    if (is_kept(fm.hole_face[k])) ++out.isolated_inside;
  for (std::uint32_t r = 0; r < fm.ring_count(); ++r) {
    if (is_kept(r)) ++out.parts;
    if (is_kept(fm.face_of_ring[r])) out.area += fm.ring_area[r];
  }

  std::vector<unsigned> sides(input.segments.size(), 0);  // per input segment: bit 1 << (kept sides of a piece)
  for (std::uint32_t k = 0; k < p.segments.size(); ++k) {
    const unsigned n =
        (is_kept(fm.face_of_half_edge(2 * k)) ? 1U : 0U) + (is_kept(fm.face_of_half_edge(2 * k + 1)) ? 1U : 0U);
    sides[resolved.source_segment[k]] |= 1U << n;
  }
  for (const unsigned bits : sides) {
    if (bits & (1U << both)) ++out.interior_segments;
    else if (bits & (1U << one)) ++out.boundary_segments;
    else ++out.outside_segments;
  }
  return out;
}

}  // namespace madd
