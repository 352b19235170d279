// Final C1 check on the committed subdivision: every corner of every face
// where a separator meets anything must be >= Phi0. It recomputes the angles
// from the stored rings, independently of how the splits chose them, so a
// violation can never be returned silently.
#include <cstdio>

#include "kernel/angles.hpp"
#include "madd/error.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

void check_new_angles(const Subdivision& sub, double min_angle_deg) {
  constexpr double tolerance_deg = angle_rounding_bound_deg;  // the splits keep a margin far above it
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    const Face& face = sub.faces[f];
    for (std::size_t r = 0; r < face.rings.size(); ++r) {
      const auto& ring = face.rings[r];
      const auto& segs = face.ring_segments[r];
      const std::size_t n = ring.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t before = (k + n - 1) % n;
        if (sub.origin[segs[before]] != no_index && sub.origin[segs[k]] != no_index) continue;
        // The face is on the left: its interior angle turns from the outgoing edge to the incoming one.
        const double angle =
            ccw_angle_deg(sub.points[ring[k]], sub.points[ring[(k + 1) % n]], sub.points[ring[before]]);
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
