// decomposition_faces (output/faces.hpp): one constrained triangulation of the
// whole decomposition, with the input's region points located by
// triangulate's own regional attributes (Triangle's -A rule, so a region
// point is placed as `madd triangulate -A` would place it). Faces are the
// triangles joined across unconstrained edges; the subdomain of a face is
// read off the ring (or interior segment) on any of its constrained edges,
// and the input's regions are the faces joined across separators.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "kernel/union_find.hpp"
#include "output/faces.hpp"

namespace madd::detail {
namespace {

bool has_interior_segments(const Decomposition& d) {
  return std::any_of(d.subdomains.begin(), d.subdomains.end(),
                     [](const Subdomain& s) { return !s.interior_segments.empty(); });
}

// The subdomain on each side of each segment: left[s] walks it from a to b
// (rings keep their subdomain on the left), right[s] from b to a; an interior
// piece has its subdomain on both sides.
struct Sides {
  std::vector<std::uint32_t> left, right;
};

Sides segment_sides(const Decomposition& d) {
  Sides sides{std::vector<std::uint32_t>(d.segments.size(), no_index),
              std::vector<std::uint32_t>(d.segments.size(), no_index)};
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    const Subdomain& sub = d.subdomains[k];
    for (std::size_t r = 0; r < sub.rings.size(); ++r)
      for (std::size_t j = 0; j < sub.rings[r].size(); ++j) {
        const std::uint32_t s = sub.ring_segments[r][j];
        (sub.rings[r][j] == d.segments[s].a ? sides.left : sides.right)[s] = k;
      }
    for (const std::uint32_t s : sub.interior_segments) sides.left[s] = sides.right[s] = k;
  }
  return sides;
}

// The whole decomposition as one PSLG; region r carries attribute r + 1 so
// that each triangle's attribute names the last region point of its face.
Triangulation triangulate_decomposition(const Decomposition& d) {
  Pslg pslg;
  pslg.points = d.points;
  pslg.segments = d.segments;
  pslg.holes = d.holes;
  for (std::uint32_t r = 0; r < d.regions.size(); ++r) pslg.regions.push_back({d.regions[r].at, r + 1.0, -1.0});
  TriangulateOptions options;
  options.region_attributes = !pslg.regions.empty();
  return triangulate(pslg, options);
}

// Face id of every triangle (triangles joined across unconstrained edges),
// numbered in order of their first triangle.
std::vector<std::uint32_t> flood_faces(const Triangulation& tri, std::uint32_t& count) {
  std::vector<std::uint32_t> face(tri.triangle_count(), no_index), stack;
  count = 0;
  for (std::uint32_t t0 = 0; t0 < tri.triangle_count(); ++t0) {
    if (face[t0] != no_index) continue;
    face[t0] = count;
    stack.push_back(t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t u = tri.neighbours[t][i];
        if (tri.is_constrained(t, i) || u == no_index || face[u] != no_index) continue;
        face[u] = count;
        stack.push_back(u);
      }
    }
    ++count;
  }
  return face;
}

// The subdomain of triangle t's side of its constrained edge i: the edge runs
// from vertex i+1 to vertex i+2 with t on its left.
std::uint32_t subdomain_beside(const Decomposition& d, const Sides& sides, const Triangulation& tri, std::uint32_t t,
                               int i) {
  const std::uint32_t s = tri.segment_of[t][i];
  const Segment& g = d.segments[s];
  const Point from = tri.points[tri.triangles[t][(i + 1) % 3]], to = tri.points[tri.triangles[t][(i + 2) % 3]];
  const Point along = d.points[g.b] - d.points[g.a], step = to - from;
  return along.x * step.x + along.y * step.y > 0 ? sides.left[s] : sides.right[s];
}

// A point strictly inside one of `triangles` (orient2d decides): the centroid
// of the largest one for which it is, trying the largest first.
Point point_inside(const Triangulation& tri, std::vector<std::uint32_t> triangles) {
  const auto area = [&](std::uint32_t t) {
    const auto& v = tri.triangles[t];
    return signed_area(tri.points[v[0]], tri.points[v[1]], tri.points[v[2]]);
  };
  std::stable_sort(triangles.begin(), triangles.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return area(a) > area(b); });
  for (const std::uint32_t t : triangles) {
    const Point a = tri.points[tri.triangles[t][0]], b = tri.points[tri.triangles[t][1]],
                c = tri.points[tri.triangles[t][2]];
    const Point m{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    if (orient2d(a, b, m) > 0 && orient2d(b, c, m) > 0 && orient2d(c, a, m) > 0) return m;
  }
  throw InternalError("decomposition faces: no point strictly inside a face of " + std::to_string(triangles.size()) +
                      " triangles");
}

