#pragma once
// The coast of a domain, as the size field reads it (docs/mesh.md, "Size
// field"): the domain's segments split at the vertices lying on them
// (pieces), each a boundary piece (the domain on one side) or an interior
// one (on both: never coast, the water goes on across it); of the boundary
// pieces, the coast is those whose marker is among the coast markers (all of
// them when none are given). The others are open water the domain was cut
// off at (a box clipping the sea): they end a chord across the water
// (feature_width.hpp) as open, and pull nothing fine.
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"
#include "sizing/segment_index.hpp"

namespace madd::detail {

struct Coast {
  std::vector<Point> points;        // the domain's
  std::vector<Segment> pieces;      // the segments split at the vertices on them
  std::vector<std::uint8_t> sides;  // per piece: bit 0 the domain left of a -> b, bit 1 left of b -> a
  std::vector<std::uint8_t> coast;  // per piece: 1 when it is coast
  std::vector<Point> holes;         // the domain's hole points
  // Per point: the sum of the unit inward normals of the coast pieces at it
  // ((0, 0) on no coast piece): the direction into the water there.
  std::vector<Point> inward;
  // Per piece: the unit normal pointing into the domain (a boundary piece's).
  std::vector<Point> piece_inward;
  std::vector<Point> coast_vertices;          // the ends of the coast pieces, each once
  SegmentIndex coast_index;                   // the coast pieces
  std::vector<std::uint32_t> coast_piece;     // per segment of coast_index: its piece
  SegmentIndex boundary_index;                // the boundary pieces, coast or not
  std::vector<std::uint32_t> boundary_piece;  // per segment of boundary_index: its piece
  SegmentIndex interior_index;                // the interior pieces

  bool is_boundary(std::uint32_t k) const noexcept { return sides[k] == 1 || sides[k] == 2; }
  // The distance from p to the nearest segment of any kind.
  double segment_distance(Point p) const noexcept;
  // p (far from every segment) is in the domain.
  bool contains(Point p) const noexcept { return boundary_index.odd_crossings(p); }
};

// `domain` passed validate(). Throws OptionError ("coast_markers") when a
// coast marker is on no boundary segment, naming the markers that are.
Coast trace_coast(const Pslg& domain, const std::vector<int>& coast_markers);

}  // namespace madd::detail
