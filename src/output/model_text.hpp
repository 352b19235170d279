#pragma once
// What the model grid writers (src/output/mesh_fort14.cpp, mesh_gr3.cpp,
// mesh_2dm.cpp) share: the checked columns of a ModelGrid, fort.14's node and
// element lines (hgrid.gr3 has the same), the numbers' text, and the mesh
// they read: a Mesh, or the view of a mesh kept in pieces (the same bytes).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "kernel/number_format.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_pieces.hpp"
#include "madd/model_output.hpp"
#include "mesh/pieces_view.hpp"
#include "output/mesh_text.hpp"

namespace madd::detail {

// The columns a model file writes per mesh point: the grid's coordinates
// (or, when null, the mesh's points) and depths (or none: all 0).
struct ModelColumns {
  const std::vector<Point>* xy = nullptr;
  const std::vector<double>* depth = nullptr;
  template <typename AnyMesh>
  Point xy_at(const AnyMesh& mesh, std::size_t v) const {
    return xy != nullptr ? (*xy)[v] : mesh.points[v];
  }
  double depth_at(std::size_t v) const { return depth != nullptr ? (*depth)[v] : 0.0; }
};

// Checks `grid` against a mesh of `points` points: coordinates and depth
// empty or one per point, all finite; the title one line. Throws OptionError
// naming the field.
ModelColumns model_columns(std::size_t points, const ModelGrid& grid);

// The mesh a model file's lines read while it is written: the Mesh itself,
// or a view of the pieces kept alive by the lines' functions.
inline const Mesh* model_mesh(const Mesh& mesh) { return &mesh; }
inline std::shared_ptr<const PiecesView> model_mesh(const MeshPieces& mesh) {
  return std::make_shared<const PiecesView>(mesh.data());
}

// model_boundaries of the view (src/output/model_boundaries.cpp).
std::vector<ModelBoundary> model_boundaries(const PiecesView& mesh, int open_marker);

// A real as the shortest text that reads back as the same double (every
// model reads it exactly: Fortran list-directed input takes "1e-05").
inline void put_real(std::string& out, double v) { append_shortest(out, v); }

// The part fort.14 and hgrid.gr3 share (ADCIRC's "Fort.14: Grid and Boundary
// Information File": AGRID; NE, NP; per node JN, X, Y, DP; per element JE,
// NHY, NM(1..3); SCHISM's hgrid.gr3, its page input-output/hgrid, is the
// same: "# of elements and nodes", "node #, x, y, depth", "element #,
// element type, nodes"): the title line, "NE NP" (with a
// comment), NP lines "JN X Y DP" and NE lines "JE 3 N1 N2 N3", 1-based, the
// lines made by bodies that read the mesh through `handle` (model_mesh) and
// the columns' arrays.
template <typename Handle>
SectionedText grid_text(Handle handle, const ModelGrid& grid, const ModelColumns& columns) {
  SectionedText text;
  std::string& head = text.text();
  head += grid.title;
  head += '\n';
  line(head, handle->triangles.size(), handle->points.size());
  head.insert(head.size() - 1, " ! NE NP = number of elements and nodes");
  text.lines(handle->points.size(), [handle, columns](std::string& out, std::size_t v) {
    const Point p = columns.xy_at(*handle, v);
    append_int(out, static_cast<std::int64_t>(v + 1));
    out += ' ';
    put_real(out, p.x);
    out += ' ';
    put_real(out, p.y);
    out += ' ';
    put_real(out, columns.depth_at(v));
    out += '\n';
  });
  text.lines(handle->triangles.size(), [handle](std::string& out, std::size_t t) {
    const std::array<std::uint32_t, 3> c = handle->triangles[t];
    append_int(out, static_cast<std::int64_t>(t + 1));
    out += " 3 ";
    line(out, std::int64_t{c[0]} + 1, std::int64_t{c[1]} + 1, std::int64_t{c[2]} + 1);
  });
  return text;
}

}  // namespace madd::detail
