#pragma once
// The new angles of a decomposition, shared by metrics(), verify_decomposition()
// and the SVG output.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
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

// Per vertex of a subdomain: the far ends of its interior pieces there.
inline std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> interior_ends(const Decomposition& d,
                                                                                   const Subdomain& sub) {
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> ends;
  for (const std::uint32_t g : sub.interior_segments) {
    if (g >= d.segments.size()) continue;
    ends[d.segments[g].a].push_back(d.segments[g].b);
    ends[d.segments[g].b].push_back(d.segments[g].a);
  }
  return ends;
}

// Calls f(subdomain, ring, k, angle_deg) for every corner k of every ring
// where the incoming or the outgoing segment is a separator (a "new angle").
// Interior pieces of the subdomain inside the corner split it: the new
// angles are then those between a separator of the corner and the interior
// piece next to it (a separator crossing an interior segment).
template <class F>
void for_each_new_angle(const Decomposition& d, F&& f) {
  for (std::uint32_t s = 0; s < d.subdomains.size(); ++s) {
    const Subdomain& sub = d.subdomains[s];
    const auto inner = interior_ends(d, sub);
    for (std::uint32_t r = 0; r < sub.rings.size(); ++r) {
      const auto& ring = sub.rings[r];
      const auto& segs = sub.ring_segments[r];
      const std::size_t n = ring.size();
      if (n < 3 || segs.size() != n) continue;
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t in = segs[(k + n - 1) % n];
        const std::uint32_t out = segs[k];
        if (!d.is_separator(in) && !d.is_separator(out)) continue;
        const Point prev = d.points[ring[(k + n - 1) % n]], at = d.points[ring[k]], next = d.points[ring[(k + 1) % n]];
        const double corner = interior_angle_deg(prev, at, next);
        double first = corner, last = 0.0;  // ccw from the outgoing edge: the nearest and the farthest piece
        if (const auto it = inner.find(ring[k]); it != inner.end()) {
          for (const std::uint32_t w : it->second) {
            const double from_out = ccw_angle_deg(at, next, d.points[w]);
            if (!(from_out > 0.0 && from_out < corner)) continue;  // in another corner at this vertex
            first = std::min(first, from_out);
            last = std::max(last, from_out);
          }
        }
        const auto kk = static_cast<std::uint32_t>(k);
        if (first == corner) {
          f(s, r, kk, corner);
          continue;
        }
        if (d.is_separator(out)) f(s, r, kk, first);
        if (d.is_separator(in)) f(s, r, kk, corner - last);
      }
    }
  }
}

}  // namespace madd::detail
