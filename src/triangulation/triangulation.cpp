// delaunay() and triangulate(): build on the flat working mesh, classify
// (Triangle's flood from the hull and the hole points across unconstrained
// edges), then compact the surviving triangles into the public value type.
#include "madd/triangulation.hpp"

#include "triangulation/delaunay_mesh.hpp"

namespace madd {

namespace {

using detail::Mesh;
using Triples = std::vector<std::array<std::uint32_t, 3>>;

// Turns the flags (nonzero = dead) into the new index of each live triangle,
// in slot order, and no_index for the dead. Returns the live count.
std::uint32_t renumber(std::vector<std::uint32_t>& dead) {
  std::uint32_t live = 0;
  for (std::uint32_t& d : dead) d = d ? no_index : live++;
  return live;
}

// Moves the triple of each live triangle t to slot index[t] <= t, so one
// forward pass never overwrites a triple it has yet to read.
void compact(std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& index, std::uint32_t live) {
  for (std::uint32_t t = 0; t < index.size(); ++t) {
    if (index[t] == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) a[3 * index[t] + i] = a[3 * t + i];
  }
  a.resize(3 * std::size_t{live});
}

// Twin half-edges become the new index of the neighbouring triangle
// (no_index across into a dead one), compacted like compact().
void compact_neighbours(std::vector<std::uint32_t>& tn, const std::vector<std::uint32_t>& index,
                        std::uint32_t live) {
  for (std::uint32_t t = 0; t < index.size(); ++t) {
    if (index[t] == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) tn[3 * index[t] + i] = index[tn[3 * t + i] / 3];
  }
  tn.resize(3 * std::size_t{live});
}

// An exact-size copy of a flat array of triples; the flat array is released.
Triples to_triples(std::vector<std::uint32_t>& flat) {
  Triples out(flat.size() / 3);
  for (std::size_t t = 0; t < out.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) out[t][i] = flat[3 * t + i];
  }
  std::vector<std::uint32_t>().swap(flat);
  return out;
}

// Moves the triangles not flagged in `dead` (ghosts are always dead) into a
// Triangulation, renumbering them in order and mapping removed neighbours to
// no_index. Peak memory: the working arrays are compacted in place and `dead`
// released before any output array exists, then each working array is
// released as soon as its exact-size copy is made, and the points come last
// (regional attributes, when asked for, are renumbered first).
Triangulation export_mesh(Mesh& mesh, std::vector<std::uint32_t>& dead, std::span<const Point> points,
                          const std::vector<double>& attribute = {}) {
  const std::uint32_t live = renumber(dead);
  std::vector<double> attributes;
  if (!attribute.empty()) {
    attributes.resize(live);
    for (std::uint32_t t = 0; t < dead.size(); ++t)
      if (dead[t] != no_index) attributes[dead[t]] = attribute[t];
  }
  compact(mesh.tv, dead, live);
  compact_neighbours(mesh.tn, dead, live);
  const bool constrained = !mesh.seg.empty();
  if (constrained) compact(mesh.seg, dead, live);
  std::vector<std::uint32_t>().swap(dead);
  Triangulation out;
  out.triangles = to_triples(mesh.tv);
  out.neighbours = to_triples(mesh.tn);
  if (constrained) {
    out.segment_of = to_triples(mesh.seg);
  } else {
    out.segment_of.assign(live, {no_index, no_index, no_index});
  }
  out.points.assign(points.begin(), points.end());
  out.attributes = std::move(attributes);
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

// Triangle's classification: with `convex_hull` off, flood from every ghost
// (the outside of the hull) up to the first segments; then from every hole
// point. Without segments there is nothing to stop a flood: the hull is kept.
std::vector<std::uint32_t> classify(const Mesh& mesh, const Pslg& pslg, const TriangulateOptions& options) {
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
    const std::uint32_t t = detail::walk_to(mesh, pslg.points, hole, some_live);
    if (t == no_index || dead[t]) continue;
    dead[t] = 1;
    stack.push_back(t);
    flood(mesh, dead, stack);
  }
  return dead;
}

// Regional attributes, as Triangle's -A: each region point's attribute spreads
// over the kept triangles around it, up to the segments; a later region in
// the same place wins; the rest get 0.
std::vector<double> region_attributes(const Mesh& mesh, const Pslg& pslg, const std::vector<std::uint32_t>& dead) {
  std::vector<double> attribute(dead.size(), 0.0);
  std::vector<std::uint32_t> seen(dead.size(), 0), stack;
  std::uint32_t some_live = 0;
  while (some_live < dead.size() && dead[some_live]) ++some_live;
  if (some_live == dead.size()) return attribute;
  for (std::uint32_t r = 0; r < pslg.regions.size(); ++r) {
    const std::uint32_t t0 = detail::walk_to(mesh, pslg.points, pslg.regions[r].at, some_live);
    if (t0 == no_index || dead[t0]) continue;
    const std::uint32_t stamp = r + 1;
    seen[t0] = stamp;
    stack.push_back(t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      attribute[t] = pslg.regions[r].attribute;
      for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
        const std::uint32_t u = mesh.tn[h] / 3;
        if ((!mesh.seg.empty() && mesh.seg[h] != no_index) || dead[u] || seen[u] == stamp) continue;
        seen[u] = stamp;
        stack.push_back(u);
      }
    }
  }
  return attribute;
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

Triangulation triangulate(const Pslg& pslg, const TriangulateOptions& options) {
  Mesh mesh;
  if (!detail::build_delaunay(mesh, pslg.points)) {
    Triangulation out;
    out.points = pslg.points;
    return out;
  }
  detail::insert_segments(mesh, pslg);
  std::vector<std::uint32_t> dead = classify(mesh, pslg, options);
  if (!options.region_attributes) return export_mesh(mesh, dead, pslg.points);
  const std::vector<double> attribute = region_attributes(mesh, pslg, dead);
  return export_mesh(mesh, dead, pslg.points, attribute);
}

} // namespace madd
