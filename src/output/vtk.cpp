// The legacy VTK view of a decomposition (include/madd/output_formats.hpp).
// VTK's POLYGON cell has no holes and ParaView triangulates concave polygons
// heuristically, so each subdomain is written as its own constrained Delaunay
// triangles: exact shape, holes kept, and cells of one subdomain share its
// cell data so "Threshold" or "Color by subdomain" work per subdomain.
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/output_formats.hpp"
#include "madd/triangulation.hpp"
#include "kernel/number_format.hpp"

namespace madd {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The triangles of one subdomain, as indices into Decomposition::points. Its
// rings become a local PSLG (a vertex shared by two rings is one point) with
// one hole point per hole ring; triangulate adds no points.
std::vector<Triangle> subdomain_triangles(const Decomposition& d, const Subdomain& s) {
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
    for (std::size_t k = 0; k < ring.size(); ++k)
      local.segments.push_back({local_index(ring[k]), local_index(ring[(k + 1) % ring.size()]), 1});
  local.holes = s.hole_points;
  const Triangulation tri = triangulate(local);
  std::vector<Triangle> out;
  out.reserve(tri.triangles.size());
  for (const Triangle& t : tri.triangles) out.push_back({global[t[0]], global[t[1]], global[t[2]]});
  return out;
}

// One array of a FIELD block: "name 1 count double", then one value per cell.
void append_field_array(std::string& out, const char* name, const std::vector<std::size_t>& owner,
                        const std::vector<double>& value_of_subdomain) {
  out += name;
  out += " 1 ";
  detail::append_int(out, static_cast<std::int64_t>(owner.size()));
  out += " double\n";
  for (const std::size_t k : owner) {
    detail::append_g17(out, value_of_subdomain[k]);
    out += '\n';
  }
}

} // namespace

std::string format_vtk(const Decomposition& decomposition) {
  const Decomposition& d = decomposition;
  std::vector<Triangle> cells;
  std::vector<std::size_t> owner;  // subdomain of each cell
  for (std::size_t k = 0; k < d.subdomains.size(); ++k) {
    const std::vector<Triangle> tris = subdomain_triangles(d, d.subdomains[k]);
    cells.insert(cells.end(), tris.begin(), tris.end());
    owner.insert(owner.end(), tris.size(), k);
  }
  std::string out = "# vtk DataFile Version 3.0\nmadd decomposition, ";
  detail::append_int(out, static_cast<std::int64_t>(d.subdomains.size()));
  out += " subdomains as triangles\nASCII\nDATASET POLYDATA\nPOINTS ";
  detail::append_int(out, static_cast<std::int64_t>(d.points.size()));
  out += " double\n";
  for (const Point& p : d.points) {
    detail::append_g17(out, p.x);
    out += ' ';
    detail::append_g17(out, p.y);
    out += " 0\n";
  }
  // The size after POLYGONS counts every integer of the section: 4 per triangle.
  out += "POLYGONS ";
  detail::append_int(out, static_cast<std::int64_t>(cells.size()));
  out += ' ';
  detail::append_int(out, static_cast<std::int64_t>(cells.size() * 4));
  out += '\n';
  for (const Triangle& t : cells) {
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
  for (const std::size_t k : owner) {
    detail::append_int(out, static_cast<std::int64_t>(k));
    out += '\n';
  }
  std::vector<double> area, weight;
  for (const Subdomain& s : d.subdomains) {
    area.push_back(s.area);
    weight.push_back(s.weight);
  }
  // VTK's legacy reader keeps only the first SCALARS of a section unless told
  // otherwise (ReadAllScalars), but always reads FIELD arrays.
  out += "FIELD FieldData 2\n";
  append_field_array(out, "area", owner, area);
  append_field_array(out, "weight", owner, weight);
  return out;
}

} // namespace madd
