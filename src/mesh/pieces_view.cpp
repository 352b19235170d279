// A mesh in pieces read as the merged Mesh (mesh/pieces_view.hpp).
#include "mesh/pieces_view.hpp"

#include <algorithm>

#include "kernel/threads.hpp"
#include "madd/predicates.hpp"
#include "quality/mesh_angle.hpp"

namespace madd::detail {

Point PiecesView::point_at(const MeshPiecesData& m, std::size_t v) {
  const auto g = static_cast<std::uint32_t>(v);
  if (g < m.decomposition.points.size()) return m.decomposition.points[g];
  const std::uint32_t k = m.subdomain_of_point(g);
  return m.pieces[k].points[g - m.first_point[k] + m.local[k].to_global.size()];
}

std::array<std::uint32_t, 3> PiecesView::triangle_at(const MeshPiecesData& m, std::size_t t) {
  const std::uint32_t k = m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  const auto& c = m.pieces[k].triangles[t - m.first_triangle[k]];
  return {m.global_point(k, c[0]), m.global_point(k, c[1]), m.global_point(k, c[2])};
}

std::array<std::uint32_t, 3> PiecesView::neighbours_at(const MeshPiecesData& m, std::size_t t) {
  const std::uint32_t k = m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  const auto local = static_cast<std::uint32_t>(t - m.first_triangle[k]);
  return {m.global_neighbour(k, local, 0), m.global_neighbour(k, local, 1), m.global_neighbour(k, local, 2)};
}

// As join() copies it: a piece's attributes when it has one per triangle, else 0.
double PiecesView::attribute_at(const MeshPiecesData& m, std::size_t t) {
  const std::uint32_t k = m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  const SubdomainMesh& p = m.pieces[k];
  return p.triangle_attribute.size() == p.triangles.size() ? p.triangle_attribute[t - m.first_triangle[k]] : 0.0;
}

std::uint32_t triangle_at(const PiecesView& view, Point p, unsigned threads) {
  const MeshPiecesData& m = view.data();
  std::vector<std::uint32_t> found(m.pieces.size(), no_index);
  for_each_on_threads(m.pieces.size(), threads, [&](std::size_t k) {
    const SubdomainMesh& piece = m.pieces[k];
    for (std::uint32_t t = 0; t < piece.triangles.size(); ++t) {
      const auto& c = piece.triangles[t];
      const Point a = piece.points[c[0]], b = piece.points[c[1]], q = piece.points[c[2]];
      if (p.x < std::min({a.x, b.x, q.x}) || p.x > std::max({a.x, b.x, q.x}) || p.y < std::min({a.y, b.y, q.y}) ||
          p.y > std::max({a.y, b.y, q.y}))
        continue;
      if (orient2d(a, b, p) >= 0 && orient2d(b, q, p) >= 0 && orient2d(q, a, p) >= 0) {
        found[k] = m.first_triangle[k] + t;
        return;
      }
    }
  });
  for (const std::uint32_t t : found)
    if (t != no_index) return t;
  return no_index;
}

double angle_of(const PiecesView& view, std::size_t t) {
  const MeshPiecesData& m = view.data();
  const std::uint32_t k = m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  const SubdomainMesh& p = m.pieces[k];
  const auto& c = p.triangles[t - m.first_triangle[k]];
  return smallest_angle_deg(p.points[c[0]], p.points[c[1]], p.points[c[2]]);
}

}  // namespace madd::detail
