#pragma once
// The global conforming planar subdivision that a decomposition grows in
// (docs/design.md, "The state lives in one place"). A split of one face is computed as
// pure geometry (SplitResult) and committed here, so that neighbours share
// every vertex by construction: no T-junctions, ever.
#include <array>
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

// Where one end of a separator edge lies, as seen in the snapshot the split
// was computed from. `local` identifies the point within its split (so that
// edges sharing an end share the committed vertex).
struct EndRef {
  enum Kind : std::uint8_t { vertex, inside_segment, centre };
  Kind kind = vertex;
  std::uint32_t id = no_index;  // vertex: global vertex; inside_segment: global segment (snapshot id)
  std::uint32_t local = 0;      // working point or circumcentre number within the split
  Point p;                      // exact coordinates of the end
};

// One separator segment; the new face `left_side` (0 or 1) lies on its left from a to b.
struct SeparatorEdge {
  EndRef a;
  EndRef b;
  std::uint8_t left_side = 0;
};

// Seconds one split spent in each phase (docs/quality.md, "Phase times").
struct SplitTimes {
  double refine = 0.0, triangulate = 0.0, graph = 0.0, bisect = 0.0;
  SplitTimes& operator+=(const SplitTimes& o) {
    refine += o.refine;
    triangulate += o.triangulate;
    graph += o.graph;
    bisect += o.bisect;
    return *this;
  }
};

// Two neighbours split in the same round choose where their separators end
// on the separator they share independently, so their ends can land a hair
// apart and leave a piece of it far shorter than anything else around, which
// the mesh that follows must resolve (docs/algorithm.md, "Short pieces"). At
// commit, an end inside a segment that only one separator edge reaches moves
// to a vertex an earlier commit put on that straight segment when it is
// closer than `distance` and every angle at both ends of the edge stays
// >= separator_angle_deg (Phi0), with nothing in the triangle the edge sweeps.
struct EndSnap {
  double distance = 0.0;  // 0: ends never move
  double separator_angle_deg = 90.0;
};

// The outcome of splitting one face (Algorithm 3 as geometry).
struct SplitResult {
  std::vector<SeparatorEdge> edges;
  std::vector<std::uint8_t> ring_side;  // per ring of the face: the side its inner neighbourhood joins
  double weight[2] = {0.0, 0.0};
  Point interior[2];  // a point strictly inside each side
  // Per interior piece of the face (Face::inner_segments as the split saw
  // it): the side of each of its working edges, in the piece's direction
  // (split/refine.hpp divides it into that many equal parts); per isolated
  // point (Face::inner_points): its side.
  std::vector<std::vector<std::uint8_t>> inner_sides;
  std::vector<std::uint8_t> point_sides;
  EndSnap snap;      // how ends may move at commit (not part of the choice)
  SplitTimes times;  // how long computing it took (not part of the geometry)
};

struct Face {
  std::vector<std::vector<std::uint32_t>> rings;          // [0] outer CCW, others CW
  std::vector<std::vector<std::uint32_t>> ring_segments;  // ring_segments[r][k]: rings[r][k] -> rings[r][k+1]
  Point interior;                                         // strictly inside
  // Interior constraints inside the face, in no ring: segment pieces with the
  // face on both sides, and isolated input vertices (docs/algorithm.md,
  // "Interior segments"). A separator crosses such a piece only at a vertex.
  std::vector<std::uint32_t> inner_segments;
  std::vector<std::uint32_t> inner_points;
  std::uint32_t plan = 1;            // final subdomains this face will become
  std::uint32_t sibling = no_index;  // the other side of the split that made it, if still whole
};

// A closed boundary cycle found by the face walk.
struct Cycle {
  std::vector<std::uint32_t> vertices;
  std::vector<std::uint32_t> segments;
  double area = 0.0;  // signed: positive for an outer ring
};

// A half-edge for the planar face walk.
struct HalfEdge {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  std::uint32_t segment = 0;
};

// Cycles of half-edges, each keeping its face on the left: at every vertex the
// walk takes the first outgoing half-edge clockwise from the way back (exact
// angular order via orient2d). Returns half-edge indices per cycle.
std::vector<std::vector<std::uint32_t>> walk_faces(const std::vector<Point>& points,
                                                   const std::vector<HalfEdge>& half_edges);

