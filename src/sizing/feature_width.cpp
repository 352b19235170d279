// The half-width of the water at a point: half the chord from its nearest
// coast point through it (feature_width.hpp).
#include "sizing/feature_width.hpp"

#include <cmath>
#include <limits>

namespace madd::detail {

double feature_width(const Coast& coast, Point x, const SegmentIndex::Nearest& nearest, Point inward, double t_max,
                     double scale) noexcept {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (nearest.segment == no_index) return infinity;  // no coast at all
  const double eps = 1e-9 * scale;
  Point u;
  double t_min = 0.0;
  if (nearest.distance > eps) {
    u = (1.0 / nearest.distance) * (x - nearest.at);
    // Just short of x: a boundary piece through x itself (a box side) ends the chord there.
    t_min = nearest.distance * (1.0 - 1e-9);
  } else {
    if (!(length(inward) > 0.0)) inward = coast.piece_inward[coast.coast_piece[nearest.segment]];
    const double len = length(inward);
    if (!(len > 0.0)) return 0.0;  // a coast vertex whose pieces' normals cancel: a needle tip, no water across
    u = (1.0 / len) * inward;
    t_min = eps;
  }
  if (!(t_max > t_min)) return infinity;
  const SegmentIndex::Hit hit = coast.boundary_index.first_hit(nearest.at, u, t_min, t_max);
  if (hit.segment == no_index || coast.coast[coast.boundary_piece[hit.segment]] == 0) return infinity;
  return 0.5 * hit.t;
}

}  // namespace madd::detail
