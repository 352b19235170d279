// The mesh as an SMS .2dm (include/madd/model_output.hpp). Cards from SMS's
// "2D Mesh Files *.2dm" (xmswiki.com/wiki/SMS:2D_Mesh_Files_*.2dm):
// MESH2D ("must be the first line of the file"); NUM_MATERIALS_PER_ELEM
// (required since SMS 11); MESHNAME; "ND id x y z" ("the x, y, and z
// coordinates of the point": z is the vertical coordinate, positive up, so
// an elevation, and a depth d below the datum is written as z = -d, the way
// SMS's ADCIRC interface shows bathymetry); "E3T id n1 n2 n3 matid" (matid
// positive: subdomain + 1); "NS id1 id2 ..." nodestrings, at most 10 ids a
// card, the last id of a nodestring negative.
#include <string>
#include <vector>

#include "madd/error.hpp"
#include "madd/model_output.hpp"
#include "output/model_text.hpp"

namespace madd {

namespace {

using detail::line;

constexpr std::size_t ids_per_ns_card = 10;

std::string nodestring_text(const std::vector<ModelBoundary>& lists) {
  std::string out;
  std::size_t bytes = 0;
  for (const ModelBoundary& list : lists) bytes += 12 * list.nodes.size() + 8;
  out.reserve(bytes);
  for (const ModelBoundary& list : lists) {
    const std::size_t n = list.nodes.size();
    for (std::size_t j = 0; j < n; ++j) {
      out += j % ids_per_ns_card == 0 ? "NS " : " ";
      const std::int64_t id = std::int64_t{list.nodes[j]} + 1;
      detail::append_int(out, j + 1 == n ? -id : id);
      if (j + 1 == n || (j + 1) % ids_per_ns_card == 0) out += '\n';
    }
  }
  return out;
}

template <typename Handle>
detail::SectionedText sms_text(Handle handle, const ModelGrid& grid) {
  const auto& mesh = *handle;
  const detail::ModelColumns columns = detail::model_columns(mesh.points.size(), grid);
  if (grid.title.find('"') != std::string::npos)
    throw OptionError("title", "must not hold '\"' in a .2dm (its MESHNAME card quotes it)");
  detail::SectionedText text;
  text.text() += "MESH2D\nNUM_MATERIALS_PER_ELEM 1\n";
  if (!grid.title.empty()) text.text() += "MESHNAME \"" + grid.title + "\"\n";
  text.lines(mesh.points.size(), [handle, columns](std::string& out, std::size_t v) {
    const Point p = columns.xy_at(*handle, v);
    out += "ND ";
    detail::append_int(out, static_cast<std::int64_t>(v + 1));
    for (const double value : {p.x, p.y, 0.0 - columns.depth_at(v)}) {  // 0 - d: no "-0" for a depth of 0
      out += ' ';
      detail::put_real(out, value);
    }
    out += '\n';
  });
  text.lines(mesh.triangles.size(), [handle](std::string& out, std::size_t t) {
    const std::array<std::uint32_t, 3> c = handle->triangles[t];
    const std::uint32_t k = t < handle->triangle_subdomain.size() ? handle->triangle_subdomain[t] : 0;
    out += "E3T ";
    line(out, t + 1, std::int64_t{c[0]} + 1, std::int64_t{c[1]} + 1, std::int64_t{c[2]} + 1, std::int64_t{k} + 1);
  });
  text.text() += nodestring_text(model_boundaries(mesh, grid.open_marker));
  return text;
}

}  // namespace

std::string format_2dm(const Mesh& mesh, const ModelGrid& grid) {
  return detail::joined(sms_text(detail::model_mesh(mesh), grid).pieces(1));
}

void add_2dm(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid, unsigned threads) {
  outputs.add_file(path, sms_text(detail::model_mesh(mesh), grid).pieces(threads));
}

void add_2dm(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
             unsigned threads) {
  outputs.add_file(path, sms_text(detail::model_mesh(mesh), grid).pieces(threads));
}

}  // namespace madd
