// The constrained Delaunay triangulation of a PSLG in the half-edge core:
// build, insert the segments, classify (Triangle's flood from the hull and
// the hole points across unconstrained edges), flood the regions, and remove
// what is not kept.
#include <vector>

#include "triangulation/cdt.hpp"
#include "triangulation/walk.hpp"

namespace madd::detail {

namespace {

std::vector<std::uint32_t> ghost_flags(const HalfEdgeMesh& mesh) {
  std::vector<std::uint32_t> dead(mesh.slot_count());
  for (std::uint32_t t = 0; t < dead.size(); ++t) dead[t] = mesh.is_ghost(t) ? 1 : 0;
  return dead;
}

// Marks everything reachable from the triangles on `stack` without crossing a
// constrained edge.
void flood(const HalfEdgeMesh& mesh, std::vector<std::uint32_t>& dead, std::vector<std::uint32_t>& stack) {
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

// The triangle holding p, walking from `from` (no_index when p is outside).
std::uint32_t locate(const HalfEdgeMesh& mesh, const Pslg& pslg, Point p, std::uint32_t from) {
  WalkRandom random;
  return walk_visibly(mesh, pslg.points, p, from, random).triangle;
}

// Triangle's classification: with `convex_hull` off, flood from every ghost
// (the outside of the hull) up to the first segments; then from every hole
// point. Without segments there is nothing to stop a flood: the hull is kept.
std::vector<std::uint32_t> classify(const HalfEdgeMesh& mesh, const Pslg& pslg, const TriangulateOptions& options) {
  std::vector<std::uint32_t> dead = ghost_flags(mesh);
  if (pslg.segments.empty()) return dead;
  std::vector<std::uint32_t> stack;
  std::uint32_t some_live = no_index;
  for (std::uint32_t t = 0; t < dead.size() && some_live == no_index; ++t)
    if (!mesh.is_ghost(t)) some_live = t;
  // One ghost at a time: the stack then holds at most the region being
  // flooded, not every hull edge at once (half the mesh for a convex polygon).
  for (std::uint32_t t = 0; t < dead.size() && !options.convex_hull; ++t) {
    if (!mesh.is_ghost(t)) continue;
    stack.push_back(t);
    flood(mesh, dead, stack);
  }
  for (const Point& hole : pslg.holes) {
    if (some_live == no_index) break;
    const std::uint32_t t = locate(mesh, pslg, hole, some_live);
    if (t == no_index || dead[t]) continue;
    dead[t] = 1;
    stack.push_back(t);
    flood(mesh, dead, stack);
  }
  return dead;
}

// Regions, as Triangle's -A: each region point's number (1 + its index)
// spreads over the kept triangles around it, up to the segments; a later
// region in the same place wins; the rest get 0.
std::vector<std::uint32_t> region_labels(const HalfEdgeMesh& mesh, const Pslg& pslg,
                                         const std::vector<std::uint32_t>& dead) {
  std::vector<std::uint32_t> label(dead.size(), 0);
  std::vector<std::uint32_t> seen(dead.size(), 0), stack;
  std::uint32_t some_live = 0;
  while (some_live < dead.size() && dead[some_live]) ++some_live;
  if (some_live == dead.size()) return label;
  for (std::uint32_t r = 0; r < pslg.regions.size(); ++r) {
    const std::uint32_t t0 = locate(mesh, pslg, pslg.regions[r].at, some_live);
    if (t0 == no_index || dead[t0]) continue;
    const std::uint32_t stamp = r + 1;
    seen[t0] = stamp;
    stack.push_back(t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      label[t] = stamp;
      for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
        const std::uint32_t u = mesh.tn[h] / 3;
        if (mesh.seg[h] != no_index || dead[u] || seen[u] == stamp) continue;
        seen[u] = stamp;
        stack.push_back(u);
      }
    }
  }
  return label;
}

}  // namespace

bool constrained_delaunay(HalfEdgeMesh& mesh, const Pslg& pslg, const TriangulateOptions& options,
                          std::vector<std::uint32_t>* regions) {
  if (!build_delaunay(mesh, pslg.points)) {
    mesh = HalfEdgeMesh{};
    return false;
  }
  insert_segments(mesh, pslg);
  std::vector<std::uint32_t> dead = classify(mesh, pslg, options);
  if (regions) *regions = region_labels(mesh, pslg, dead);
  const std::uint32_t live = mesh.remove_triangles(dead);
  if (regions) {
    // Each kept triangle moves down to its new index, as in remove_triangles.
    for (std::uint32_t t = 0; t < dead.size(); ++t)
      if (dead[t] != no_index) (*regions)[dead[t]] = (*regions)[t];
    regions->resize(live);
  }
  return true;
}

}  // namespace madd::detail
