#pragma once
// A mesh in pieces read as if it were the merged Mesh: the same field names,
// each element computed from its piece on access (its subdomain the one the
// reading thread found last, else found by binary search over the offsets:
// MeshPiecesData::subdomain_of_triangle), so that code written for a Mesh's fields
// (the file writers, the figures) reads the pieces unchanged and writes the
// same bytes. Read-only; the pieces must outlive it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "madd/mesh.hpp"
#include "mesh/mesh_pieces.hpp"

namespace madd::detail {

class PiecesView {
public:
  explicit PiecesView(const MeshPiecesData& m)
      : decomposition(m.decomposition), segments(m.segments), subdomain_first_triangle(m.first_triangle),
        shortfall(m.shortfall), min_triangle_angle_deg(m.min_triangle_angle_deg), points{&m},
        point_markers{&m}, triangles{&m}, neighbours{&m}, triangle_subdomain{&m}, triangle_attribute{&m}, data_(&m) {}

  // One array of the merged mesh: size() and an element by value.
  template <typename Element, Element (*at)(const MeshPiecesData&, std::size_t),
            std::size_t (*count)(const MeshPiecesData&)>
  struct Array {
    const MeshPiecesData* m;
    std::size_t size() const { return count(*m); }
    bool empty() const { return size() == 0; }
    Element operator[](std::size_t i) const { return at(*m, i); }
  };

  static std::size_t point_total(const MeshPiecesData& m) { return m.point_count(); }
  static std::size_t triangle_total(const MeshPiecesData& m) { return m.triangle_count(); }
  static std::size_t attribute_total(const MeshPiecesData& m) { return m.has_regions() ? m.triangle_count() : 0; }
  static Point point_at(const MeshPiecesData& m, std::size_t v);
  static int marker_at(const MeshPiecesData& m, std::size_t v) { return m.point_marker(static_cast<std::uint32_t>(v)); }
  static std::array<std::uint32_t, 3> triangle_at(const MeshPiecesData& m, std::size_t t);
  static std::array<std::uint32_t, 3> neighbours_at(const MeshPiecesData& m, std::size_t t);
  static std::uint32_t subdomain_at(const MeshPiecesData& m, std::size_t t) {
    return m.subdomain_of_triangle(static_cast<std::uint32_t>(t));
  }
  static double attribute_at(const MeshPiecesData& m, std::size_t t);

  const Decomposition& decomposition;
  const std::vector<MeshSegment>& segments;
  const std::vector<std::uint32_t>& subdomain_first_triangle;
  const MeshShortfall& shortfall;
  const double& min_triangle_angle_deg;
  Array<Point, point_at, point_total> points;
  Array<int, marker_at, point_total> point_markers;
  Array<std::array<std::uint32_t, 3>, triangle_at, triangle_total> triangles;
  Array<std::array<std::uint32_t, 3>, neighbours_at, triangle_total> neighbours;
  Array<std::uint32_t, subdomain_at, triangle_total> triangle_subdomain;
  Array<double, attribute_at, attribute_total> triangle_attribute;

  std::size_t triangle_count() const noexcept { return data_->triangle_count(); }
  std::uint32_t subdomain_count() const noexcept { return data_->subdomain_count(); }
  const MeshPiecesData& data() const noexcept { return *data_; }

private:
  const MeshPiecesData* data_;
};

// Triangle t's smallest angle, from its piece's own coordinates (those of
// its decomposition points are the decomposition's, bit for bit): what the
// figures (quality/mesh_figures.hpp) read for every triangle, without
// mapping its corners to global ids first.
double angle_of(const PiecesView& view, std::size_t t);

// for_each_triangle_in (quality/mesh_regions.hpp) of a view: subdomain k's
// triangles read from its piece in order, their corners and links mapped to
// the merged numbering, without finding the subdomain of each.
template <typename Fn>
void for_each_triangle_in(const PiecesView& view, std::uint32_t k, const Fn& fn) {
  const MeshPiecesData& m = view.data();
  const SubdomainMesh& p = m.pieces[k];
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t) {
    const auto& c = p.triangles[t];
    fn(m.first_triangle[k] + t,
       std::array<std::uint32_t, 3>{m.global_point(k, c[0]), m.global_point(k, c[1]), m.global_point(k, c[2])},
       std::array<std::uint32_t, 3>{m.global_neighbour(k, t, 0), m.global_neighbour(k, t, 1),
                                    m.global_neighbour(k, t, 2)});
  }
}

// The lowest triangle (in the merged numbering) whose closure holds p, or
// no_index, from the pieces' own coordinates, the pieces on `threads`
// threads: what the region flood (quality/mesh_regions.hpp) starts from.
std::uint32_t triangle_at(const PiecesView& view, Point p, unsigned threads);

}  // namespace madd::detail
