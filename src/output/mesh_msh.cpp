// The merged mesh as gmsh's MSH 4.1 ASCII (include/madd/mesh_output.hpp).
// MSH 4 attaches physical groups to entities, so the file carries a small
// discrete model: one surface per subdomain and one curve per boundary
// marker. A curve per decomposition piece would be the finer model, but the
// pieces of a discretised decomposition are about one mesh edge each, and the
// $Entities section would then be as long as the boundary; solvers only ask
// which marker an edge has.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh_output.hpp"
#include "output/mesh_text.hpp"

namespace madd {
namespace {

using detail::line;

// A domain-boundary edge, oriented as its triangle runs it (the domain on
// its left), and the index of its curve.
struct BoundaryEdge {
  std::uint32_t a = 0, b = 0;
  std::uint32_t triangle = 0;
  std::size_t curve = 0;
};

struct Box {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  void add(Point p) {
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
};

// The model behind the mesh: its boundary edges grouped by marker.
struct Model {
  std::vector<int> markers;                              // curve c holds the edges of markers[c], increasing
  std::vector<BoundaryEdge> edges;                       // by curve, then in triangle order
  std::vector<std::vector<std::size_t>> surface_curves;  // the curves each subdomain touches
};

// Interior-segment edges (two triangles of one subdomain, on a piece of an
// input segment) join the curve of their marker too, once each, as the
// lower-numbered of their triangles runs them.
template <typename AnyMesh>
Model boundary_model(const AnyMesh& mesh) {
  const auto segment_markers = detail::segment_markers(mesh.segments);
  const std::vector<std::uint32_t> owner = interior_segment_owners(mesh.decomposition);
  std::unordered_map<std::uint64_t, int> interior;
  for (const MeshSegment& s : mesh.segments)
    if (s.piece < owner.size() && owner[s.piece] != no_index) interior.emplace(detail::edge_key(s.a, s.b), s.marker);
  Model model;
  std::vector<int> edge_marker;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t across = mesh.neighbours[t][i];
      const std::uint32_t a = mesh.triangles[t][(i + 1) % 3], b = mesh.triangles[t][(i + 2) % 3];
      if (across == no_index) {
        model.edges.push_back({a, b, t, 0});
        edge_marker.push_back(detail::boundary_marker(segment_markers, a, b));
        continue;
      }
      if (across < t || interior.empty()) continue;
      const auto it = interior.find(detail::edge_key(a, b));
      if (it == interior.end()) continue;
      model.edges.push_back({a, b, t, 0});
      edge_marker.push_back(it->second);
    }
  }
  model.markers = edge_marker;
  std::sort(model.markers.begin(), model.markers.end());
  model.markers.erase(std::unique(model.markers.begin(), model.markers.end()), model.markers.end());
  for (std::size_t e = 0; e < model.edges.size(); ++e)
    model.edges[e].curve = static_cast<std::size_t>(
        std::lower_bound(model.markers.begin(), model.markers.end(), edge_marker[e]) - model.markers.begin());
  std::stable_sort(model.edges.begin(), model.edges.end(),
                   [](const BoundaryEdge& x, const BoundaryEdge& y) { return x.curve < y.curve; });
  model.surface_curves.resize(mesh.subdomain_count());
  for (const BoundaryEdge& e : model.edges)
    model.surface_curves[mesh.triangle_subdomain[e.triangle]].push_back(e.curve);
  for (auto& curves : model.surface_curves) {
    std::sort(curves.begin(), curves.end());
    curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  }
  return model;
}

// gmsh needs positive physical tags: a marker m > 0 keeps m, the others (in
// increasing order) take the tags after the largest positive marker.
std::vector<std::int64_t> physical_curve_tags(const std::vector<int>& markers) {
  std::int64_t next = 1;
  for (const int m : markers) next = std::max(next, std::int64_t{m} + 1);
  std::vector<std::int64_t> tags;
  for (const int m : markers) tags.push_back(m > 0 ? std::int64_t{m} : next++);
  return tags;
}

template <typename AnyMesh>
void append_physical_names(std::string& out, const AnyMesh& mesh, const Model& model) {
  const std::vector<std::int64_t> tags = physical_curve_tags(model.markers);
  out += "$PhysicalNames\n";
  line(out, model.markers.size() + mesh.subdomain_count());
  for (std::size_t c = 0; c < model.markers.size(); ++c)
    out += "1 " + std::to_string(tags[c]) + " \"boundary_" + std::to_string(model.markers[c]) + "\"\n";
  for (std::uint32_t k = 0; k < mesh.subdomain_count(); ++k)
    out += "2 " + std::to_string(k + 1) + " \"subdomain_" + std::to_string(k) + "\"\n";
  out += "$EndPhysicalNames\n";
}

void append_box(std::string& out, const Box& box) {
  for (const double v : {box.min_x, box.min_y, 0.0, box.max_x, box.max_y, 0.0}) {
    detail::put(out, v);
    out += ' ';
  }
}

template <typename AnyMesh>
void append_entities(std::string& out, const AnyMesh& mesh, const Model& model) {
  const std::vector<std::int64_t> tags = physical_curve_tags(model.markers);
  std::vector<Box> curve_box(model.markers.size()), surface_box(mesh.subdomain_count());
  for (const BoundaryEdge& e : model.edges) {
    curve_box[e.curve].add(mesh.points[e.a]);
    curve_box[e.curve].add(mesh.points[e.b]);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t]) surface_box[mesh.triangle_subdomain[t]].add(mesh.points[v]);
  out += "$Entities\n";
  line(out, 0, model.markers.size(), mesh.subdomain_count(), 0);
  for (std::size_t c = 0; c < model.markers.size(); ++c) {
    // tag, box, one physical tag, no bounding points (no point entities)
    out += std::to_string(c + 1) + ' ';
    append_box(out, curve_box[c]);
    line(out, 1, tags[c], 0);
  }
  for (std::uint32_t k = 0; k < mesh.subdomain_count(); ++k) {
    // Every edge of a curve has the domain on its left: each bounding curve is
    // run in its own direction (+).
    out += std::to_string(k + 1) + ' ';
    append_box(out, surface_box[k]);
    out += "1 " + std::to_string(k + 1) + ' ' + std::to_string(model.surface_curves[k].size());
    for (const std::size_t c : model.surface_curves[k]) out += ' ' + std::to_string(c + 1);
    out += '\n';
  }
  out += "$EndEntities\n";
}

