// The merged mesh as a VTK XML UnstructuredGrid (include/madd/mesh_output.hpp),
// ASCII so it diffs and greps; ParaView reads it as it is. Connectivity and
// offsets are Int64: a mesh of more than 2^31 / 3 triangles overflows Int32.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

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

// One data array of `count` lines, body(out, i) appending line i.
void add_array(detail::SectionedText& text, const char* type, const char* name, std::size_t count,
               detail::SectionedText::Body body, int components = 1, bool id_type = false) {
  open_array(text.text(), type, name, components, id_type);
  text.lines(count, std::move(body));
  close_array(text.text());
}

// The points' and cells' data arrays: a part's global ids first (they are
// the GlobalIds attribute ParaView joins the pieces of a .pvtu by).
template <typename AnyMesh>
void add_point_data(detail::SectionedText& text, const AnyMesh& mesh, const detail::VtuGlobalIds* global) {
  const std::size_t n = mesh.points.size();
  text.text() += global ? "      <PointData Scalars=\"marker\" GlobalIds=\"global_id\">\n"
                        : "      <PointData Scalars=\"marker\">\n";
  if (global) {
    const auto& ids = *global->point_ids;
    const auto& owner = *global->point_owner;
    add_array(
        text, "Int64", "global_id", ids.size(), [&ids](std::string& out, std::size_t v) { line(out, ids[v]); }, 1,
        true);
    add_array(text, "Int32", "owner", owner.size(), [&owner](std::string& out, std::size_t v) { line(out, owner[v]); });
  }
  add_array(text, "Int32", "marker", n, [&mesh](std::string& out, std::size_t v) {
    line(out, v < mesh.point_markers.size() ? mesh.point_markers[v] : 0);
  });
  text.text() += "      </PointData>\n";
}

template <typename AnyMesh>
void add_cell_data(detail::SectionedText& text, const AnyMesh& mesh, bool regions, const detail::VtuGlobalIds* global) {
  const std::size_t t = mesh.triangles.size();
  text.text() += global ? "      <CellData Scalars=\"subdomain\" GlobalIds=\"global_id\">\n"
                        : "      <CellData Scalars=\"subdomain\">\n";
  if (global) {
    const auto& ids = *global->triangle_ids;
    const std::uint32_t rank = global->rank;
    add_array(
        text, "Int64", "global_id", ids.size(), [&ids](std::string& out, std::size_t c) { line(out, ids[c]); }, 1,
        true);
    add_array(text, "Int32", "rank", t, [rank](std::string& out, std::size_t) { line(out, rank); });
  }
  add_array(text, "Int32", "subdomain", mesh.triangle_subdomain.size(),
            [&mesh](std::string& out, std::size_t c) { line(out, mesh.triangle_subdomain[c]); });
  if (regions)  // with regions (Triangle's -A)
    add_array(text, "Float64", "region_attribute", t,
              [&mesh](std::string& out, std::size_t c) { line(out, detail::region_attribute(mesh, c)); });
  text.text() += "      </CellData>\n";
}

// A Mesh or a part's LocalMesh: the same fields.
template <typename AnyMesh>
detail::SectionedText vtu_text(const AnyMesh& mesh, bool regions, const detail::VtuGlobalIds* global) {
  const std::size_t n = mesh.points.size(), t = mesh.triangles.size();
  detail::SectionedText text;
  text.text() += "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <UnstructuredGrid>\n";
  text.text() +=
      "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(t) + "\">\n";
  add_point_data(text, mesh, global);
  add_cell_data(text, mesh, regions, global);
  text.text() += "      <Points>\n";
  add_array(
      text, "Float64", nullptr, n,
      [&mesh](std::string& out, std::size_t v) {
        const Point p = mesh.points[v];
        line(out, p.x, p.y, 0.0);
      },
      3);
  text.text() += "      </Points>\n      <Cells>\n";
  add_array(text, "Int64", "connectivity", t, [&mesh](std::string& out, std::size_t c) {
    const std::array<std::uint32_t, 3> corners = mesh.triangles[c];
    line(out, corners[0], corners[1], corners[2]);
  });
  add_array(text, "Int64", "offsets", t, [](std::string& out, std::size_t c) { line(out, 3 * (c + 1)); });
  add_array(text, "UInt8", "types", t, [](std::string& out, std::size_t) { out += "5\n"; });
  text.text() += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return text;
}

}  // namespace

namespace detail {

void SectionedText::lines(std::size_t count, Body body) {
  sections_.push_back({std::move(pending_), count, std::move(body)});
  pending_.clear();
}

// Piece list: for each section, its lines in runs of mesh_lines_per_piece
// (at least one piece, for its fixed text); the text after the last lines
// is a section of none.
FilePieces SectionedText::pieces(unsigned threads) {
  lines(0, {});
  struct Piece {
    std::size_t section, begin, end;
  };
  auto list = std::make_shared<std::vector<Piece>>();
  for (std::size_t s = 0; s < sections_.size(); ++s) {
    const std::size_t count = sections_[s].count;
    std::size_t begin = 0;
    do {
      const std::size_t end = std::min(count, begin + mesh_lines_per_piece);
      list->push_back({s, begin, end});
      begin = end;
    } while (begin < count);
  }
  auto sections = std::make_shared<const std::vector<Section>>(std::move(sections_));
  sections_.clear();
  return {list->size(),
          [list, sections](std::size_t i) {
            const Piece& p = (*list)[i];
            const Section& s = (*sections)[p.section];
            std::string out = p.begin == 0 ? s.before : std::string();
            out.reserve(out.size() + 48 * (p.end - p.begin));
            for (std::size_t k = p.begin; k < p.end; ++k) s.body(out, k);
            return out;
          },
          threads};
}

std::string format_vtu(const LocalMesh& mesh, bool regions, const VtuGlobalIds& global) {
  return joined(vtu_pieces(mesh, regions, global, 1));
}

FilePieces vtu_pieces(const LocalMesh& mesh, bool regions, const VtuGlobalIds& global, unsigned threads) {
  return vtu_text(mesh, regions, &global).pieces(threads);
}

FilePieces mesh_vtu_pieces(const Mesh& mesh, unsigned threads) {
  return vtu_text(mesh, has_region_attributes(mesh), nullptr).pieces(threads);
}

// The view the sections read is kept alive by the pieces' function.
FilePieces mesh_vtu_pieces(const MeshPiecesData& mesh, unsigned threads) {
  const auto view = std::make_shared<const PiecesView>(mesh);
  FilePieces pieces = vtu_text(*view, has_region_attributes(*view), nullptr).pieces(threads);
  pieces.make = [view, make = std::move(pieces.make)](std::size_t i) { return make(i); };
  return pieces;
}

}  // namespace detail

std::string format_mesh_vtu(const Mesh& mesh) { return detail::joined(detail::mesh_vtu_pieces(mesh, 1)); }

}  // namespace madd
