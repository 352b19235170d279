// Final C1 check on the committed subdivision: every corner of every face
// where a separator meets anything must be >= Phi0. It recomputes the angles
// from the stored rings, independently of how the splits chose them, so a
// violation can never be returned silently.
#include <cstdio>

#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

namespace {
// Interior angle (degrees) at v between the ring edges to prev and next; the face is on the left.
double interior_angle(Point v, Point prev, Point next) {
  const double base = degrees(angle_at(v, next, prev));
  return orient2d(v, next, prev) < 0.0 ? 360.0 - base : base;
}
} // namespace

void check_new_angles(const Subdivision& sub, double min_angle_deg) {
  constexpr double tolerance_deg = 1e-7;
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    const Face& face = sub.faces[f];
    for (std::size_t r = 0; r < face.rings.size(); ++r) {
      const auto& ring = face.rings[r];
      const auto& segs = face.ring_segments[r];
      const std::size_t n = ring.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t before = (k + n - 1) % n;
        if (sub.origin[segs[before]] != no_index && sub.origin[segs[k]] != no_index) continue;
        const double angle =
            interior_angle(sub.points[ring[k]], sub.points[ring[before]], sub.points[ring[(k + 1) % n]]);
        if (angle < min_angle_deg - tolerance_deg) {
          char buf[200];
          std::snprintf(buf, sizeof buf, "subdomain %u has a new angle of %.6g degrees < %g (internal error)", f,
                        angle, min_angle_deg);
          throw DecompositionError(buf, f, sub.face_area(f), min_angle_deg);
        }
      }
    }
  }
}

} // namespace madd::detail