// Each node once, on the entity it lies on: the curve of its largest marker
// on the domain boundary, else the surface of the lowest subdomain using it.
// A node shared by two surfaces (a separator's) is used by the other one's
// triangles too; MSH 4.1 numbers nodes globally, so that is allowed.
template <typename AnyMesh>
void append_nodes(std::string& out, const AnyMesh& mesh, const Model& model) {
  const std::size_t curves = model.markers.size();
  constexpr std::size_t unset = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> entity(mesh.points.size(), unset);  // c < curves, or curves + k for surface k
  for (const BoundaryEdge& e : model.edges)
    for (const std::uint32_t v : {e.a, e.b})
      if (entity[v] == unset || entity[v] < e.curve) entity[v] = e.curve;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const std::uint32_t v : mesh.triangles[t])
      if (entity[v] == unset) entity[v] = curves + mesh.triangle_subdomain[t];
  for (std::size_t& e : entity)
    if (e == unset) e = curves;  // a point no triangle uses (not in a valid mesh): on surface 1
  std::vector<std::vector<std::uint32_t>> members(curves + mesh.subdomain_count());
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
    if (entity[v] < members.size()) members[entity[v]].push_back(v);
  std::size_t blocks = 0;
  for (const auto& m : members) blocks += m.empty() ? 0 : 1;
  out += "$Nodes\n";
  line(out, blocks, mesh.points.size(), mesh.points.empty() ? 0 : 1, mesh.points.size());
  for (std::size_t e = 0; e < members.size(); ++e) {
    if (members[e].empty()) continue;
    const bool on_curve = e < curves;
    line(out, on_curve ? 1 : 2, on_curve ? e + 1 : e - curves + 1, 0, members[e].size());
    for (const std::uint32_t v : members[e]) line(out, std::int64_t{v} + 1);
    for (const std::uint32_t v : members[e]) line(out, mesh.points[v].x, mesh.points[v].y, 0.0);
  }
  out += "$EndNodes\n";
}

// Triangles first, so that triangle t has tag t + 1 as in PREFIX.ele; then
// the boundary lines, curve by curve.
template <typename AnyMesh>
void append_elements(std::string& out, const AnyMesh& mesh, const Model& model) {
  const std::uint32_t n = mesh.subdomain_count();
  std::size_t blocks = 0;
  for (std::uint32_t k = 0; k < n; ++k)
    blocks += mesh.subdomain_first_triangle[k + 1] > mesh.subdomain_first_triangle[k] ? 1 : 0;
  std::vector<std::size_t> curve_size(model.markers.size(), 0);
  for (const BoundaryEdge& e : model.edges) ++curve_size[e.curve];
  for (const std::size_t s : curve_size) blocks += s > 0 ? 1 : 0;
  const std::size_t total = mesh.triangles.size() + model.edges.size();
  out += "$Elements\n";
  line(out, blocks, total, total == 0 ? 0 : 1, total);
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t first = mesh.subdomain_first_triangle[k], end = mesh.subdomain_first_triangle[k + 1];
    if (end == first) continue;
    line(out, 2, k + 1, 2, end - first);
    for (std::uint32_t t = first; t < end; ++t) {
      const auto& tri = mesh.triangles[t];
      line(out, std::int64_t{t} + 1, std::int64_t{tri[0]} + 1, std::int64_t{tri[1]} + 1, std::int64_t{tri[2]} + 1);
    }
  }
  std::size_t tag = mesh.triangles.size();
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const BoundaryEdge& edge = model.edges[e];
    if (e == 0 || model.edges[e - 1].curve != edge.curve) line(out, 1, edge.curve + 1, 1, curve_size[edge.curve]);
    line(out, ++tag, std::int64_t{edge.a} + 1, std::int64_t{edge.b} + 1);
  }
  out += "$EndElements\n";
}

// With regions (Triangle's -A): the region attribute of every triangle as
// one element data view, "region_attribute" (time 0, step 0, one component).
template <typename AnyMesh>
void append_region_attributes(std::string& out, const AnyMesh& mesh) {
  if (!detail::has_region_attributes(mesh)) return;
  out += "$ElementData\n1\n\"region_attribute\"\n1\n0\n3\n0\n1\n";
  line(out, mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    line(out, std::int64_t(t) + 1, detail::region_attribute(mesh, t));
  out += "$EndElementData\n";
}

template <typename AnyMesh>
std::string msh_text(const AnyMesh& mesh) {
  const Model model = boundary_model(mesh);
  std::string out;
  out.reserve(64 * mesh.points.size() + 48 * (mesh.triangles.size() + model.edges.size()) + 1024);
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  append_physical_names(out, mesh, model);
  append_entities(out, mesh, model);
  append_nodes(out, mesh, model);
  append_elements(out, mesh, model);
  append_region_attributes(out, mesh);
  return out;
}

}  // namespace

std::string format_mesh_msh(const Mesh& mesh) { return msh_text(mesh); }

std::string detail::format_mesh_msh(const MeshPiecesData& mesh) { return msh_text(PiecesView(mesh)); }

}  // namespace madd
