#pragma once
// Internals of verify_mesh(), split by concern. Every check after
// check_mesh_shape relies on the indices it has checked being in range.
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/exact_sum.hpp"
#include "madd/mesh.hpp"
#include "quality/area_bound.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

// "triangle t (subdomain k) (x, y) (x, y) (x, y)", for messages.
std::string mesh_triangle_text(const Mesh& mesh, std::uint32_t t);

// What the edge pass (verify_mesh_edges.cpp) leaves for the later checks.
struct MeshEdges {
  // Twice the triangles' total signed area, exactly.
  ExactSum twice_area;
  // Every edge no triangle is linked across (a free edge), directed as its
  // triangle has it, in triangle order.
  std::vector<Segment> boundary;
};

// Adjacency (mutual links across every shared edge), conformity across
// subdomains, free edges = boundary segments, every segment one edge,
// constrained Delaunay within each subdomain; in chunks of triangles on
// `threads` threads, the same report for any count (verify_mesh_edges.cpp
// says why this and the cover check rule out any overlap). ccw[t] != 0
// when triangle t is strictly counter-clockwise (the in-circle test needs it).
MeshEdges check_mesh_edges(const Mesh& mesh, const std::vector<std::uint8_t>& ccw, ProblemLog& log,
                           unsigned threads = 1);

// The mesh segments against the decomposition and the input: markers, each
// decomposition segment covered by one chain of its mesh segments, each input
// segment by one chain of boundary segments near it, the points' markers.
// Returns the bound on twice the area between the boundary chains and the
// input segments (for the cover check). In parts on `threads` threads, the
// same report and bound for any count.
double check_mesh_segments(const Mesh& mesh, const Pslg& domain, ProblemLog& log, unsigned threads = 1);

// Twice the triangles' exact area (the sum over the free edges) equal to
// twice the domain's, up to `sliver` (check_mesh_segments' bound): with the
// links and the boundary chains checked, no gap and no overlap.
void check_cover(const ExactSum& twice_area, const Pslg& domain, double sliver, ProblemLog& log);

// No triangle vertex strictly inside an edge that only one triangle has
// (the vertices in parts on `threads` threads).
void check_hanging_vertices(const Mesh& mesh, const std::vector<Segment>& boundary, ProblemLog& log,
                            unsigned threads = 1);

// Every isolated input vertex (Subdomain::interior_points) a vertex of a
// triangle of its subdomain (the subdomains on `threads` threads).
void check_interior_points(const Mesh& mesh, ProblemLog& log, unsigned threads = 1);

// Per triangle: 1 + the index of the region (mesh.decomposition.regions)
// whose flood holds it, 0 for none; the flood starts from the lowest
// triangle whose closure holds the region point and crosses every edge but
// boundary and interior segments, regions in input order, the later
// winning. All 0 without regions. Found on `threads` threads, the same for any count.
std::vector<std::uint32_t> mesh_regions(const Mesh& mesh, unsigned threads = 1);

// mesh.triangle_attribute equal to the attribute of each triangle's region
// by `label` (mesh_regions), 0 in none (in parts on `threads` threads).
void check_region_attributes(const Mesh& mesh, const std::vector<std::uint32_t>& label, ProblemLog& log,
                             unsigned threads = 1);

// Every triangle within the size bound at its centroid and within its
// region's max_area (by `label`, mesh_regions; when > 0). The bounds are
// read on `threads` threads (a query of the size field per triangle), the
// same report for any count.
void check_mesh_size(const Mesh& mesh, const AreaBound& bound, const std::vector<std::uint32_t>& label, ProblemLog& log,
                     unsigned threads = 1);

// The triangles below the angle bound are exactly as many as the shortfall
// counts (the angles measured on `threads` threads).
void check_mesh_angles(const Mesh& mesh, ProblemLog& log, unsigned threads = 1);

}  // namespace madd::detail
