// Density weights of the G_D vertices of one split (Sec. 5.2), so that the
// bisection balances density rather than area.
#include <algorithm>
#include <cmath>

#include "kernel/box.hpp"
#include "kernel/containment.hpp"
#include "split/refine.hpp"
#include "split/split.hpp"

namespace madd::detail {

namespace {

// The triangulation points at the corners of G_D vertex v (two for a sub-triangle around a circumcentre).
int vertex_points(const MedialGraph& g, const Triangulation& tri, std::uint32_t v, std::uint32_t out[3]) {
  const auto& tv = tri.triangles[g.vertex_triangle[v]];
  const int sub = g.vertex_sub[v];
  if (sub == 3) {
    out[0] = tv[0], out[1] = tv[1], out[2] = tv[2];
    return 3;
  }
  out[0] = tv[(sub + 1) % 3], out[1] = tv[(sub + 2) % 3];
  return 2;
}

// Case 1: every working point that is a subdivision vertex shares its weight
// equally among the G_D vertices touching it.
void add_boundary_share(const MedialGraph& g, const Triangulation& tri, const FaceDomain& fd,
                        const FaceDensity& density, std::vector<double>& out) {
  std::vector<std::uint32_t> touching(tri.points.size(), 0);
  std::uint32_t pts[3];
  for (std::uint32_t v = 0; v < out.size(); ++v) {
    const int n = vertex_points(g, tri, v, pts);
    for (int i = 0; i < n; ++i) ++touching[pts[i]];
  }
  for (std::uint32_t v = 0; v < out.size(); ++v) {
    const int n = vertex_points(g, tri, v, pts);
    for (int i = 0; i < n; ++i) {
      const EndRef& ref = fd.refs[pts[i]];
      if (ref.kind != EndRef::vertex) continue;
      out[v] += density.a * (*density.point_weights)[ref.id] / touching[pts[i]];
    }
  }
}

// Cases 2/3: each weight sample goes to the G_D vertex containing it, found
// through a uniform bucket grid of the vertices' bounding boxes.
void add_samples(const MedialGraph& g, const Triangulation& tri, const FaceDensity& density, std::vector<double>& out) {
  if (density.samples.empty() || out.empty()) return;
  const Box all = bounding_box(tri.points);
  const Point lo = all.lo;
  const auto cells = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(out.size())), 1.0, 512.0));
  const double cw = std::max(all.width() / cells, 1e-300), ch = std::max(all.height() / cells, 1e-300);
  auto cell = [&](double x, double origin, double size) {
    return static_cast<std::uint32_t>(std::clamp(std::floor((x - origin) / size), 0.0, cells - 1.0));
  };
  std::vector<std::vector<std::uint32_t>> bucket(static_cast<std::size_t>(cells) * cells);
  for (std::uint32_t v = 0; v < out.size(); ++v) {
    const Box box = bounding_box(vertex_triangle_corners(g, tri, v));
    for (std::uint32_t i = cell(box.lo.x, lo.x, cw); i <= cell(box.hi.x, lo.x, cw); ++i) {
      for (std::uint32_t j = cell(box.lo.y, lo.y, ch); j <= cell(box.hi.y, lo.y, ch); ++j) bucket[i * cells + j].push_back(v);
    }
  }
  for (const ValuedPoint& s : density.samples) {
    for (std::uint32_t v : bucket[cell(s.at.x, lo.x, cw) * cells + cell(s.at.y, lo.y, ch)]) {
      const auto c = vertex_triangle_corners(g, tri, v);
      if (in_closed_triangle(c[0], c[1], c[2], s.at)) {
        out[v] += density.a * s.value;
        break;
      }
    }
  }
}

} // namespace

std::vector<double> density_weights(const MedialGraph& g, const Triangulation& tri, const FaceDomain& fd,
                                    const FaceDensity& density) {
  std::vector<double> out(g.gd.vertex_weights.size());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = density.r * g.gd.vertex_weights[v];
  if (density.point_weights != nullptr) add_boundary_share(g, tri, fd, density, out);
  add_samples(g, tri, density, out);
  return out;
}

} // namespace madd::detail
