// delaunay() and triangulate(): build on the flat working mesh, classify
// (Triangle's flood from the hull and the hole points across unconstrained
// edges), then compact the surviving triangles into the public value type.
#include "madd/triangulation.hpp"

#include "delaunay_mesh.hpp"

namespace madd {

namespace {

using detail::Mesh;

// Moves the triangles not flagged in `dead` (ghosts are always dead) into a
// Triangulation, renumbering them in order and mapping removed neighbours to
// no_index. `dead` is reused for the new indices, and each working array is
// released as soon as it is copied, to keep the peak memory low.
Triangulation export_mesh(Mesh& mesh, std::vector<std::uint32_t>& dead, std::span<const Point> points) {
  std::vector<Point>().swap(mesh.points);
  Triangulation out;
  out.points.assign(points.begin(), points.end());
  const std::uint32_t nt = mesh.triangle_count();
  std::uint32_t live = 0;
  for (std::uint32_t t = 0; t < nt; ++t) dead[t] = dead[t] ? no_index : live++;
  out.triangles.resize(live);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (dead[t] == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) out.triangles[dead[t]][i] = mesh.order[mesh.tv[3 * t + i]];
  }
  std::vector<std::uint32_t>().swap(mesh.tv);
  std::vector<std::uint32_t>().swap(mesh.order);
  out.neighbours.resize(live);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (dead[t] == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) out.neighbours[dead[t]][i] = dead[mesh.tn[3 * t + i] / 3];
  }
  std::vector<std::uint32_t>().swap(mesh.tn);
  const bool constrained = !mesh.seg.empty();
  out.segment_of.resize(live);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (dead[t] == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      out.segment_of[dead[t]][i] = constrained ? mesh.seg[3 * t + i] : no_index;
    }
  }
  return out;
}

std::vector<std::uint32_t> ghost_flags(const Mesh& mesh) {
  std::vector<std::uint32_t> dead(mesh.triangle_count());
  for (std::uint32_t t = 0; t < dead.size(); ++t) dead[t] = mesh.is_ghost(t) ? 1 : 0;
  return dead;
}

// Marks everything reachable from the triangles on `stack` without crossing a
// constrained edge.
void flood(const Mesh& mesh, std::vector<std::uint32_t>& dead, std::vector<std::uint32_t>& stack) {
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
      if (mesh.seg[h] != no_index) continue;
      const std::uint32_t u = mesh.tn[h] / 3;
      if (dead[u]) continue;
      dead[u] = 1;
      stack.push_back(u);
    }
  }
}

std::vector<std::uint32_t> classify(const Mesh& mesh, const Pslg& pslg) {
  std::vector<std::uint32_t> dead = ghost_flags(mesh);
  if (pslg.segments.empty()) return dead;  // no boundary: keep the convex hull
  std::vector<std::uint32_t> stack;
  std::uint32_t some_live = no_index;
  for (std::uint32_t t = 0; t < dead.size(); ++t) {
    if (dead[t]) {
      stack.push_back(t);
    } else if (some_live == no_index) {
      some_live = t;
    }
  }
  flood(mesh, dead, stack);
  for (const Point& hole : pslg.holes) {
    if (some_live == no_index) break;
    const std::uint32_t t = detail::walk_to(mesh, hole, some_live);
    if (t == no_index || dead[t]) continue;
    dead[t] = 1;
    stack.push_back(t);
    flood(mesh, dead, stack);
  }
  return dead;
}

} // namespace

Triangulation delaunay(std::span<const Point> points) {
  Mesh mesh;
  if (!detail::build_delaunay(mesh, points)) {
    Triangulation out;
    out.points.assign(points.begin(), points.end());
    return out;
  }
  std::vector<std::uint32_t> dead = ghost_flags(mesh);
  return export_mesh(mesh, dead, points);
}

Triangulation triangulate(const Pslg& pslg) {
  Mesh mesh;
  if (!detail::build_delaunay(mesh, pslg.points)) {
    Triangulation out;
    out.points = pslg.points;
    return out;
  }
  detail::insert_segments(mesh, pslg);
  std::vector<std::uint32_t> dead = classify(mesh, pslg);
  return export_mesh(mesh, dead, pslg.points);
}

} // namespace madd
