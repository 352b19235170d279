// delaunay() and triangulate(): build in the half-edge core
// (triangulation/cdt.hpp), then copy the surviving triangles into the public
// value type.
#include "madd/triangulation.hpp"

#include "triangulation/cdt.hpp"

namespace madd {

namespace {

using detail::HalfEdgeMesh;
using Triples = std::vector<std::array<std::uint32_t, 3>>;

// An exact-size copy of a flat array of triples, each entry mapped by `f`;
// the flat array is released.
template <class F>
Triples to_triples(std::vector<std::uint32_t>& flat, F&& f) {
  Triples out(flat.size() / 3);
  for (std::size_t t = 0; t < out.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) out[t][i] = f(flat[3 * t + i]);
  }
  std::vector<std::uint32_t>().swap(flat);
  return out;
}

// Moves a ghost-free core mesh into a Triangulation, twins becoming the
// neighbouring triangle. Peak memory: each working array is released as
// soon as its exact-size copy is made, and the points come last.
Triangulation export_mesh(HalfEdgeMesh& mesh, std::span<const Point> points, std::vector<double> attributes = {}) {
  const auto same = [](std::uint32_t x) { return x; };
  Triangulation out;
  out.attributes = std::move(attributes);
  const std::size_t live = mesh.slot_count();
  out.triangles = to_triples(mesh.tv, same);
  out.neighbours = to_triples(mesh.tn, [](std::uint32_t h) { return h == no_index ? no_index : h / 3; });
  if (mesh.constrained()) {
    out.segment_of = to_triples(mesh.seg, same);
  } else {
    out.segment_of.assign(live, {no_index, no_index, no_index});
  }
  out.points.assign(points.begin(), points.end());
  return out;
}

}  // namespace

Triangulation delaunay(std::span<const Point> points) {
  HalfEdgeMesh mesh;
  if (!detail::build_delaunay(mesh, points)) {
    Triangulation out;
    out.points.assign(points.begin(), points.end());
    return out;
  }
  std::vector<std::uint32_t> dead(mesh.slot_count());
  for (std::uint32_t t = 0; t < dead.size(); ++t) dead[t] = mesh.is_ghost(t) ? 1 : 0;
  mesh.remove_triangles(dead);
  std::vector<std::uint32_t>().swap(dead);
  return export_mesh(mesh, points);
}

Triangulation triangulate(const Pslg& pslg, const TriangulateOptions& options) {
  HalfEdgeMesh mesh;
  std::vector<std::uint32_t> regions;
  if (!detail::constrained_delaunay(mesh, pslg, options, options.region_attributes ? &regions : nullptr)) {
    Triangulation out;
    out.points = pslg.points;
    return out;
  }
  if (!options.region_attributes) return export_mesh(mesh, pslg.points);
  std::vector<double> attributes(regions.size());
  for (std::size_t t = 0; t < regions.size(); ++t)
    attributes[t] = regions[t] == 0 ? 0.0 : pslg.regions[regions[t] - 1].attribute;
  std::vector<std::uint32_t>().swap(regions);
  return export_mesh(mesh, pslg.points, std::move(attributes));
}

}  // namespace madd
