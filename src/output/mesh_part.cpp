// One share's part of a mesh as files (include/madd/mesh_part_output.hpp):
// Triangle's .node/.ele with global ids as attributes, a .vtu piece, and the
// .pvtu that joins the pieces.
#include <string>
#include <utility>
#include <vector>

#include "madd/mesh_output.hpp"
#include "madd/mesh_part_output.hpp"
#include "madd/output.hpp"
#include "output/mesh_text.hpp"

namespace madd {

using detail::line;

namespace {

// The part's .node and .ele in pieces (detail::line_pieces), made while written.
FilePieces part_node_pieces(const MeshPart& part, unsigned first_index, unsigned threads) {
  detail::check_first_index(first_index);
  const LocalMesh& m = part.mesh;
  const std::size_t n = m.points.size();
  return detail::line_pieces(
      n, 64, [n](std::string& out) { line(out, n, 2, 2, 1); },
      [&part, first_index](std::string& out, std::size_t v) {
        const LocalMesh& lm = part.mesh;
        line(out, v + first_index, lm.points[v].x, lm.points[v].y, part.point_ids[v] + first_index, part.point_owner[v],
             lm.point_markers[v]);
      },
      threads);
}

FilePieces part_ele_pieces(const MeshPart& part, unsigned first_index, unsigned threads) {
  detail::check_first_index(first_index);
  const std::size_t n = part.mesh.triangles.size();
  // With regions, a third attribute: the triangle's region attribute.
  const bool regions = detail::has_region_attributes(part);
  return detail::line_pieces(
      n, 56, [n, regions](std::string& out) { line(out, n, 3, regions ? 3 : 2); },
      [&part, first_index, regions](std::string& out, std::size_t t) {
        const LocalMesh& m = part.mesh;
        const auto& tri = m.triangles[t];
        if (regions)
          line(out, t + first_index, tri[0] + first_index, tri[1] + first_index, tri[2] + first_index,
               m.triangle_subdomain[t], part.triangle_ids[t] + first_index, detail::region_attribute(m, t));
        else
          line(out, t + first_index, tri[0] + first_index, tri[1] + first_index, tri[2] + first_index,
               m.triangle_subdomain[t], part.triangle_ids[t] + first_index);
      },
      threads);
}

}  // namespace

std::string format_part_node(const MeshPart& part, unsigned first_index) {
  return detail::joined(part_node_pieces(part, first_index, 1));
}

std::string format_part_ele(const MeshPart& part, unsigned first_index) {
  return detail::joined(part_ele_pieces(part, first_index, 1));
}

std::string format_part_vtu(const MeshPart& part) {
  const detail::VtuGlobalIds global{&part.point_ids, &part.point_owner, &part.triangle_ids, part.share};
  return detail::format_vtu(part.mesh, detail::has_region_attributes(part), global);
}

std::string format_parts_pvtu(const std::vector<std::string>& pieces, bool region_attributes) {
  std::string out = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <PUnstructuredGrid GhostLevel=\"0\">\n"
                    "    <PPointData Scalars=\"marker\" GlobalIds=\"global_id\">\n"
                    "      <PDataArray type=\"Int64\" Name=\"global_id\" IdType=\"1\"/>\n"
                    "      <PDataArray type=\"Int32\" Name=\"owner\"/>\n"
                    "      <PDataArray type=\"Int32\" Name=\"marker\"/>\n"
                    "    </PPointData>\n"
                    "    <PCellData Scalars=\"subdomain\" GlobalIds=\"global_id\">\n"
                    "      <PDataArray type=\"Int64\" Name=\"global_id\" IdType=\"1\"/>\n"
                    "      <PDataArray type=\"Int32\" Name=\"rank\"/>\n"
                    "      <PDataArray type=\"Int32\" Name=\"subdomain\"/>\n";
  if (region_attributes) out += "      <PDataArray type=\"Float64\" Name=\"region_attribute\"/>\n";
  out += "    </PCellData>\n"
         "    <PPoints>\n"
         "      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
         "    </PPoints>\n";
  for (const std::string& piece : pieces) out += "    <Piece Source=\"" + piece + "\"/>\n";
  out += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string part_file_name(std::string_view stem, std::uint32_t share, std::uint32_t shares,
                           std::string_view extension) {
  return split_mesh_file_name(stem, share, shares, extension);
}

namespace {

// "dir/stem" -> ("dir/", "stem").
std::pair<std::string, std::string> split_prefix(const std::string& prefix) {
  const std::size_t slash = prefix.find_last_of('/');
  if (slash == std::string::npos) return {"", prefix};
  return {prefix.substr(0, slash + 1), prefix.substr(slash + 1)};
}

}  // namespace

void add_mesh_part(OutputSet& outputs, const MeshPart& part, const std::string& prefix, const MeshPartFormats& formats,
                   unsigned threads) {
  detail::check_first_index(formats.first_index);
  // Not a structured binding: clang 14 cannot capture one in the lambda below.
  const std::pair<std::string, std::string> parts = split_prefix(prefix);
  const std::string& dir = parts.first;
  const std::string& stem = parts.second;
  const auto name = [&](std::uint32_t share, const char* extension) {
    return part_file_name(stem, share, part.shares, extension);
  };
  if (formats.triangle) {
    outputs.add_file(dir + name(part.share, ".node"), part_node_pieces(part, formats.first_index, threads));
    outputs.add_file(dir + name(part.share, ".ele"), part_ele_pieces(part, formats.first_index, threads));
  }
  if (formats.vtu) {
    const detail::VtuGlobalIds global{&part.point_ids, &part.point_owner, &part.triangle_ids, part.share};
    outputs.add_file(dir + name(part.share, ".vtu"),
                     detail::vtu_pieces(part.mesh, detail::has_region_attributes(part), global, threads));
    if (part.share == 0) {
      std::vector<std::string> pieces;
      for (std::uint32_t r = 0; r < part.shares; ++r) pieces.push_back(name(r, ".vtu"));
      outputs.add_file(prefix + ".pvtu", format_parts_pvtu(pieces, detail::has_region_attributes(part)));
    }
  }
}

}  // namespace madd
