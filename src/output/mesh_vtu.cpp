// The merged mesh as a VTK XML UnstructuredGrid (include/madd/mesh_output.hpp),
// ASCII so it diffs and greps; ParaView reads it as it is. Connectivity and
// offsets are Int64: a mesh of more than 2^31 / 3 triangles overflows Int32.
#include <cstdint>
#include <string>

#include "madd/mesh_output.hpp"
#include "output/mesh_text.hpp"

namespace madd {
namespace {

using detail::line;

// `id_type`: the array holds vtkIdType values (IdType="1"), which VTK needs
// to take it as the GlobalIds attribute.
void open_array(std::string& out, const char* type, const char* name, int components = 1, bool id_type = false) {
  out += "        <DataArray type=\"";
  out += type;
  out += '"';
  if (name != nullptr) {
    out += " Name=\"";
    out += name;
    out += '"';
  }
  if (id_type) out += " IdType=\"1\"";
  if (components != 1) out += " NumberOfComponents=\"" + std::to_string(components) + '"';
  out += " format=\"ascii\">\n";
}

void close_array(std::string& out) { out += "        </DataArray>\n"; }

// The points' and cells' data arrays: a part's global ids first (they are
// the GlobalIds attribute ParaView joins the pieces of a .pvtu by).
template <typename AnyMesh>
void append_point_data(std::string& out, const AnyMesh& mesh, const detail::VtuGlobalIds* global) {
  const std::size_t n = mesh.points.size();
  out += global ? "      <PointData Scalars=\"marker\" GlobalIds=\"global_id\">\n"
                : "      <PointData Scalars=\"marker\">\n";
  if (global) {
    open_array(out, "Int64", "global_id", 1, true);
    for (const std::uint64_t id : *global->point_ids) line(out, id);
    close_array(out);
    open_array(out, "Int32", "owner");
    for (const std::uint32_t r : *global->point_owner) line(out, r);
    close_array(out);
  }
  open_array(out, "Int32", "marker");
  for (std::size_t v = 0; v < n; ++v) line(out, v < mesh.point_markers.size() ? mesh.point_markers[v] : 0);
  close_array(out);
  out += "      </PointData>\n";
}

template <typename AnyMesh>
void append_cell_data(std::string& out, const AnyMesh& mesh, bool regions, const detail::VtuGlobalIds* global) {
  out += global ? "      <CellData Scalars=\"subdomain\" GlobalIds=\"global_id\">\n"
                : "      <CellData Scalars=\"subdomain\">\n";
  if (global) {
    open_array(out, "Int64", "global_id", 1, true);
    for (const std::uint64_t id : *global->triangle_ids) line(out, id);
    close_array(out);
    open_array(out, "Int32", "rank");
    for (std::size_t c = 0; c < mesh.triangles.size(); ++c) line(out, global->rank);
    close_array(out);
  }
  open_array(out, "Int32", "subdomain");
  for (const std::uint32_t k : mesh.triangle_subdomain) line(out, k);
  close_array(out);
  if (regions) {  // with regions (Triangle's -A)
    open_array(out, "Float64", "region_attribute");
    for (std::size_t c = 0; c < mesh.triangles.size(); ++c) line(out, detail::region_attribute(mesh, c));
    close_array(out);
  }
  out += "      </CellData>\n";
}

// A Mesh or a part's LocalMesh: the same fields.
template <typename AnyMesh>
std::string vtu_text(const AnyMesh& mesh, bool regions, const detail::VtuGlobalIds* global) {
  const std::size_t n = mesh.points.size(), t = mesh.triangles.size();
  std::string out;
  out.reserve((global ? 72 : 48) * n + (global ? 64 : 40) * t + 1024);
  out += "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(t) + "\">\n";
  append_point_data(out, mesh, global);
  append_cell_data(out, mesh, regions, global);
  out += "      <Points>\n";
  open_array(out, "Float64", nullptr, 3);
  for (const Point& p : mesh.points) line(out, p.x, p.y, 0.0);
  close_array(out);
  out += "      </Points>\n      <Cells>\n";
  open_array(out, "Int64", "connectivity");
  for (const auto& tri : mesh.triangles) line(out, tri[0], tri[1], tri[2]);
  close_array(out);
  open_array(out, "Int64", "offsets");
  for (std::size_t c = 1; c <= t; ++c) line(out, 3 * c);
  close_array(out);
  open_array(out, "UInt8", "types");
  for (std::size_t c = 0; c < t; ++c) out += "5\n";
  close_array(out);
  out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace

namespace detail {

std::string format_vtu(const LocalMesh& mesh, bool regions, const VtuGlobalIds& global) {
  return vtu_text(mesh, regions, &global);
}

}  // namespace detail

std::string format_mesh_vtu(const Mesh& mesh) { return vtu_text(mesh, detail::has_region_attributes(mesh), nullptr); }

}  // namespace madd
