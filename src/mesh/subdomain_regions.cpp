// Each subdomain's regions (subdomain_regions.hpp): the faces of the
// subdomain's own segments, a point inside each, and the region of the
// input face that point lies in.
#include "mesh/subdomain_regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kernel/threads.hpp"
#include "kernel/uniform_grid.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "mesh/merge.hpp"

namespace madd::detail {

namespace {

// Per triangle of the whole domain's boundary and interior pieces: 1 + the
// index of the region whose face holds it, 0 for none (the triangulator's
// own -A flood on the region numbers).
Triangulation labelled_domain(const Decomposition& d) {
  Pslg p;
  p.points = d.points;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j)
    if (!d.is_separator(j)) p.segments.push_back(d.segments[j]);
  p.holes = d.holes;
  p.regions = d.regions;
  for (std::size_t r = 0; r < p.regions.size(); ++r) p.regions[r].attribute = static_cast<double>(r + 1);
  TriangulateOptions options;
  options.region_attributes = true;
  return triangulate(p, options);
}

// Subdomain k's own triangulation (its rings, interior pieces and isolated
// vertices), the face of each triangle (flooded across unconstrained edges)
// and one point strictly inside each face: the centroid of the face's
// largest triangle (ties: the lowest), far from its edges as triangles go.
struct Faces {
  LocalDomain local;
  Triangulation tri;
  std::vector<std::uint32_t> face;  // per triangle
  std::vector<Point> point;         // per face
};

Faces faces_of(const Decomposition& d, std::uint32_t k) {
  Faces out;
  out.local = local_domain(d, k);
  out.tri = triangulate(out.local.pslg);
  const Triangulation& tri = out.tri;
  const auto n = static_cast<std::uint32_t>(tri.triangles.size());
  const auto area = [&](std::uint32_t t) {
    const auto& c = tri.triangles[t];
    return triangle_area(tri.points[c[0]], tri.points[c[1]], tri.points[c[2]]);
  };
  out.face.assign(n, no_index);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t t0 = 0; t0 < n; ++t0) {
    if (out.face[t0] != no_index) continue;
    out.face[t0] = static_cast<std::uint32_t>(out.point.size());
    std::uint32_t best = t0;
    stack.assign(1, t0);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      if (area(t) > area(best) || (area(t) == area(best) && t < best)) best = t;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t u = tri.neighbours[t][i];
        if (u == no_index || tri.is_constrained(t, i) || out.face[u] != no_index) continue;
        out.face[u] = out.face[t0];
        stack.push_back(u);
      }
    }
    const auto& c = tri.triangles[best];
    out.point.push_back(triangle_centroid(tri.points[c[0]], tri.points[c[1]], tri.points[c[2]]));
  }
  return out;
}

// The label of the triangle of `tri` holding each query point (closed
// triangles; the lowest triangle wins), 0 where none does. The queries are
// listed in a uniform grid, so each triangle tests only those near it.
std::vector<std::uint32_t> labels_at(const Triangulation& tri, const std::vector<Point>& queries) {
  std::vector<std::uint32_t> out(queries.size(), 0);
  std::vector<std::uint8_t> found(queries.size(), 0);
  if (queries.empty()) return out;
  double x0 = queries[0].x, y0 = queries[0].y, x1 = x0, y1 = y0;
  for (const Point q : queries) {
    x0 = std::min(x0, q.x);
    y0 = std::min(y0, q.y);
    x1 = std::max(x1, q.x);
    y1 = std::max(y1, q.y);
  }
  const auto side = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(queries.size())), 1.0, 256.0));
  UniformGrid grid({x0, y0}, std::max(x1 - x0, 1e-300) / side, std::max(y1 - y0, 1e-300) / side, side, side);
  grid.fill(static_cast<std::uint32_t>(queries.size()), UniformGrid::Index::by_cell,
            [&](std::uint32_t q, auto&& add) { add(grid.col_of(queries[q].x), grid.row_of(queries[q].y)); });
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t) {
    const Point a = tri.points[tri.triangles[t][0]], b = tri.points[tri.triangles[t][1]],
                c = tri.points[tri.triangles[t][2]];
    const Point lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
    const Point hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
    if (hi.x < x0 || lo.x > x1 || hi.y < y0 || lo.y > y1) continue;
    grid.in_box(lo, hi, [&](std::uint32_t q) {
      if (found[q]) return;
      const Point p = queries[q];
      if (orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0) {
        found[q] = 1;
        out[q] = static_cast<std::uint32_t>(tri.attributes[t]);
      }
    });
  }
  return out;
}

}  // namespace

RegionView region_view(const Decomposition& d, unsigned threads) {
  RegionView out;
  out.regions.resize(d.subdomains.size());
  out.bounded_faces.resize(d.subdomains.size());
  out.segment_area.assign(d.segments.size(), std::numeric_limits<double>::infinity());
  if (d.regions.empty()) return out;
  // Each subdomain's faces from its own triangulation, into its own slot.
  std::vector<Faces> faces(d.subdomains.size());
  for_each_on_threads(d.subdomains.size(), threads,
                      [&](std::size_t k) { faces[k] = faces_of(d, static_cast<std::uint32_t>(k)); });
  std::vector<Point> queries;
  std::vector<std::uint32_t> first;  // per subdomain: its first query
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    first.push_back(static_cast<std::uint32_t>(queries.size()));
    queries.insert(queries.end(), faces[k].point.begin(), faces[k].point.end());
  }
  const std::vector<std::uint32_t> labels = labels_at(labelled_domain(d), queries);
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    const Faces& f = faces[k];
    for (std::size_t p = 0; p < f.point.size(); ++p) {
      const std::uint32_t label = labels[first[k] + p];
      if (label == 0) continue;
      const Region& r = d.regions[label - 1];
      out.regions[k].push_back({f.point[p], r.attribute, r.max_area});
    }
    std::vector<double> face_area(f.point.size(), 0.0);
    for (std::uint32_t t = 0; t < f.tri.triangles.size(); ++t) {
      const auto& c = f.tri.triangles[t];
      face_area[f.face[t]] += triangle_area(f.tri.points[c[0]], f.tri.points[c[1]], f.tri.points[c[2]]);
    }
    for (std::size_t p = 0; p < f.point.size(); ++p) {
      const std::uint32_t label = labels[first[k] + p];
      if (label != 0 && d.regions[label - 1].max_area > 0)
        out.bounded_faces[k].emplace_back(face_area[p], d.regions[label - 1].max_area);
    }
    // Each segment edge of the triangulation bounds the face of its triangle.
    for (std::uint32_t t = 0; t < f.tri.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t s = f.tri.segment_of[t][i];
        const std::uint32_t label = labels[first[k] + f.face[t]];
        if (s == no_index || label == 0 || !(d.regions[label - 1].max_area > 0)) continue;
        double& bound = out.segment_area[f.local.piece[s]];
        bound = std::min(bound, d.regions[label - 1].max_area);
      }
  }
  return out;
}

}  // namespace madd::detail
