// mesh_metrics of a mesh kept in pieces (include/madd/mesh_metrics.hpp): the
// merged mesh's figures, read through PiecesView.
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_pieces.hpp"
#include "mesh/pieces_view.hpp"
#include "quality/mesh_figures.hpp"

namespace madd {

double detail::angle_of(const PiecesView& view, std::size_t t) {
  const MeshPiecesData& m = view.data();
  const std::uint32_t k = m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  const SubdomainMesh& p = m.pieces[k];
  const auto& c = p.triangles[t - m.first_triangle[k]];
  return smallest_angle_deg(p.points[c[0]], p.points[c[1]], p.points[c[2]]);
}

MeshMetrics mesh_metrics(const MeshPieces& mesh, const MeshSizeOptions& size, unsigned threads) {
  return detail::mesh_figures(detail::PiecesView(mesh.data()), size, threads);
}

}  // namespace madd
