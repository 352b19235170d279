// The expected triangle count of a subdomain (docs/mesh.md, "Balance by
// work"): its area over the mean triangle area a size bound A gives, plus,
// for every boundary piece shorter than the edge A allows, the triangles of
// the graded layer that grows from the piece's length to that edge:
//
//   T = area / (kappa A) + sum over pieces of (1 + nu ln(max(1, e_A / L))),
//
// e_A = sqrt(4 A / sqrt 3) the edge of an equilateral triangle of area A.
// A layer whose triangles grow geometrically from L to e_A holds a number of
// triangles proportional to ln(e_A / L) per unit of piece (Ruppert's
// size-optimality: the count is the integral of 1 / lfs^2).
#include "mesh/work.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/mesh.hpp"

namespace madd::detail {

namespace {

// docs/mesh.md, "Balance by work": the mean triangle area of a
// mesh refined to an area bound A, over A; and the triangles one graded layer
// adds per factor e of size change along one piece.
constexpr double kappa = 0.64;
constexpr double nu = 2.0;
// Balance by work only when the boundary's triangles are at least this
// share of the interior's (below it the area says as much).
constexpr double boundary_share_for_work = 0.1;

double piece_work(Point a, Point b, double area_bound, double fallback_edge) {
  const double length = distance(a, b);
  const double edge = std::isfinite(area_bound) ? std::sqrt(4.0 * area_bound / std::sqrt(3.0)) : fallback_edge;
  return 1.0 + nu * std::log(std::max(1.0, edge / std::max(length, std::numeric_limits<double>::min())));
}

} // namespace

std::vector<double> expected_triangles(const Decomposition& d, const SizeField& size) {
  std::vector<double> out;
  out.reserve(d.subdomains.size());
  for (const Subdomain& s : d.subdomains) {
    const double bound = size.area_at(s.interior_point);
    double t = std::isfinite(bound) ? s.area / (kappa * bound) : 0.0;
    const double fallback = std::sqrt(s.area);
    for (const auto& ring : s.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Point a = d.points[ring[k]], b = d.points[ring[(k + 1) % ring.size()]];
        t += piece_work(a, b, size.area_at(midpoint(a, b)), fallback);
      }
    }
    out.push_back(t);
  }
  return out;
}

void weigh_by_work(DecomposeOptions& options, const Pslg& domain, const SizeField& size) {
  if (options.weight_function || !options.background_weights.empty() || options.gradation > 0 ||
      options.area_function || !options.background_areas.empty())
    return;
  // The input boundary, discretised as the mesh will discretise it.
  Decomposition boundary;
  boundary.points = domain.points;
  boundary.segments = domain.segments;
  boundary.segment_origin.resize(domain.segments.size());
  for (std::uint32_t j = 0; j < domain.segments.size(); ++j) boundary.segment_origin[j] = j;
  const Decomposition pieces = discretise(boundary, size.options());
  const double area = domain_area(domain);
  const double fallback = std::sqrt(area / std::max<double>(1, options.subdomains));
  // Each piece's work, at its midpoint, in units of area: kappa A per
  // triangle where there is a size bound, so the decomposition's area term
  // (refine x area, Sec. 5.2) counts the interior triangles; without one
  // the boundary is the whole work, scaled to drown the area term.
  std::vector<ValuedPoint> samples;
  samples.reserve(pieces.segments.size());
  double total = 0;
  for (const Segment& s : pieces.segments) {
    const Point a = pieces.points[s.a], b = pieces.points[s.b], m = midpoint(a, b);
    const double bound = size.area_at(m);
    const double w = piece_work(a, b, bound, fallback);
    samples.push_back({m, std::isfinite(bound) ? w * kappa * bound : w});
    total += w;
  }
  // Where the boundary adds little to the interior's triangles, the area is
  // as good a measure of work, and an area-balanced decomposition is
  // rebalanced (DecomposeOptions::rebalance_above) where a graded one is
  // not: keep the areas then.
  const double interior = size.bounded() && std::isfinite(size.area_at(samples.empty() ? Point{} : samples[0].at))
                              ? area / (kappa * size.area_at(samples[0].at))
                              : 0.0;
  if (size.bounded() && total < boundary_share_for_work * interior) return;
  if (!size.bounded()) {
    for (ValuedPoint& v : samples) v.value *= 100.0 * area / std::max(total, 1.0);
  }
  options.background_weights = std::move(samples);
  options.gradation = options.refine;
}

std::size_t steiner_budget(double expected_triangles, std::size_t ring_vertices) {
  // Generous: ten times the expected triangles, with a floor for meshes
  // whose estimate is small. Hitting it is reported, never silent.
  return static_cast<std::size_t>(std::min(4e9, 10.0 * expected_triangles + 20.0 * static_cast<double>(ring_vertices) + 1e5));
}

} // namespace madd::detail
