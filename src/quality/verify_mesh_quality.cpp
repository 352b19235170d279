// verify_mesh, the quality bounds: every triangle within the size bound at
// its centroid, and the triangles below the angle bound exactly as many as
// the shortfall counts.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "kernel/number_format.hpp"
#include "kernel/threads.hpp"
#include "quality/area_bound.hpp"
#include "quality/mesh_angle.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

namespace {

// The triangle's smallest angle (the corner smallest_angle_deg measures:
// opposite the shortest edge) is at least the angle whose tangent is
// `tangent`, by a margin far above rounding: tan of that corner is
// |cross| / dot of its edges (dot > 0: the smallest angle is at most 60
// degrees), each within a few ulps of |u| |v|, which moves an angle of a
// degree or more by ~1e-14 rad against the caller's 1e-6 degrees (1.7e-8
// rad), for a bound of a degree or more. Then smallest_angle_deg is above
// the bound too; otherwise it decides.
bool well_above_bound(Point a, Point b, Point c, double tangent) noexcept {
  const Point ab = b - a, bc = c - b, ca = a - c;
  const double lab = dot(ab, ab), lbc = dot(bc, bc), lca = dot(ca, ca);
  Point u, v;  // the two edges at the measured corner
  if (lab <= lbc && lab <= lca) u = a - c, v = b - c;
  else if (lbc <= lca) u = b - a, v = c - a;
  else u = c - b, v = a - b;
  const double d = dot(u, v), x = std::abs(cross(u, v));
  return d > 0.0 && x > tangent * d * (1.0 + 1e-12);
}

}  // namespace

// A triangle is too large when twice its area exceeds twice its bound by
// more than the rounding of both computations of the area, this one and the
// mesher's:
// - the area is computed here as |cross(b - a, c - a)| / 2 in doubles; with
//   each difference and product rounded, it is within 4u (|u.x v.y| + |u.y v.x|)
//   <= 8u L^2 of twice the exact area (u = 2^-53, L the longest edge); the
//   mesher's own formula, at whatever corner, is within the same kind of
//   bound, so 16u L^2 (doubled: 32u L^2 on twice the area) covers the two.
//   For a well-shaped triangle that is ~1e-14 relative; it only matters for
//   flat ones, where the rounded area is mostly noise;
// - the relative 1e-12 on the bound is room for the mesher reaching the same
//   bound through other roundings: a bound computed once and scaled, the
//   function evaluated at a centroid formed another way (a few ulps off).
//   Both ask the one AreaBound (quality/area_bound.hpp) at triangle_centroid;
//   a bound that differs by more than this is another bound, not rounding.
// A region's max_area (> 0) is one more bound on its triangles, the smallest winning.
namespace {

// Under a field of slope L (AreaBound::edge_slope), a lower bound on h at
// triangle t's centroid g from the queries already made at its neighbours'
// centroids (edge[u], NaN where none was): the path from a neighbour's
// centroid to the midpoint of their shared edge and on to g lies in the two
// triangles, so h(g) >= h there less L times its length (as the mesher
// reads its bounds, mesh/refine.cpp, Refiner::bound_of; the margin covers
// the rounding of the field's value). 0 when no neighbour was queried.
double edge_from_neighbours(const Mesh& m, std::uint32_t t, Point g, double slope, const std::vector<double>& edge,
                            std::size_t first) {
  double low = 0.0;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t u = m.neighbours[t][static_cast<std::size_t>(i)];
    if (u == no_index || u < first || u - first >= edge.size() || std::isnan(edge[u - first])) continue;
    const auto& c = m.triangles[u];
    const Point gu = triangle_centroid(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
    const Point mid = midpoint(m.points[m.triangles[t][static_cast<std::size_t>((i + 1) % 3)]],
                               m.points[m.triangles[t][static_cast<std::size_t>((i + 2) % 3)]]);
    low = std::max(low, (edge[u - first] - slope * (distance(gu, mid) + distance(mid, g))) * (1.0 - 1e-9));
  }
  return low;
}

}  // namespace

