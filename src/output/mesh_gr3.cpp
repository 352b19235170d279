// The mesh as SCHISM's hgrid.gr3, or hgrid.ll with lon/lat coordinates
// (include/madd/model_output.hpp). Layout from SCHISM's "Horizontal grid"
// (schism-dev.github.io/schism, its page input-output/hgrid): the fort.14
// node and element parts, then "3 = Number of open boundaries", "95 = Total
// number of open boundary nodes", per open boundary "3 = Number of nodes for
// open boundary 1" and its nodes, "16 = number of land boundaries
// (including islands)", "1743 = Total number of land boundary nodes", per
// land boundary "753 0 = Number of nodes for land boundary 1 ('0' means the
// exterior land boundary)" or "10 1 = Number of nodes for island boundary 1
// ('1' means island)", an island's last node "different from the first".
// Its note 2: with no open boundary, two land boundary segments linked to
// each other; with no land boundary, two open ones. hgrid.ll "is the same as
// hgrid.gr3" with lon/lat coordinates (its page input-output/optional-inputs).
#include <string>
#include <vector>

#include "madd/model_output.hpp"
#include "output/model_text.hpp"

namespace madd {

namespace {

using detail::line;

// One list as written: nodes [begin, begin + size) of a model list; flag
// -1 open, 0 exterior land, 1 island.
struct Gr3List {
  const std::uint32_t* begin = nullptr;
  std::size_t size = 0;
  int flag = -1;
};

// SCHISM's lists: an island without its repeated node; a closed loop of
// another kind as two lists sharing both ends (the halves of its m nodes).
std::vector<Gr3List> gr3_lists(const std::vector<ModelBoundary>& lists) {
  std::vector<Gr3List> out;
  for (const ModelBoundary& list : lists) {
    const int flag = list.kind == BoundaryKind::open ? -1 : list.kind == BoundaryKind::mainland ? 0 : 1;
    const std::uint32_t* nodes = list.nodes.data();
    if (!list.closed) {
      out.push_back({nodes, list.nodes.size(), flag});
    } else if (list.kind == BoundaryKind::island) {
      out.push_back({nodes, list.nodes.size() - 1, flag});
    } else {
      const std::size_t m = list.nodes.size() - 1, half = m / 2;
      out.push_back({nodes, half + 1, flag});
      out.push_back({nodes + half, m - half + 1, flag});
    }
  }
  return out;
}

template <typename... Values>
void count_line(std::string& out, const std::string& comment, Values... values) {
  line(out, values...);
  out.insert(out.size() - 1, " = " + comment);
}

std::string gr3_boundary_text(const std::vector<ModelBoundary>& model) {
  const std::vector<Gr3List> lists = gr3_lists(model);
  std::size_t open = 0, open_nodes = 0, land_nodes = 0, bytes = 256;
  for (const Gr3List& list : lists) {
    if (list.flag < 0) ++open, open_nodes += list.size;
    else land_nodes += list.size;
    bytes += 12 * list.size + 64;
  }
  std::string out;
  out.reserve(bytes);
  count_line(out, "Number of open boundaries", open);
  count_line(out, "Total number of open boundary nodes", open_nodes);
  std::size_t k = 0, land = 0, island = 0;
  for (const Gr3List& list : lists) {
    if (list.flag >= 0) continue;
    count_line(out, "Number of nodes for open boundary " + std::to_string(++k), list.size);
    for (std::size_t j = 0; j < list.size; ++j) line(out, std::int64_t{list.begin[j]} + 1);
  }
  count_line(out, "Number of land boundaries (including islands)", lists.size() - open);
  count_line(out, "Total number of land boundary nodes", land_nodes);
  for (const Gr3List& list : lists) {
    if (list.flag < 0) continue;
    const std::string comment = list.flag == 0 ? "Number of nodes for land boundary " + std::to_string(++land)
                                               : "Number of nodes for island boundary " + std::to_string(++island);
    count_line(out, comment, list.size, list.flag);
    for (std::size_t j = 0; j < list.size; ++j) line(out, std::int64_t{list.begin[j]} + 1);
  }
  return out;
}

template <typename Handle>
detail::SectionedText gr3_text(Handle handle, const ModelGrid& grid) {
  const detail::ModelColumns columns = detail::model_columns(handle->points.size(), grid);
  detail::SectionedText text = detail::grid_text(handle, grid, columns);
  text.text() += gr3_boundary_text(model_boundaries(*handle, grid.open_marker));
  return text;
}

}  // namespace

std::string format_gr3(const Mesh& mesh, const ModelGrid& grid) {
  return detail::joined(gr3_text(detail::model_mesh(mesh), grid).pieces(1));
}

void add_gr3(OutputSet& outputs, const std::string& path, const Mesh& mesh, const ModelGrid& grid, unsigned threads) {
  outputs.add_file(path, gr3_text(detail::model_mesh(mesh), grid).pieces(threads));
}

void add_gr3(OutputSet& outputs, const std::string& path, const MeshPieces& mesh, const ModelGrid& grid,
             unsigned threads) {
  outputs.add_file(path, gr3_text(detail::model_mesh(mesh), grid).pieces(threads));
}

}  // namespace madd
