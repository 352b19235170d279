#pragma once
// Delaunay refinement of one subdomain (docs/mesh.md, "Refinement"): Ruppert's
// algorithm with Chew's and Shewchuk's rules for small angles, and Ungor's
// off-centres. Separators are never split (the decoupling makes that
// unnecessary where the guarantee holds); boundary and interior pieces are
// split like Ruppert's segments, at powers of two from a sharp input corner
// (concentric shells).
#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "kernel/resource_limits.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

struct RefineSettings {
  double min_triangle_angle_deg = 30.0;
  const AreaBound* size = nullptr;  // the area bound (nullptr = none)
  bool off_centres = true;
  std::size_t max_steiner_points = 0;  // 0 = no budget
  double expected_triangles = 0;       // to reserve room (docs/mesh.md, "Balance by work")
  // Checked every few thousand new vertices: throws LimitError past the
  // run's time or memory limit (nullptr = none).
  const ResourceGuard* guard = nullptr;
  const std::atomic<std::uint32_t>* meshed = nullptr;  // subdomains done so far, for the limit's message
  // Under a graded field, read most triangles' bounds from a neighbour's
  // query (refine.cpp, Refiner::bound_of): the same mesh, fewer queries.
  // Off only to show that it changes nothing (tests).
  bool bounds_from_neighbours = true;
};

// A subdomain mesh in local numbering: the input's points first, same
// indices, then the Steiner points. A Steiner point on a segment records it
// and its parameter along it (0 at the segment's a, 1 at its b).
struct SubdomainMesh {
  std::vector<Point> points;
  std::vector<std::uint32_t> point_segment;  // per point: no_index, or the segment a Steiner point lies inside
  std::vector<double> point_parameter;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 3>> neighbours;  // across edge i (opposite corner i); no_index outside
  // With regions (the input Pslg's regions not empty): per triangle the
  // attribute of the region whose face holds it, 0 for none.
  std::vector<double> triangle_attribute;
  MeshShortfall shortfall;
  // Separator segments (local ids) whose diametral circle a point that would
  // fix a bad triangle fell into: split them (for both subdomains) and mesh
  // again (docs/mesh.md, "Decoupling").
  std::vector<std::uint32_t> blocking_separators;
  friend bool operator==(const SubdomainMesh&, const SubdomainMesh&) = default;
};

// Refines the constrained Delaunay triangulation of `pslg` (one closed
// subdomain: rings of segments, hole points, interior segments and isolated
// vertices inside). Segment i may be split when splittable[i]. pslg.regions
// are the subdomain's regions (Triangle's -A and -a: each triangle gets the
// attribute of the region whose face holds it, and no more than its
// max_triangle_area when > 0). Deterministic.
SubdomainMesh refine_subdomain(const Pslg& pslg, const std::vector<bool>& splittable, const RefineSettings& settings);

}  // namespace madd::detail