// True when p lies on a constrained edge of one of `triangles` (closed: its
// ends included), that is, on the face's boundary or one of its segments.
bool on_constrained_edge(const Triangulation& tri, const std::vector<std::uint32_t>& triangles, Point p) {
  for (const std::uint32_t t : triangles)
    for (int i = 0; i < 3; ++i) {
      if (!tri.is_constrained(t, i)) continue;
      const Point a = tri.points[tri.triangles[t][(i + 1) % 3]], b = tri.points[tri.triangles[t][(i + 2) % 3]];
      if (orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
          std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
        return true;
    }
  return false;
}

}  // namespace

std::vector<DecompositionFace> decomposition_faces(const Decomposition& d) {
  std::vector<DecompositionFace> out;
  const bool interior = has_interior_segments(d);
  if (!interior && d.regions.empty()) {
    for (std::uint32_t k = 0; k < d.subdomains.size(); ++k)
      out.push_back({k, d.subdomains[k].interior_point, no_index});
    return out;
  }
  const Sides sides = segment_sides(d);
  const Triangulation tri = triangulate_decomposition(d);
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> face = flood_faces(tri, count);

  std::vector<std::uint32_t> subdomain(count, no_index), region(count, 0), parent(count);
  std::iota(parent.begin(), parent.end(), 0U);
  std::vector<std::vector<std::uint32_t>> triangles(count);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    const std::uint32_t f = face[t];
    triangles[f].push_back(t);
    if (!tri.attributes.empty()) region[f] = std::max(region[f], static_cast<std::uint32_t>(tri.attributes[t]));
    for (int i = 0; i < 3; ++i) {
      if (!tri.is_constrained(t, i)) continue;
      const std::uint32_t k = subdomain_beside(d, sides, tri, t, i);
      if (k != no_index && subdomain[f] != no_index && subdomain[f] != k)
        throw InternalError("decomposition faces: a face is bounded by subdomains " + std::to_string(subdomain[f]) +
                            " and " + std::to_string(k));
      if (k != no_index) subdomain[f] = k;
      // The input does not stop at separators: both sides are one region of it.
      const std::uint32_t u = tri.neighbours[t][i];
      if (u != no_index && d.is_separator(tri.segment_of[t][i]))
        parent[find_root(parent, f)] = find_root(parent, face[u]);
    }
  }
  // Later regions win (Triangle's -A): the largest number in the input's region.
  std::vector<std::uint32_t> governing(count, 0);
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::uint32_t root = find_root(parent, f);
    governing[root] = std::max(governing[root], region[f]);
  }
  std::vector<std::uint32_t> faces_of_subdomain(d.subdomains.size(), 0);
  for (std::uint32_t f = 0; f < count; ++f)
    if (subdomain[f] != no_index) ++faces_of_subdomain[subdomain[f]];
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0U);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return subdomain[a] < subdomain[b]; });
  // The point of a face: the input's own region point when it is the one
  // covering the face and lies strictly inside it (the file then shows the
  // user's point), else the subdomain's interior point when the face is the
  // whole subdomain, else a point inside its largest triangle.
  for (const std::uint32_t f : order) {
    const std::uint32_t k = subdomain[f];
    if (k == no_index) continue;  // bounded by segments of no subdomain (not part of the decomposition)
    const std::uint32_t g = governing[find_root(parent, f)];
    const bool whole = faces_of_subdomain[k] == 1 && d.subdomains[k].interior_segments.empty();
    Point at;
    if (g != 0 && region[f] == g && !on_constrained_edge(tri, triangles[f], d.regions[g - 1].at)) {
      at = d.regions[g - 1].at;  // its flood started in this face, and it is on none of its edges
    } else {
      at = whole ? d.subdomains[k].interior_point : point_inside(tri, triangles[f]);
    }
    out.push_back({k, at, g == 0 ? no_index : g - 1});
  }
  return out;
}

}  // namespace madd::detail
