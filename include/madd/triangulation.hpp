#pragma once
// Our own constrained Delaunay triangulator (robust predicates, no recursion
// whose depth grows with the input).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "madd/error.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd {

// Triangles are counter-clockwise index triples into `points`. Edge i of a
// triangle is the edge opposite its vertex i; neighbours[t][i] is the triangle
// across it (no_index on the outside), and segment_of[t][i] is the input
// segment the edge lies on (no_index when unconstrained).
struct Triangulation {
  std::vector<Point> points;  // the input points, same indices as the input
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  std::vector<std::array<std::uint32_t, 3>> segment_of;
  // Per triangle, its regional attribute (TriangulateOptions::region_attributes);
  // empty otherwise.
  std::vector<double> attributes;

  std::size_t triangle_count() const noexcept { return triangles.size(); }
  bool is_constrained(std::uint32_t t, int edge) const noexcept { return segment_of[t][edge] != no_index; }
  Point circumcentre_of(std::uint32_t t) const noexcept {
    const auto& v = triangles[t];
    return circumcentre(points[v[0]], points[v[1]], points[v[2]]);
  }
  friend bool operator==(const Triangulation&, const Triangulation&) = default;
};

// Delaunay triangulation of a point set (its convex hull). Duplicate points
// are an error (InvalidInputError). Fewer than three non-collinear points give
// no triangles. Deterministic, O(n log n) expected.
Triangulation delaunay(std::span<const Point> points);

struct TriangulateOptions {
  // Keep every triangle of the convex hull (Triangle's -c) but those the hole
  // points remove. Off: triangles are removed from the hull inwards up to the
  // first segments (Triangle's -p), and from every hole point outwards.
  bool convex_hull = false;
  // Give every triangle the attribute of the region point whose region (up to
  // the segments) holds it, 0 where there is none; of two region points in
  // one region the later wins (Triangle's -A). A region point on a segment
  // falls on one side of it.
  bool region_attributes = false;
  friend bool operator==(const TriangulateOptions&, const TriangulateOptions&) = default;
};

// Constrained Delaunay triangulation of a PSLG that passed validate_pslg()
// (crossings resolved first by resolve_intersections(), if any): every vertex
// is a vertex of the triangulation (isolated ones included), every segment a
// chain of constrained edges (split where a vertex lies exactly on it). Then
// the outside is removed as `options` says, and from every hole point the
// region around it (flood across unconstrained edges only, as Triangle does).
// Without segments the whole convex hull is kept whatever `options` says
// (Triangle's -p would keep nothing). Points outside what is kept stay in
// `points` but are in no triangle.
Triangulation triangulate(const Pslg& pslg, const TriangulateOptions& options = {});

// Independent check of the invariants: orientation, symmetric adjacency, the
// empty-circle property of every unconstrained interior edge (exact incircle),
// and, when `pslg` is given, every segment present as a chain of edges and the
// total area exactly that of the region triangulate(*pslg, options) keeps;
// with attributes, one per triangle, equal across every unconstrained edge;
// (summed in exact expansion arithmetic; with `convex_hull` and a hole point
// outside every bounded face, the area is not checked).
Verification verify_triangulation(const Triangulation& tri, const Pslg* pslg = nullptr,
                                  const TriangulateOptions& options = {});

}  // namespace madd
