// The checked columns of a ModelGrid and the node and element lines that
// fort.14 and hgrid.gr3 share (src/output/model_text.hpp). ADCIRC's layout,
// "Fort.14: Grid and Boundary Information File": AGRID; NE, NP; per node
// JN, X, Y, DP; per element JE, NHY, NM(1..3). SCHISM's hgrid.gr3
// (SCHISM's page input-output/hgrid) is the same: "# of elements and nodes", then
// "node #, x, y, depth", then "element #, element type, nodes".
#include <cmath>
#include <string>

#include "madd/error.hpp"
#include "output/model_text.hpp"

namespace madd::detail {

namespace {

template <typename Value, typename Finite>
void check_column(const std::vector<Value>& column, std::size_t points, const char* field, Finite finite) {
  if (!column.empty() && column.size() != points)
    throw OptionError(field, "must be empty or hold one value per mesh point (" + std::to_string(points) + "), not " +
                                 std::to_string(column.size()));
  for (std::size_t v = 0; v < column.size(); ++v)
    if (!finite(column[v])) throw OptionError(field, "must be finite (point " + std::to_string(v) + " is not)");
}

}  // namespace

ModelColumns model_columns(const Mesh& mesh, const ModelGrid& grid) {
  check_column(grid.coordinates, mesh.points.size(), "coordinates",
               [](Point p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  check_column(grid.depth, mesh.points.size(), "depth", [](double d) { return std::isfinite(d); });
  if (grid.title.find_first_of("\r\n") != std::string::npos)
    throw OptionError("title", "must be one line (it is the file's first line)");
  ModelColumns columns;
  columns.xy = grid.coordinates.empty() ? &mesh.points : &grid.coordinates;
  if (!grid.depth.empty()) columns.depth = &grid.depth;
  return columns;
}

SectionedText grid_text(const Mesh& mesh, const ModelGrid& grid, const ModelColumns& columns) {
  SectionedText text;
  std::string& head = text.text();
  head += grid.title;
  head += '\n';
  line(head, mesh.triangles.size(), mesh.points.size());
  head.insert(head.size() - 1, " ! NE NP = number of elements and nodes");
  text.lines(mesh.points.size(), [columns](std::string& out, std::size_t v) {
    const Point p = (*columns.xy)[v];
    append_int(out, static_cast<std::int64_t>(v + 1));
    out += ' ';
    put_real(out, p.x);
    out += ' ';
    put_real(out, p.y);
    out += ' ';
    put_real(out, columns.depth_at(v));
    out += '\n';
  });
  text.lines(mesh.triangles.size(), [&mesh](std::string& out, std::size_t t) {
    const auto& c = mesh.triangles[t];
    append_int(out, static_cast<std::int64_t>(t + 1));
    out += " 3 ";
    line(out, std::int64_t{c[0]} + 1, std::int64_t{c[1]} + 1, std::int64_t{c[2]} + 1);
  });
  return text;
}

}  // namespace madd::detail
