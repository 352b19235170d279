#pragma once
// A coastline as a domain (docs/coastal.md): the water polygons of a GIS file
// (madd/polygons.hpp) cut to a box, projected to metres, cleaned as real data
// needs, and turned into the one connected Pslg that check, decompose, mesh
// and triangulate take, with the coast marked as land and the box's sides as
// open boundary.
#include <cstddef>
#include <optional>
#include <string>

#include "madd/bathymetry.hpp"
#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/polygons.hpp"
#include "madd/pslg.hpp"

namespace madd {

// The local projection meshing happens in: equirectangular about a centre
// (lon0, lat0), as ADCIRC's CPP (carte parallelogrammatique) projection,
// with the origin moved to the centre so that coordinates stay small:
//   x = R cos(lat0) (lon - lon0) pi/180,  y = R (lat - lat0) pi/180,
// R = 6378206.4 m (the radius ADCIRC uses). Lengths are true along the
// parallel lat0 and along every meridian; along other parallels they are
// off by cos(lat)/cos(lat0) (0.6% at 1 degree of latitude from the centre
// at 45 N), which a size field in metres inherits. `geographic` false is the
// identity (the file was in projected metres already).
struct Projection {
  static constexpr double earth_radius_m = 6378206.4;
  bool geographic = false;
  double lon0_deg = 0.0;
  double lat0_deg = 0.0;

  Point to_metres(Point lonlat) const noexcept;
  Point to_lonlat(Point xy) const noexcept;
  // A gradient per unit of the file's coordinates (per degree) as a
  // gradient per metre.
  Point gradient_to_metres(Point per_unit) const noexcept;
  friend bool operator==(const Projection&, const Projection&) = default;
};

// An axis-aligned box in the file's coordinates (lon/lat degrees, or
// projected units): x0 < x1, y0 < y1.
struct ClipBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  friend bool operator==(const ClipBox&, const ClipBox&) = default;
};

struct CoastOptions {
  // Cut the water polygons to this box (--clip); the box's sides that bound
  // the water become open boundary. None: the polygons as they are.
  std::optional<ClipBox> clip;
  // Keep the connected water body holding this point (file coordinates);
  // none: the one of largest area.
  std::optional<Point> water_at;
  // Islands (holes) and water bodies of smaller area, in square metres (of
  // the projection), are removed (--min-island-area); 0 keeps every one.
  double min_island_area = 0.0;
  // Consecutive vertices of a ring closer than this (metres) are merged;
  // 0: 1e-9 of the domain's extent (well below any mesh size, above the
  // rounding of the projection).
  double merge_distance = 0.0;
  int open_marker = 2;  // the marker of the box's sides; the coast keeps its polygon's marker (1 by default)
  friend bool operator==(const CoastOptions&, const CoastOptions&) = default;
};

// What cleaning did, for `madd check` and the run's report.
struct CoastReport {
  std::size_t polygons_read = 0, rings_read = 0, vertices_read = 0;
  std::size_t bodies = 0;                 // water bodies after clipping (outer rings)
  std::size_t bodies_dropped = 0;         // ... not kept (smaller, elsewhere, or below min_island_area)
  std::size_t islands = 0;                // islands (holes) of the kept body
  std::size_t small_islands_removed = 0;  // holes below min_island_area
  std::size_t vertices_merged = 0;        // duplicate or nearer than merge_distance to the previous one
  std::size_t spikes_removed = 0;         // vertices where a ring doubles back on itself
  std::size_t rings_collapsed = 0;        // rings left with no area after merging and spikes
  std::size_t crossings_resolved = 0;     // pairs of ring edges crossing or overlapping, split where they meet
  std::size_t pinches = 0;                // vertices where rings touch (shared by several boundary loops)
  std::size_t pockets_dropped = 0;        // water pieces cut off at touching points, not kept
  double area_m2 = 0.0;                   // of the domain
  std::size_t open_segments = 0;          // boundary segments with the open marker
  std::size_t land_segments = 0;
  friend bool operator==(const CoastReport&, const CoastReport&) = default;
};

struct CoastDomain {
  Pslg domain;  // in the projection's metres, valid (validate() passed)
  Projection projection;
  CoastReport report;
  friend bool operator==(const CoastDomain&, const CoastDomain&) = default;
};

// Clips, projects and cleans `polygons` into one domain (docs/coastal.md,
// "From polygons to a domain"). `path` names the file in error messages.
// Throws OptionError on a bad option (an empty box, water_at in no water),
// InvalidInputError when no water is left or what is left cannot be a
// domain (with the nearest input vertex: "feature K, polygon P, ring R,
// vertex V"). Deterministic.
CoastDomain coast_domain(const PolygonSet& polygons, const CoastOptions& options = {}, const std::string& path = {});

// read_polygons + coast_domain.
CoastDomain read_coast(const std::string& path, const CoastOptions& options = {});

// The depth rules of `size` (MeshSizeOptions::depth, depth_gradient) read
// from `depth`, whose coordinates are the file's (lon/lat for a lon/lat
// coastline), at the projection's metres. Both keep a copy of the field
// (cheap: it shares its interpolant) and of the projection.
void set_depth(MeshSizeOptions& size, const DepthField& depth, const Projection& projection);

}  // namespace madd