// Each triangle's area against the bound at its centroid. Under a field of
// slope L most triangles are passed from a neighbour's query
// (edge_from_neighbours): a lower bound on the bound that the triangle
// already meets; the others, and any the lower bound does not pass, are
// queried (a query per triangle was a third of the graded Maine coast's
// check).
void check_mesh_size(const Mesh& m, const AreaBound& bound_at, const std::vector<std::uint32_t>& label, ProblemLog& log,
                     unsigned threads) {
  const std::vector<Region>& regions = m.decomposition.regions;
  bool regional = false;
  for (const Region& r : regions) regional |= r.max_area > 0;
  if (!bound_at.bounded() && !regional) return;
  constexpr double u = 0x1p-53;
  const auto& P = m.points;
  const double slope = bound_at.edge_slope();
  const bool linked = slope > 0.0 && m.neighbours.size() == m.triangles.size();
  // A triangle within the least bound anywhere (AreaBound::least) is within
  // its own: no query (the check below then passes it with that bound).
  const std::size_t parts = 4 * std::size_t{thread_count(threads, m.triangles.size())};
  log_in_parts(m.triangles.size(), parts, threads, log,
               [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& part_log) {
                 BoundHint hint;  // a subdomain's triangles are numbered together: near each other
                 std::vector<double> edge(linked ? end - begin : 0, std::numeric_limits<double>::quiet_NaN());
                 for (auto t = static_cast<std::uint32_t>(begin); t < end; ++t) {
                   const Point a = P[m.triangles[t][0]], b = P[m.triangles[t][1]], c = P[m.triangles[t][2]];
                   const Point ab = b - a, ac = c - a, bc = c - b;
                   const double twice = std::abs(cross(ab, ac));
                   const double longest2 = std::max({dot(ab, ab), dot(ac, ac), dot(bc, bc)});
                   const double regional_bound = t < label.size() && label[t] != 0 && regions[label[t] - 1].max_area > 0
                                                     ? regions[label[t] - 1].max_area
                                                     : std::numeric_limits<double>::infinity();
                   const auto within = [&](double bound) {
                     return twice <= 2.0 * bound * (1.0 + 1e-12) + 32.0 * u * longest2;
                   };
                   double bound = bound_at.least();
                   if (0.5 * twice > bound_at.least()) {
                     const Point g = triangle_centroid(a, b, c);
                     const double low = linked ? edge_from_neighbours(m, t, g, slope, edge, begin) : 0.0;
                     if (low > 0.0 && within(std::min(bound_at.area_of_field_edge(low), regional_bound))) continue;
                     if (linked) {
                       edge[t - begin] = bound_at.field_edge_at(g, &hint);
                       bound = bound_at.area_of_field_edge(edge[t - begin]);
                     } else {
                       bound = bound_at.area_at(g, &hint);
                     }
                   }
                   bound = std::min(bound, regional_bound);
                   if (!(bound < std::numeric_limits<double>::infinity())) continue;
                   if (!within(bound))
                     part_log.add(mesh_triangle_text(m, t) + " has area " + number_text(0.5 * twice) +
                                  ", above the size bound " + number_text(bound) +
                                  " at its centroid (the smallest of the size bound and its region's)");
                 }
               });
}

// The angle measure is smallest_angle_deg (quality/mesh_angle.hpp), the one
// the mesher's shortfall count must use too; a triangle counts when it is
// below min_triangle_angle_deg by more than mesh_angle_slack_deg.
void check_mesh_angles(const Mesh& m, ProblemLog& log, unsigned threads) {
  const double below = m.min_triangle_angle_deg - mesh_angle_slack_deg;
  std::size_t count = 0;
  double worst = std::numeric_limits<double>::infinity();
  std::uint32_t worst_t = no_index;
  const auto& P = m.points;
  const std::size_t claimed = m.shortfall.total();
  // Counted on the threads in chunks; most triangles are shown to be above
  // the bound without an atan2 (well_above_bound).
  if (below > 0.0) {
    const bool fast = below >= 1.0;
    const double tangent = std::tan((below + 1e-6) * std::numbers::pi / 180.0);
    constexpr std::size_t chunk = 1 << 14;
    const std::size_t nt = m.triangles.size(), chunks = (nt + chunk - 1) / chunk;
    std::vector<std::size_t> counts(chunks, 0);
    for_each_on_threads(chunks, threads, [&](std::size_t c) {
      for (std::size_t t = c * chunk; t < std::min(nt, (c + 1) * chunk); ++t) {
        const Point a = P[m.triangles[t][0]], b = P[m.triangles[t][1]], c3 = P[m.triangles[t][2]];
        if (fast && well_above_bound(a, b, c3, tangent)) continue;
        counts[c] += smallest_angle_deg(a, b, c3) < below ? 1 : 0;
      }
    });
    for (const std::size_t k : counts) count += k;
  }
  if (count == claimed) return;
  // A wrong count (a failed check): every angle, to name the smallest.
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const double angle = smallest_angle_deg(P[m.triangles[t][0]], P[m.triangles[t][1]], P[m.triangles[t][2]]);
    if (angle < worst) {
      worst = angle;
      worst_t = t;
    }
  }
  std::string text = std::to_string(count) + " triangles have a smallest angle below the bound " +
                     number_text(m.min_triangle_angle_deg) + " deg, but the shortfall counts " +
                     std::to_string(claimed) + " (" + std::to_string(m.shortfall.input_angle) + " input angle, " +
                     std::to_string(m.shortfall.separator) + " separator, " + std::to_string(m.shortfall.precision) +
                     " precision, " + std::to_string(m.shortfall.limit) + " limit)";
  if (worst_t != no_index)
    text += "; the smallest angle is " + number_text(worst) + " deg, of " + mesh_triangle_text(m, worst_t);
  log.add(text);
}

}  // namespace madd::detail
