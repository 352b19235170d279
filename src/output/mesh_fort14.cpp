// The mesh as ADCIRC's fort.14 (include/madd/model_output.hpp). Layout from
// "Fort.14: Grid and Boundary Information File"
// (adcirc.github.io/adcirc/technical_reference/input_files/fort14.html):
//   AGRID / NE, NP / NP x (JN, X, Y, DP) / NE x (JE, NHY, NM1, NM2, NM3) /
//   NOPE / NETA / per open boundary: NVDLL, IBTYPEE, then NVDLL x NBDV /
//   NBOU / NVEL / per flow boundary: NVELL, IBTYPE, then NVELL x NBVV
// (NBVV alone on its line for IBTYPE 0, 1, 2, 10, 11, 12, 20, 21, 22, 30).
// IBTYPE 20 and 21 are the flux table's external and internal zero normal
// flow boundaries with the natural implementation ("Flux specified
// boundaries", wiki.adcirc.org: types 20-25 preferred to 0-5, which "can
// introduce instabilities"). The v52 manual's notes: external boundaries
// before internal ones, islands and a boundary surrounding the domain closed
// by repeating the first node, unclosed ones starting where two meet:
// model_boundaries gives the lists in that order and form.
#include <string>
#include <vector>

#include "madd/model_output.hpp"
#include "output/model_text.hpp"

namespace madd {

namespace {

using detail::line;

void append_nodes(std::string& out, const std::vector<std::uint32_t>& nodes) {
  for (const std::uint32_t v : nodes) line(out, std::int64_t{v} + 1);
}

// A count line with its comment: "<values> ! <comment>".
template <typename... Values>
void count_line(std::string& out, const char* comment, Values... values) {
  line(out, values...);
  out.insert(out.size() - 1, std::string(" ! ") + comment);
}

std::string fort14_boundary_text(const std::vector<ModelBoundary>& lists) {
  std::size_t open = 0, open_nodes = 0, land_nodes = 0, bytes = 256;
  for (const ModelBoundary& list : lists) {
    if (list.kind == BoundaryKind::open) ++open, open_nodes += list.nodes.size();
    else land_nodes += list.nodes.size();
    bytes += 12 * list.nodes.size() + 80;
  }
  std::string out;
  out.reserve(bytes);
  count_line(out, "NOPE = number of open boundary segments", open);
  count_line(out, "NETA = total number of open boundary nodes", open_nodes);
  std::size_t k = 0;
  for (const ModelBoundary& list : lists) {
    if (list.kind != BoundaryKind::open) continue;
    const std::string comment = "NVDLL IBTYPEE = nodes and type of open boundary " + std::to_string(++k);
    count_line(out, comment.c_str(), list.nodes.size(), 0);
    append_nodes(out, list.nodes);
  }
  count_line(out, "NBOU = number of land boundary segments", lists.size() - open);
  count_line(out, "NVEL = total number of land boundary nodes", land_nodes);
  k = 0;
  for (const ModelBoundary& list : lists) {
    if (list.kind == BoundaryKind::open) continue;
    const bool island = list.kind == BoundaryKind::island;
    const std::string comment = "NVELL IBTYPE = nodes and type of land boundary " + std::to_string(++k) +
                                (island ? " (island)" : " (mainland)");
    count_line(out, comment.c_str(), list.nodes.size(), island ? 21 : 20);
    append_nodes(out, list.nodes);
  }
  return out;
}

template <typename Handle>
detail::SectionedText fort14_text(Handle handle, const ModelGrid& grid) {
  const detail::ModelColumns columns = detail::model_columns(handle->points.size(), grid);
  detail::SectionedText text = detail::grid_text(handle, grid, columns);
  text.text() += fort14_boundary_text(model_boundaries(*handle, grid.open_marker));
  return text;
}

}  // namespace

std::string format_fort14(const Mesh& mesh, const ModelGrid& grid) {
  return detail::joined(fort14_text(detail::model_mesh(mesh), grid).pieces(1));
}

void add_fort14(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid,
                unsigned threads) {
  outputs.add_file(path, fort14_text(detail::model_mesh(mesh), grid).pieces(threads));
}

void add_fort14(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
                unsigned threads) {
  outputs.add_file(path, fort14_text(detail::model_mesh(mesh), grid).pieces(threads));
}

}  // namespace madd
