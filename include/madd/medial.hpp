#pragma once
// The circumcentre approximation of the medial axis of one (sub)domain and the
// MADD graphs built on it: junction triangles (paper Sec. 3), G_D
// (Algorithm 1) and the contracted graph G'_D (Algorithm 2).
#include <array>
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/graph.hpp"
#include "madd/triangulation.hpp"

namespace madd {

struct MedialOptions {
  double separator_angle_deg = 60.0;  // Phi0
  bool smooth = true;                 // scale edge weights by the Sec. 5.1 angle coefficient and end bonuses
  friend bool operator==(const MedialOptions&, const MedialOptions&) = default;
};

// The smaller of the two angles (degrees) that the segment from boundary
// vertex `at` towards `towards` makes with the boundary at `at`, i.e. with the
// ring edges to prev and next. Returns -1 when `towards` is not strictly
// inside the domain's wedge at `at`. Orientation signs are exact.
double boundary_angle(Point at, Point prev, Point next, Point towards);

// One edge of G_D and the partial-separator segment it stands for: a triangle
// edge or a spoke from a junction circumcentre, as indices into
// MedialGraph::points, with G_D vertex `left` on its left going from -> to.
struct MedialEdge {
  std::uint32_t left = 0;
  std::uint32_t right = 0;
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  double smallest_angle_deg = 180.0;  // the smallest angle it makes (boundary, other spokes)
  bool acceptable = false;            // every angle it makes is >= Phi0
  friend bool operator==(const MedialEdge&, const MedialEdge&) = default;
};

struct MedialGraph {
  std::vector<Point> points;                   // triangulation points, then junction circumcentres
  std::vector<std::uint32_t> centre;           // per triangle: its circumcentre in points, or no_index
  std::vector<std::uint32_t> first_vertex;     // per triangle: its G_D vertex (junction: three,
                                               // first + i being the sub-triangle next to edge i)
  std::vector<std::uint32_t> vertex_triangle;  // per G_D vertex: its triangle
  std::vector<std::uint8_t> vertex_sub;        // per G_D vertex: sub-triangle 0-2, or 3 for a whole triangle
  Graph gd;                                    // G_D: vertex weight = area, edge weight = (smoothed) length
  std::vector<MedialEdge> edges;               // G_D's edges, each once
  std::vector<std::uint32_t> coarse;           // per G_D vertex: its G'_D vertex
  Graph contracted;                            // G'_D: only acceptable partial separators remain as edges
  // G'_D edge k joins contracted_ends[k] (u < v) and stands for the G_D edges
  // separators[separator_offsets[k] .. separator_offsets[k+1]).
  std::vector<std::array<std::uint32_t, 2>> contracted_ends;
  std::vector<std::uint32_t> separator_offsets;
  std::vector<std::uint32_t> separators;
  friend bool operator==(const MedialGraph&, const MedialGraph&) = default;
};

// Builds G_D and G'_D for a triangulation whose vertices all lie on the
// boundary of the triangulated region (as a split's working triangulation:
// the boundary's sample points only). Each vertex's neighbours along the
// boundary are read off the triangles' outer edges, with the region on
// their left; a vertex the boundary passes twice is one where no separator
// may end. Deterministic.
MedialGraph build_medial_graph(const Triangulation& tri, const MedialOptions& options = {});

// The corners of G_D vertex v (a triangle, or a sub-triangle around a circumcentre), counter-clockwise.
std::array<Point, 3> vertex_triangle_corners(const MedialGraph& graph, const Triangulation& tri, std::uint32_t v);

}  // namespace madd
