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

void open_array(std::string& out, const char* type, const char* name, int components = 1) {
  out += "        <DataArray type=\"";
  out += type;
  out += '"';
  if (name != nullptr) {
    out += " Name=\"";
    out += name;
    out += '"';
  }
  if (components != 1) out += " NumberOfComponents=\"" + std::to_string(components) + '"';
  out += " format=\"ascii\">\n";
}

void close_array(std::string& out) { out += "        </DataArray>\n"; }

} // namespace

std::string format_mesh_vtu(const Mesh& mesh) {
  const std::size_t n = mesh.points.size(), t = mesh.triangles.size();
  std::string out;
  out.reserve(48 * n + 40 * t + 1024);
  out += "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(t) + "\">\n";
  out += "      <PointData Scalars=\"marker\">\n";
  open_array(out, "Int32", "marker");
  for (std::size_t v = 0; v < n; ++v) line(out, v < mesh.point_markers.size() ? mesh.point_markers[v] : 0);
  close_array(out);
  out += "      </PointData>\n      <CellData Scalars=\"subdomain\">\n";
  open_array(out, "Int32", "subdomain");
  for (const std::uint32_t k : mesh.triangle_subdomain) line(out, k);
  close_array(out);
  out += "      </CellData>\n      <Points>\n";
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

} // namespace madd
