// Density weights of the G_D vertices of one split (Sec. 5.2), so that the
// bisection balances density rather than area.
#include <algorithm>
#include <cmath>

#include "split/locate.hpp"
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

// Cases 2/3: each weight sample goes to the first G_D vertex containing it.
void add_samples(const MedialGraph& g, const Triangulation& tri, const FaceDensity& density, std::vector<double>& out) {
  if (density.samples.empty() || out.empty()) return;
  const GdLocator locator(g, tri);
  for (const ValuedPoint& s : density.samples) {
    locator.for_each_containing(s.at, [&](std::uint32_t v) {
      out[v] += density.a * s.value;
      return false;
    });
  }
}

}  // namespace

std::vector<double> density_weights(const MedialGraph& g, const Triangulation& tri, const FaceDomain& fd,
                                    const FaceDensity& density) {
  std::vector<double> out(g.gd.vertex_weights.size());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = density.r * g.gd.vertex_weights[v];
  if (density.point_weights != nullptr) add_boundary_share(g, tri, fd, density, out);
  add_samples(g, tri, density, out);
  return out;
}

}  // namespace madd::detail
