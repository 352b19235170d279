// mesh_metrics of a mesh kept in pieces (include/madd/mesh_metrics.hpp): the
// merged mesh's figures, read through PiecesView.
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_pieces.hpp"
#include "mesh/pieces_view.hpp"
#include "quality/mesh_figures.hpp"

namespace madd {

MeshMetrics mesh_metrics(const MeshPieces& mesh, const MeshSizeOptions& size, unsigned threads) {
  return detail::mesh_figures(detail::PiecesView(mesh.data()), size, threads);
}

}  // namespace madd
