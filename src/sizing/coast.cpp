// The coast of a domain: its boundary pieces, the coast among them, their
// inward normals and the indices the field queries (coast.hpp).
#include "sizing/coast.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "madd/error.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {

namespace {

std::string marker_list(const std::set<int>& markers) {
  std::string out;
  for (const int m : markers) out += (out.empty() ? "" : ", ") + std::to_string(m);
  return out.empty() ? "none" : out;
}

void check_markers(const Coast& c, const std::vector<int>& coast_markers) {
  std::set<int> present;
  for (std::uint32_t k = 0; k < c.pieces.size(); ++k)
    if (c.is_boundary(k)) present.insert(c.pieces[k].marker);
  for (const int m : coast_markers)
    if (present.count(m) == 0)
      throw OptionError("coast_markers", "must name boundary markers of the domain",
                        "coast marker " + std::to_string(m) + " is on no boundary segment (the boundary markers are " +
                            marker_list(present) + ")");
}

}  // namespace

double Coast::segment_distance(Point p) const noexcept {
  return std::min(boundary_index.nearest(p).distance, interior_index.nearest(p).distance);
}

Coast trace_coast(const Pslg& domain, const std::vector<int>& coast_markers) {
  const DomainPieces traced = trace_domain_pieces(domain, has_vertex_inside_segment(domain));
  Coast c;
  c.points = traced.resolved.pslg.points;
  c.pieces = traced.resolved.pslg.segments;
  c.holes = domain.holes;
  c.sides.resize(c.pieces.size());
  for (std::uint32_t k = 0; k < c.pieces.size(); ++k) c.sides[k] = static_cast<std::uint8_t>(traced.domain_sides(k));
  check_markers(c, coast_markers);
  c.coast.assign(c.pieces.size(), 0);
  c.inward.assign(c.points.size(), Point{});
  c.piece_inward.assign(c.pieces.size(), Point{});
  std::vector<Segment> coast, boundary, interior;
  std::vector<bool> coast_vertex(c.points.size(), false);
  for (std::uint32_t k = 0; k < c.pieces.size(); ++k) {
    const Segment& s = c.pieces[k];
    if (!c.is_boundary(k)) {
      interior.push_back(s);
      continue;
    }
    const Point ab = c.points[s.b] - c.points[s.a];
    const Point left = (1.0 / length(ab)) * Point{-ab.y, ab.x};
    c.piece_inward[k] = (c.sides[k] & 1) != 0 ? left : -1.0 * left;
    boundary.push_back(s);
    c.boundary_piece.push_back(k);
    const bool is_coast =
        coast_markers.empty() || std::find(coast_markers.begin(), coast_markers.end(), s.marker) != coast_markers.end();
    if (!is_coast) continue;
    c.coast[k] = 1;
    coast.push_back(s);
    c.coast_piece.push_back(k);
    for (const std::uint32_t v : {s.a, s.b}) {
      c.inward[v] = c.inward[v] + c.piece_inward[k];
      coast_vertex[v] = true;
    }
  }
  for (std::uint32_t v = 0; v < c.points.size(); ++v)
    if (coast_vertex[v]) c.coast_vertices.push_back(c.points[v]);
  c.coast_index = SegmentIndex(c.points, coast);
  c.boundary_index = SegmentIndex(c.points, boundary);
  c.interior_index = SegmentIndex(c.points, interior);
  return c;
}

}  // namespace madd::detail
