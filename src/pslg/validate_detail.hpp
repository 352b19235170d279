#pragma once
// Internal pieces of validate(): the exact segment-pair test, the grid-driven
// search for conflicting pairs, and the face structure of the segment graph.
#include <cstdint>
#include <optional>
#include <vector>

#include "madd/intersections.hpp"
#include "madd/pslg.hpp"
#include "kernel/segment_grid.hpp"

namespace madd::detail {

enum class Contact : std::uint8_t { none, cross, touch, overlap };

// How segments s and t meet, decided exactly with orient2d. Sharing an
// endpoint index without being collinear in the same direction is `none`.
// `at` is a point they share (approximate only for a proper crossing).
// Precondition: no two distinct point indices have equal coordinates.
struct ContactResult {
  Contact kind = Contact::none;
  Point at;
};
ContactResult classify_contact(const std::vector<Point>& pts, const Segment& s, const Segment& t);

// The conflicting pair (first by the later segment's index, then the earlier)
// among all segments, or nothing. Sub-quadratic through the grid.
struct SegmentConflict {
  std::uint32_t later = 0;
  std::uint32_t earlier = 0;
  ContactResult contact;
};
// With `touches` off, a segment ending inside another (Contact::touch) is
// not a conflict: what validate_pslg() allows.
std::optional<SegmentConflict> find_segment_conflict(const Pslg& pslg, const SegmentGrid& grid, bool touches = true);

// Every pair of segments that meets other than at a shared endpoint (crossing,
// touching or overlapping), each pair once, ascending by (later, earlier).
// Throws InvalidInputError (segments_intersect) once more than `limit` pairs
// are found, so that a file where everything crosses everything cannot make
// the search (and what is built from it) quadratic in memory.
std::vector<SegmentConflict> all_segment_contacts(const Pslg& pslg, const SegmentGrid& grid, std::size_t limit);

// First segment (by index) that a point lies on, endpoints included.
std::optional<std::uint32_t> segment_under(const Pslg& pslg, const SegmentGrid& grid, Point p);

// True when a vertex on no segment lies on one: the segment pair search
// above only compares segments, so it never sees such a vertex, yet the
// segment is split there all the same (as a segment's end inside another).
bool lone_vertex_on_segment(const Pslg& pslg, const SegmentGrid& grid);

// The faces of the planar graph of segments. Precondition: no crossings,
// overlaps, duplicate points or zero-length segments. Half-edge 2s runs a->b
// of segment s, 2s+1 runs b->a; each ring is the boundary walk of the face on
// its left. A face is named by its outer ring, or `no_index` (the unbounded face).
struct FaceMap {
  std::vector<std::uint32_t> ring_of;       // per half-edge
  std::vector<double> ring_area;            // signed, per ring
  std::vector<std::uint32_t> face_of_ring;  // per ring
  std::vector<std::uint32_t> hole_face;     // per hole point
  std::uint32_t face_of_half_edge(std::uint32_t h) const { return face_of_ring[ring_of[h]]; }
  std::uint32_t ring_count() const { return static_cast<std::uint32_t>(ring_area.size()); }
};
FaceMap build_face_map(const Pslg& pslg, const SegmentGrid& grid);

// Per ring (= per bounded face): true when no hole point lies in the face.
std::vector<bool> kept_faces(const FaceMap& faces);

// The segment graph of a domain as decompose() sees it (docs/formats.md,
// "Interior segments"): the segments split at every vertex lying inside one
// (no new points), each piece with the sides the domain is on, and the
// vertices on no segment with the face each lies in. The domain is the union
// of the bounded faces holding no hole point. Precondition: no crossings,
// overlaps, duplicate points or zero-length segments.
struct DomainPieces {
  ResolvedPslg resolved;                // resolved.pslg.holes: the input's, then one per isolated vertex
  FaceMap faces;                        // of resolved.pslg
  std::vector<bool> kept;               // per face (ring id): part of the domain
  std::vector<std::uint32_t> isolated;  // input vertices on no segment, ascending
  std::size_t real_holes = 0;           // hole points that are the input's

  bool is_kept(std::uint32_t face) const { return face != no_index && kept[face]; }
  // Bit 0: the domain lies left of piece k run a -> b; bit 1: left of b -> a.
  unsigned domain_sides(std::uint32_t k) const {
    return (is_kept(faces.face_of_half_edge(2 * k)) ? 1U : 0U) |
           (is_kept(faces.face_of_half_edge(2 * k + 1)) ? 2U : 0U);
  }
  // The face isolated vertex isolated[i] lies in (no_index: outside every ring).
  std::uint32_t isolated_face(std::size_t i) const { return faces.hole_face[real_holes + i]; }
};
// `split_at_vertices`: some vertex lies inside a segment (else the segments
// are taken as they are, saving the search).
DomainPieces trace_domain_pieces(const Pslg& domain, bool split_at_vertices);

// True when some vertex lies inside a segment (a touch, or a vertex on no
// segment lying on one): what trace_domain_pieces must be told.
// Precondition as find_segment_conflict.
bool has_vertex_inside_segment(const Pslg& pslg);

}  // namespace madd::detail
