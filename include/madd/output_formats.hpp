#pragma once
// Views of a Decomposition for other tools: a gmsh .geo model, a legacy VTK
// file for ParaView and GeoJSON. Like output.hpp, each returns the whole text
// (write it with write_file_atomically); docs/api.md says how each tool reads them.
#include <string>

#include "madd/decomposition.hpp"

namespace madd {

// The options of format_geo.
struct GeoOptions {
  // Target element size written at every Point. 0 (the default) writes, at
  // each point, the length of the shortest segment meeting it, so gmsh keeps
  // the decomposition's own resolution; > 0 uses that size everywhere.
  double mesh_size = 0.0;
  friend bool operator==(const GeoOptions&, const GeoOptions&) = default;
};

// A gmsh .geo model (built-in kernel, %.17g) of the whole subdivision:
// Point(i+1) per point, Line(j+1) per segment (each written once, so
// neighbouring surfaces share it and `gmsh -2` meshes conformingly), one Curve
// Loop per ring, Plane Surface(k+1) per subdomain k (outer loop, then holes),
// its interior segments and isolated points embedded in it (Line{...} In
// Surface, Point{...} In Surface), Physical Surface("subdomain_<k>", k+1),
// and Physical Curve("boundary_<m>") per marker m of the input's segments,
// boundary and interior pieces alike (tag m when m > 0, else chosen by gmsh).
std::string format_geo(const Decomposition& decomposition, const GeoOptions& options = {});

// A legacy VTK (version 3.0, ASCII) POLYDATA file: every point, then the
// isolated points as VERTICES, every segment as LINES, and the subdomains as
// POLYGONS. VTK polygons cannot have holes and concave ones are rendered by
// guesswork, so each subdomain is written as the triangles of its
// constrained Delaunay triangulation (madd::triangulate over its rings and
// interior segments; no new points). CELL_DATA of every cell: SCALARS
// subdomain (int; -1 for a separator), and FIELD arrays area and weight
// (its subdomain's; FIELD, so VTK's reader loads them all), kind (0 triangle,
// 1 boundary piece, 2 separator, 3 interior segment, 4 isolated point) and
// marker (the segment's, else 0); with the input's regions, region_attribute
// and region_max_area (the triangle's under Triangle's -A and -a rule; 0 and
// -1 where no region reaches and for the other cells).
// Triangles of neighbouring subdomains share the points of their separator.
// Throws what madd::triangulate throws if a subdomain is not a valid polygon.
std::string format_vtk(const Decomposition& decomposition);

// An RFC 7946 GeoJSON FeatureCollection: one Polygon Feature per subdomain,
// outer ring counter-clockwise then hole rings clockwise, each ring closed by
// repeating its first position; properties {"id": k, "area", "weight"}. Then
// one LineString per interior segment piece, properties {"subdomain",
// "segment" (1-based id in output 1), "marker"}, and one Point per isolated
// point, properties {"subdomain", "point" (1-based id in output 1)}.
// Coordinates are the plane's x and y, in the shortest text that reads back
// exactly (std::to_chars), not longitude and latitude.
std::string format_geojson(const Decomposition& decomposition);

}  // namespace madd
