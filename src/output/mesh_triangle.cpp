// The merged mesh in Triangle's formats (.node, .ele, .neigh, .edge), and one
// subdomain's piece of it (include/madd/mesh_output.hpp). The layouts are
// Triangle 1.6's, so triangle -r, showme and every reader of Triangle's
// output take them.
#include <algorithm>
#include <array>
#include <memory>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/error.hpp"
#include "madd/mesh_output.hpp"
#include "output/mesh_text.hpp"

namespace madd {

namespace detail {

void check_first_index(unsigned first_index) {
  if (first_index > 1) throw OptionError("first_index", "must be 0 or 1 (the id of the first point and triangle)");
}

std::unordered_map<std::uint64_t, int> segment_markers(const std::vector<MeshSegment>& segments) {
  std::unordered_map<std::uint64_t, int> markers;
  markers.reserve(segments.size());
  for (const MeshSegment& s : segments) markers[edge_key(s.a, s.b)] = s.marker;
  return markers;
}

int boundary_marker(const std::unordered_map<std::uint64_t, int>& markers, std::uint32_t a, std::uint32_t b) {
  const auto it = markers.find(edge_key(a, b));
  return it == markers.end() ? 1 : it->second;
}

}  // namespace detail

namespace {

using detail::line;

// Lines of "id v0 v1 v2 k" per triangle, vertices through `id_of`, then
// the region attribute of triangle `t` when the mesh has them.
template <typename IdOf, typename AnyMesh>
void append_triangle_line(std::string& out, std::int64_t id, const std::array<std::uint32_t, 3>& t, IdOf id_of,
                          std::uint32_t subdomain, const AnyMesh& mesh, std::size_t triangle) {
  if (!detail::has_region_attributes(mesh)) line(out, id, id_of(t[0]), id_of(t[1]), id_of(t[2]), subdomain);
  else line(out, id, id_of(t[0]), id_of(t[1]), id_of(t[2]), subdomain, detail::region_attribute(mesh, triangle));
}

// The .ele attribute count: the subdomain, and the region attribute with regions.
template <typename AnyMesh>
int ele_attributes(const AnyMesh& mesh) {
  return detail::has_region_attributes(mesh) ? 2 : 1;
}

}  // namespace

namespace detail {

// `handle`: a pointer to the mesh or its view, copied into the pieces'
// functions (so a view made here lives as long as they do).
template <typename Handle>
FilePieces mesh_node_pieces_of(Handle handle, unsigned first_index, unsigned threads) {
  check_first_index(first_index);
  const std::size_t n = handle->points.size();
  return line_pieces(
      n, 48, [n](std::string& out) { line(out, n, 2, 0, 1); },
      [handle, first_index](std::string& out, std::size_t v) {
        const auto& mesh = *handle;
        const int marker = v < mesh.point_markers.size() ? mesh.point_markers[v] : 0;
        const Point p = mesh.points[v];
        line(out, v + first_index, p.x, p.y, marker);
      },
      threads);
}

template <typename Handle>
FilePieces mesh_ele_pieces_of(Handle handle, unsigned first_index, unsigned threads) {
  check_first_index(first_index);
  const std::size_t n = handle->triangles.size();
  return line_pieces(
      n, 40, [handle, n](std::string& out) { line(out, n, 3, ele_attributes(*handle)); },
      [handle, first_index](std::string& out, std::size_t t) {
        const auto& mesh = *handle;
        const auto id_of = [first_index](std::uint32_t v) { return std::int64_t{v} + first_index; };
        append_triangle_line(out, static_cast<std::int64_t>(t + first_index), mesh.triangles[t], id_of,
                             mesh.triangle_subdomain[t], mesh, t);
      },
      threads);
}

template <typename Handle>
FilePieces mesh_neigh_pieces_of(Handle handle, unsigned first_index, unsigned threads) {
  check_first_index(first_index);
  const std::size_t n = handle->neighbours.size();
  return line_pieces(
      n, 36, [n](std::string& out) { line(out, n, 3); },
      [handle, first_index](std::string& out, std::size_t t) {
        const auto id_of = [first_index](std::uint32_t u) {
          return u == no_index ? -1 : std::int64_t{u} + first_index;
        };
        const std::array<std::uint32_t, 3> u = handle->neighbours[t];
        line(out, t + first_index, id_of(u[0]), id_of(u[1]), id_of(u[2]));
      },
      threads);
}

FilePieces mesh_node_pieces(const Mesh& mesh, unsigned first_index, unsigned threads) {
  return mesh_node_pieces_of(&mesh, first_index, threads);
}
FilePieces mesh_ele_pieces(const Mesh& mesh, unsigned first_index, unsigned threads) {
  return mesh_ele_pieces_of(&mesh, first_index, threads);
}
FilePieces mesh_neigh_pieces(const Mesh& mesh, unsigned first_index, unsigned threads) {
  return mesh_neigh_pieces_of(&mesh, first_index, threads);
}
// The pieces' view lives in the FilePieces' functions (it holds only
// references to the pieces, which outlive the write).
FilePieces mesh_node_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads) {
  return mesh_node_pieces_of(std::make_shared<const PiecesView>(mesh), first_index, threads);
}
FilePieces mesh_ele_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads) {
  return mesh_ele_pieces_of(std::make_shared<const PiecesView>(mesh), first_index, threads);
}
FilePieces mesh_neigh_pieces(const MeshPiecesData& mesh, unsigned first_index, unsigned threads) {
  return mesh_neigh_pieces_of(std::make_shared<const PiecesView>(mesh), first_index, threads);
}

}  // namespace detail

