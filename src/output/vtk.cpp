// The legacy VTK view of a decomposition (include/madd/output_formats.hpp).
// VTK's POLYGON cell has no holes and ParaView triangulates concave polygons
// heuristically, so each subdomain is written as its own constrained Delaunay
// triangles: exact shape, holes kept, and cells of one subdomain share its
// cell data so "Threshold" or "Color by subdomain" work per subdomain. Every
// segment is a line cell too, and every isolated point a vertex cell, told
// apart by the "kind" array, so the lines can be shown over the triangles.
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/output_formats.hpp"
#include "madd/triangulation.hpp"
#include "kernel/number_format.hpp"
#include "output/faces.hpp"

namespace madd {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The triangles of one subdomain, as indices into Decomposition::points. Its
// rings become a local PSLG (a vertex shared by two rings is one point) with
// one hole point per hole ring; triangulate adds no points.
// With `faces` (the decomposition's, output/faces.hpp), `face_of` gets, per
// triangle, the index in `faces` of the face holding it: each face's point is
// a region point of the local triangulation, so its flood marks the face.
std::vector<Triangle> subdomain_triangles(const Decomposition& d, std::uint32_t k,
                                          const std::vector<detail::DecompositionFace>& faces,
                                          std::vector<std::uint32_t>& face_of) {
  const Subdomain& s = d.subdomains[k];
  Pslg local;
  std::vector<std::uint32_t> global;
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  auto local_index = [&](std::uint32_t g) {
    const auto [it, inserted] = local_of.try_emplace(g, static_cast<std::uint32_t>(global.size()));
    if (inserted) {
      global.push_back(g);
      local.points.push_back(d.points[g]);
    }
    return it->second;
  };
  for (const auto& ring : s.rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      local.segments.push_back({local_index(ring[i]), local_index(ring[(i + 1) % ring.size()]), 1});
  // Interior segments and isolated points are edges and vertices of the
  // triangles too, so the cells conform to what the mesher will keep.
  for (const std::uint32_t j : s.interior_segments)
    local.segments.push_back({local_index(d.segments[j].a), local_index(d.segments[j].b), 1});
  for (const std::uint32_t p : s.interior_points) local_index(p);
  local.holes = s.hole_points;
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    if (faces[f].subdomain == k) local.regions.push_back({faces[f].point, f + 1.0, -1.0});
  TriangulateOptions options;
  options.region_attributes = !local.regions.empty();
  const Triangulation tri = triangulate(local, options);
  std::vector<Triangle> out;
  out.reserve(tri.triangles.size());
  for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
    out.push_back({global[tri.triangles[t][0]], global[tri.triangles[t][1]], global[tri.triangles[t][2]]});
    face_of.push_back(
        tri.attributes.empty() || tri.attributes[t] < 1 ? no_index : static_cast<std::uint32_t>(tri.attributes[t]) - 1);
  }
  return out;
}

// What a cell is (the "kind" cell array, docs/formats.md).
enum CellKind : int {
  subdomain_triangle = 0,
  boundary_piece = 1,
  separator_piece = 2,
  interior_piece = 3,
  isolated_point = 4
};

// The cells in the order legacy POLYDATA numbers them (VERTICES, LINES,
// POLYGONS), with the cell data of each.
struct Cells {
  std::vector<std::uint32_t> vertices;  // isolated points
  std::vector<std::uint32_t> lines;     // every segment, by index
  std::vector<Triangle> triangles;
  std::vector<std::int64_t> subdomain;  // -1: a separator, in two subdomains
  std::vector<int> kind, marker;
  // Only when the input has regions: the attribute and max area Triangle
  // would give each triangle (output 1's regions), 0 and -1 for other cells.
  std::vector<double> region_attribute, region_max_area;
  std::size_t size() const { return subdomain.size(); }
};

Cells collect_cells(const Decomposition& d) {
  Cells c;
  const std::vector<std::uint32_t> owner = interior_segment_owners(d);
  std::vector<std::int64_t> segment_subdomain(d.segments.size(), -1);
  for (std::size_t k = 0; k < d.subdomains.size(); ++k)
    for (const auto& ring : d.subdomains[k].ring_segments)
      for (const std::uint32_t j : ring)
        if (!d.is_separator(j)) segment_subdomain[j] = static_cast<std::int64_t>(k);
  for (std::size_t k = 0; k < d.subdomains.size(); ++k)
    for (const std::uint32_t p : d.subdomains[k].interior_points) {
      c.vertices.push_back(p);
      c.subdomain.push_back(static_cast<std::int64_t>(k));
      c.kind.push_back(isolated_point);
      c.marker.push_back(0);
    }
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    c.lines.push_back(j);
    const bool interior = owner[j] != no_index;
    c.subdomain.push_back(interior ? std::int64_t{owner[j]} : segment_subdomain[j]);
    c.kind.push_back(d.is_separator(j) ? separator_piece : interior ? interior_piece : boundary_piece);
    c.marker.push_back(d.segments[j].marker);
  }
  const bool regions = !d.regions.empty();
  const std::vector<detail::DecompositionFace> faces =
      regions ? detail::decomposition_faces(d) : std::vector<detail::DecompositionFace>{};
  if (regions) {
    c.region_attribute.assign(c.size(), 0.0);
    c.region_max_area.assign(c.size(), -1.0);
  }
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    std::vector<std::uint32_t> face_of;
    const std::vector<Triangle> triangles = subdomain_triangles(d, k, faces, face_of);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      c.triangles.push_back(triangles[i]);
      c.subdomain.push_back(static_cast<std::int64_t>(k));
      c.kind.push_back(subdomain_triangle);
      c.marker.push_back(0);
      if (!regions) continue;
      const std::uint32_t r = face_of[i] == no_index ? no_index : faces[face_of[i]].region;
      c.region_attribute.push_back(r == no_index ? 0.0 : d.regions[r].attribute);
      c.region_max_area.push_back(r == no_index ? -1.0 : d.regions[r].max_area);
    }
  }
  return c;
}