// The cycle of half-edges `ids` (one entry of walk_faces), with its signed area.
Cycle make_cycle(const std::vector<Point>& points, const std::vector<HalfEdge>& half_edges,
                 const std::vector<std::uint32_t>& ids);

class Subdivision {
public:
  std::vector<Point> points;
  std::vector<Segment> segments;
  std::vector<std::uint32_t> origin;                    // input segment, no_index for separators
  std::vector<std::uint32_t> next_piece;                // next piece along the same original segment
  std::vector<std::array<std::uint32_t, 2>> seg_faces;  // faces having the segment in a ring;
                                                        // an interior piece names its face twice
  std::vector<Face> faces;
  std::vector<Point> origin_hole;  // per input segment on a hole ring: its hole point
  std::vector<std::uint8_t> origin_has_hole;

  // The whole validated domain as one face (rings traced from the segments).
  // Throws DecompositionError when a hole ring holds no hole point.
  static Subdivision from_domain(const Pslg& domain);

  // A point strictly inside the region enclosed by hole ring `ring` of `face`
  // and outside the face: an input hole point or a neighbouring face's interior.
  Point hole_point(std::uint32_t face, std::size_t ring) const;

  // Inserts the separators of `split` into face `face`, which becomes side 0;
  // side 1 is appended. Returns the new face id.
  std::uint32_t commit(std::uint32_t face, const SplitResult& split);

  // An interior piece: in no ring, inside one face (seg_faces names it twice).
  bool is_inner(std::uint32_t segment) const {
    return seg_faces[segment][0] != no_index && seg_faces[segment][0] == seg_faces[segment][1];
  }

  double face_area(std::uint32_t face) const;
  // The vertices on all rings of a face: a face whose boundary changed has more.
  std::size_t ring_vertex_count(std::uint32_t face) const;

  // Removes every separator between the adjacent faces `a` and `b` and makes
  // their union one face, with the id min(a, b) and a's interior point; the
  // last face takes the id max(a, b), so face ids stay 0..faces.size()-1.
  // Returns false, changing nothing, when the faces share no separator or
  // their union is not one face with simple rings (decompose/rebalance.hpp).
  // Removed separators stay in `segments`, owned by no face, until compact().
  bool merge(std::uint32_t a, std::uint32_t b);

  // Drops the separators merge() removed and the points only they used,
  // renumbering the remaining segments and points in their order.
  void compact();

private:
  // The separator edge from `far` to an end inside a segment, for EndSnap.
  struct SnapEdge {
    const SplitResult* split = nullptr;
    std::uint32_t face = 0;
    EndRef far;                        // the edge's other end, as the split saw it
    std::vector<Point> far_ends;       // far is a centre: the other ends of all its edges (this one's included)
    std::vector<std::uint32_t> taken;  // vertices other ends of the split resolved to
  };
  std::uint32_t resolve(const EndRef& end, const SnapEdge* snap = nullptr);
  // Subdivision vertex `v` (on the straight chain of the end's segment) may
  // take the end of `edge` (snap.cpp).
  bool may_snap(std::uint32_t v, const EndRef& end, const SnapEdge& edge) const;
  // Every angle at the far end of `edge` stays >= phi when its near end moves to `to`.
  bool far_angles_hold(const SnapEdge& edge, Point from, Point to, double phi) const;
  std::uint32_t add_separators(std::uint32_t face, const SplitResult& split);  // returns the first new segment
  // Gives each side of a commit its interior pieces (`before`, the face's as
  // the split saw them, spanning `span`, and what the commit split off them)
  // and isolated points, by the sides the split found.
  void assign_inner(std::uint32_t face, const SplitResult& split, const std::vector<std::uint32_t>& before,
                    const std::vector<Segment>& span, Face sides[2]) const;
  Face assemble_face(std::vector<Cycle>& cycles, Point interior, std::uint32_t face) const;
  std::uint32_t split_segment(std::uint32_t piece, std::uint32_t vertex);
};

}  // namespace madd::detail