std::string format_mesh_node(const Mesh& mesh, unsigned first_index) {
  return detail::joined(detail::mesh_node_pieces(mesh, first_index, 1));
}

std::string format_mesh_ele(const Mesh& mesh, unsigned first_index) {
  return detail::joined(detail::mesh_ele_pieces(mesh, first_index, 1));
}

std::string format_mesh_neigh(const Mesh& mesh, unsigned first_index) {
  return detail::joined(detail::mesh_neigh_pieces(mesh, first_index, 1));
}

// Each edge once, from the lower-numbered of its two triangles (or its only
// one), as cmd_triangulate writes it: the count is only known at the end.
namespace {

template <typename AnyMesh>
std::string edge_text(const AnyMesh& mesh, unsigned first_index) {
  detail::check_first_index(first_index);
  const auto markers = detail::segment_markers(mesh.segments);
  std::string body;
  body.reserve(30 * 3 * mesh.triangles.size() / 2 + 32);
  std::int64_t count = 0;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::array<std::uint32_t, 3> neighbours = mesh.neighbours[t], corners = mesh.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t across = neighbours[static_cast<std::size_t>(i)];
      if (across != no_index && across < t) continue;
      const std::uint32_t a = corners[static_cast<std::size_t>((i + 1) % 3)];
      const std::uint32_t b = corners[static_cast<std::size_t>((i + 2) % 3)];
      // An edge inside the domain: an interior segment's marker, else 0 (separators too).
      const auto inside = across == no_index ? markers.end() : markers.find(detail::edge_key(a, b));
      const int marker = across == no_index        ? detail::boundary_marker(markers, a, b)
                         : inside == markers.end() ? 0
                                                   : inside->second;
      line(body, count + first_index, std::int64_t{a} + first_index, std::int64_t{b} + first_index, marker);
      ++count;
    }
  }
  std::string out;
  line(out, count, 1);
  return out + body;
}

}  // namespace

std::string format_mesh_edge(const Mesh& mesh, unsigned first_index) { return edge_text(mesh, first_index); }

namespace detail {

std::string format_mesh_edge(const MeshPiecesData& mesh, unsigned first_index) {
  return edge_text(PiecesView(mesh), first_index);
}

}  // namespace detail

namespace {

// The global vertices of subdomain k's triangles, in increasing index: its
// piece's local numbering (local id = position + first_index).
template <typename AnyMesh>
std::vector<std::uint32_t> subdomain_vertices(const AnyMesh& mesh, std::uint32_t k) {
  std::vector<std::uint32_t> vertices;
  for (std::uint32_t t = mesh.subdomain_first_triangle.at(k); t < mesh.subdomain_first_triangle.at(k + 1); ++t) {
    const std::array<std::uint32_t, 3> corners = mesh.triangles[t];
    vertices.insert(vertices.end(), corners.begin(), corners.end());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

template <typename AnyMesh>
std::string subdomain_node_text(const AnyMesh& mesh, std::uint32_t k, unsigned first_index) {
  detail::check_first_index(first_index);
  const std::vector<std::uint32_t> vertices = subdomain_vertices(mesh, k);
  std::string out;
  out.reserve(56 * vertices.size() + 32);
  line(out, vertices.size(), 2, 1, 1);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const std::uint32_t g = vertices[i];
    const int marker = g < mesh.point_markers.size() ? mesh.point_markers[g] : 0;
    const Point p = mesh.points[g];
    line(out, i + first_index, p.x, p.y, std::int64_t{g} + first_index, marker);
  }
  return out;
}

template <typename AnyMesh>
std::string subdomain_ele_text(const AnyMesh& mesh, std::uint32_t k, unsigned first_index) {
  detail::check_first_index(first_index);
  const std::vector<std::uint32_t> vertices = subdomain_vertices(mesh, k);
  const auto id_of = [&](std::uint32_t g) {
    const auto at = std::lower_bound(vertices.begin(), vertices.end(), g) - vertices.begin();
    return static_cast<std::int64_t>(at) + first_index;
  };
  const std::uint32_t first = mesh.subdomain_first_triangle[k], end = mesh.subdomain_first_triangle[k + 1];
  std::string out;
  out.reserve(40 * (end - first) + 32);
  line(out, end - first, 3, ele_attributes(mesh));
  for (std::uint32_t t = first; t < end; ++t)
    append_triangle_line(out, std::int64_t{t - first} + first_index, mesh.triangles[t], id_of, k, mesh, t);
  return out;
}

}  // namespace

std::string format_subdomain_mesh_node(const Mesh& mesh, std::uint32_t k, unsigned first_index) {
  return subdomain_node_text(mesh, k, first_index);
}
std::string format_subdomain_mesh_ele(const Mesh& mesh, std::uint32_t k, unsigned first_index) {
  return subdomain_ele_text(mesh, k, first_index);
}

namespace detail {

std::string format_subdomain_mesh_node(const MeshPiecesData& mesh, std::uint32_t k, unsigned first_index) {
  return subdomain_node_text(PiecesView(mesh), k, first_index);
}
std::string format_subdomain_mesh_ele(const MeshPiecesData& mesh, std::uint32_t k, unsigned first_index) {
  return subdomain_ele_text(PiecesView(mesh), k, first_index);
}

}  // namespace detail

}  // namespace madd