// One array of a FIELD block: "name 1 count type", then one value per cell.
template <class T, class F>
void append_field_array(std::string& out, const char* name, const char* type, const std::vector<T>& values, F&& write) {
  out += name;
  out += " 1 ";
  detail::append_int(out, static_cast<std::int64_t>(values.size()));
  out += ' ';
  out += type;
  out += '\n';
  for (const T& v : values) {
    write(v);
    out += '\n';
  }
}

// "KEYWORD cells size": size counts every integer of the section.
void append_section(std::string& out, const char* keyword, std::size_t cells, std::size_t per_cell) {
  out += keyword;
  out += ' ';
  detail::append_int(out, static_cast<std::int64_t>(cells));
  out += ' ';
  detail::append_int(out, static_cast<std::int64_t>(cells * (per_cell + 1)));
  out += '\n';
}

}  // namespace

std::string format_vtk(const Decomposition& decomposition) {
  const Decomposition& d = decomposition;
  const Cells cells = collect_cells(d);
  std::string out = "# vtk DataFile Version 3.0\nmadd decomposition, ";
  detail::append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += " subdomains as triangles, segments as lines\nASCII\nDATASET POLYDATA\nPOINTS ";
  detail::append_int(out, static_cast<std::int64_t>(d.points.size()));
  out += " double\n";
  for (const Point& p : d.points) {
    detail::append_g17(out, p.x);
    out += ' ';
    detail::append_g17(out, p.y);
    out += " 0\n";
  }
  if (!cells.vertices.empty()) {
    append_section(out, "VERTICES", cells.vertices.size(), 1);
    for (const std::uint32_t p : cells.vertices) {
      out += "1 ";
      detail::append_int(out, p);
      out += '\n';
    }
  }
  append_section(out, "LINES", cells.lines.size(), 2);
  for (const std::uint32_t j : cells.lines) {
    out += "2 ";
    detail::append_int(out, d.segments[j].a);
    out += ' ';
    detail::append_int(out, d.segments[j].b);
    out += '\n';
  }
  append_section(out, "POLYGONS", cells.triangles.size(), 3);
  for (const Triangle& t : cells.triangles) {
    out += '3';
    for (const std::uint32_t v : t) {
      out += ' ';
      detail::append_int(out, v);
    }
    out += '\n';
  }
  out += "CELL_DATA ";
  detail::append_int(out, static_cast<std::int64_t>(cells.size()));
  out += "\nSCALARS subdomain int 1\nLOOKUP_TABLE default\n";
  for (const std::int64_t k : cells.subdomain) {
    detail::append_int(out, k);
    out += '\n';
  }
  // VTK's legacy reader keeps only the first SCALARS of a section unless told
  // otherwise (ReadAllScalars), but always reads FIELD arrays. A separator's
  // area and weight are 0: it belongs to two subdomains.
  const auto of_subdomain = [&](double Subdomain::*field) {
    std::vector<double> v;
    for (const std::int64_t k : cells.subdomain)
      v.push_back(k < 0 ? 0.0 : d.subdomains[static_cast<std::size_t>(k)].*field);
    return v;
  };
  const auto write_double = [&](double v) { detail::append_g17(out, v); };
  const auto write_int = [&](int v) { detail::append_int(out, v); };
  out += cells.region_attribute.empty() ? "FIELD FieldData 4\n" : "FIELD FieldData 6\n";
  append_field_array(out, "area", "double", of_subdomain(&Subdomain::area), write_double);
  append_field_array(out, "weight", "double", of_subdomain(&Subdomain::weight), write_double);
  append_field_array(out, "kind", "int", cells.kind, write_int);
  append_field_array(out, "marker", "int", cells.marker, write_int);
  if (!cells.region_attribute.empty()) {
    append_field_array(out, "region_attribute", "double", cells.region_attribute, write_double);
    append_field_array(out, "region_max_area", "double", cells.region_max_area, write_double);
  }
  return out;
}

}  // namespace madd
