#pragma once
// The working triangulation of Delaunay refinement: a constrained Delaunay
// triangulation of one subdomain that grows one vertex at a time.
//
// It is the triangulator's own half-edge core (triangulation/half_edge_mesh.hpp),
// taken over as constrained_delaunay() leaves it, and grown by the core's
// cavity and walk; what refinement adds lives here. Twins are no_index
// outside the subdomain (every such edge is a segment). There are no ghost
// triangles: the subdomain is closed by its segments. An interior segment
// (a constraint inside the subdomain) has triangles on both sides: its
// half-edges have twins and a segment.
//
// Every triangle carries a label (the caller's region number): a cavity
// never crosses a segment, so the triangles replacing it take the label of
// the cavity triangle each rim edge came from, and the labels stay constant
// on each face of the segments as the mesh grows.
//
// Every vertex on a segment records it and its parameter along it, so that a
// subsegment is split at a point computed on the segment's own line
// (lerp of the segment's end points), never on the chord of a chord.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/pslg.hpp"
#include "triangulation/cavity.hpp"
#include "triangulation/half_edge_mesh.hpp"
#include "triangulation/walk.hpp"

namespace madd::detail {

// A segment of the subdomain: a piece of the discretised boundary.
struct RefinementSegment {
  std::uint32_t a = 0, b = 0;  // end vertices (parameter 0 at a, 1 at b)
  bool splittable = false;     // a boundary or interior piece (a separator never is: the decoupling)
};

class RefinementMesh {
public:
  // Takes over `mesh`, a constrained Delaunay triangulation of the subdomain
  // without ghosts or free slots (constrained_delaunay()), whose vertex i is
  // points[i] and whose segment i is segments[i] (mesh.seg indexes it);
  // labels[t] is triangle t's label (empty: all 0).
  RefinementMesh(HalfEdgeMesh mesh, std::vector<Point> points, std::vector<RefinementSegment> segments,
                 std::vector<std::uint32_t> labels = {});

  // Room for this many triangles (and about half as many vertices), so
  // that growing does not copy the arrays again and again.
  void reserve(std::size_t triangles);

  std::span<const Point> points() const noexcept { return points_; }
  Point point(std::uint32_t v) const noexcept { return points_[v]; }
  std::uint32_t vertex_count() const noexcept { return static_cast<std::uint32_t>(points_.size()); }
  std::uint32_t slot_count() const noexcept { return mesh_.slot_count(); }
  bool alive(std::uint32_t t) const noexcept { return mesh_.alive(t); }
  std::uint32_t label(std::uint32_t t) const noexcept { return label_[t]; }
  std::uint32_t corner(std::uint32_t t, int i) const noexcept {
    return mesh_.tv[3 * t + static_cast<std::uint32_t>(i)];
  }
  std::uint32_t origin(std::uint32_t h) const noexcept { return mesh_.origin(h); }
  std::uint32_t dest(std::uint32_t h) const noexcept { return mesh_.dest(h); }
  std::uint32_t twin(std::uint32_t h) const noexcept { return mesh_.tn[h]; }
  std::uint32_t segment_of(std::uint32_t h) const noexcept { return mesh_.seg[h]; }
  const RefinementSegment& segment(std::uint32_t s) const noexcept { return segments_[s]; }
  std::size_t segment_count() const noexcept { return segments_.size(); }
  // The segment a vertex lies inside (no_index for an input vertex or one
  // inside the subdomain) and its parameter along it.
  std::uint32_t vertex_segment(std::uint32_t v) const noexcept { return vertex_segment_[v]; }
  double vertex_parameter(std::uint32_t v) const noexcept { return vertex_parameter_[v]; }
  // Vertices that existed before refinement (the subdomain's ring vertices).
  std::uint32_t input_vertex_count() const noexcept { return input_vertices_; }

  // The half-edge from a to b, or no_index when a and b are not joined.
  std::uint32_t find_half_edge(std::uint32_t a, std::uint32_t b) const noexcept;

  // Walks the straight line from the centroid of `from` to p, crossing only
  // unconstrained edges (walk_straight: the triangle holding p, or the
  // segment half-edge in the way, or neither when it gives up).
  WalkResult walk(std::uint32_t from, Point p) const;

  // Inserting p, found in the closure of triangle `t` and visible from it,
  // by Bowyer-Watson, in two steps so that the caller can look before it
  // leaps: prepare() collects the cavity (the triangles whose circumcircle
  // strictly contains p, reachable from t without crossing a segment) and
  // returns false when its fan around p would not be strictly
  // counter-clockwise everywhere (p too close to the rim to be resolved);
  // rim_segments() are then the segment half-edges on the cavity's rim (the
  // diametral circles p may encroach); commit() makes the fan and returns
  // the new vertex, abandon() forgets the cavity. Nothing changes before commit().
  bool prepare(std::uint32_t t, Point p);
  const std::vector<std::uint32_t>& rim_segments() const noexcept { return rim_segments_; }
  std::uint32_t commit();
  void abandon();

  // Splits the segment half-edge h at parameter `parameter` of its segment
  // (the new vertex at lerp of the segment's ends): the two subsegments keep
  // the segment, the triangles inside whose circumcircle holds the new vertex
  // are re-fanned (on both sides of an interior segment). Returns the new
  // vertex, or no_index when the split point does not land strictly between
  // h's ends or the fan would fold.
  std::uint32_t split(std::uint32_t h, double parameter);

  // Newly made triangles since the last call (for the caller's queue).
  std::vector<std::uint32_t>& fresh() noexcept { return fresh_; }

private:
  std::uint32_t add_vertex(Point p, std::uint32_t vertex_segment, double parameter);
  void set_corner_home(std::uint32_t t);

  HalfEdgeMesh mesh_;
  Cavity cavity_{Cavity::SlotOrder::last_found_first};
  std::vector<Point> points_;
  std::vector<std::uint32_t> vertex_segment_;
  std::vector<double> vertex_parameter_;
  std::vector<std::uint32_t> vertex_triangle_;  // some live triangle at each vertex
  std::uint32_t input_vertices_ = 0;
  std::vector<RefinementSegment> segments_;
  std::vector<std::uint32_t> label_;  // per slot

  // Scratch of one insertion.
  std::vector<std::uint32_t> rim_segments_;
  std::vector<std::uint32_t> rim_labels_;
  Point pending_;  // the point prepare() dug for
  std::vector<std::uint32_t> fresh_;
};

}  // namespace madd::detail
