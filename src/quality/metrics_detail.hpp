#pragma once
// The new angles of a decomposition, shared by metrics(), verify_decomposition()
// and the SVG output.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "kernel/angles.hpp"
#include "madd/decomposition.hpp"

namespace madd::detail {

// Interior angle in degrees, in [0, 360), at `at` of a ring walked with the
// interior on its left (outer rings CCW, hole rings CW): the counter-clockwise
// turn from the outgoing edge to the reversed incoming edge.
// Whether it passes 180 is decided exactly (ccw_angle_deg), so a corner of
// almost 0 degrees is never taken for one of almost 360.
inline double interior_angle_deg(Point prev, Point at, Point next) { return ccw_angle_deg(at, next, prev); }

// Calls f(subdomain, ring, k, angle_deg) for every corner k of every ring
// where the incoming or the outgoing segment is a separator (a "new angle").
template <class F>
void for_each_new_angle(const Decomposition& d, F&& f) {
  for (std::uint32_t s = 0; s < d.subdomains.size(); ++s) {
    const Subdomain& sub = d.subdomains[s];
    for (std::uint32_t r = 0; r < sub.rings.size(); ++r) {
      const auto& ring = sub.rings[r];
      const auto& segs = sub.ring_segments[r];
      const std::size_t n = ring.size();
      if (n < 3 || segs.size() != n) continue;
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t in = segs[(k + n - 1) % n];
        const std::uint32_t out = segs[k];
        if (!d.is_separator(in) && !d.is_separator(out)) continue;
        const double angle =
            interior_angle_deg(d.points[ring[(k + n - 1) % n]], d.points[ring[k]], d.points[ring[(k + 1) % n]]);
        f(s, r, static_cast<std::uint32_t>(k), angle);
      }
    }
  }
}

} // namespace madd::detail
