// Final C1 check on the committed subdivision: every corner of every face
// where a separator meets anything must be >= Phi0. It recomputes the angles
// from the stored rings, independently of how the splits chose them, so a
// violation can never be returned silently.
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

#include "kernel/angles.hpp"
#include "madd/error.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

namespace {

[[noreturn]] void fail_angle(const Subdivision& sub, std::uint32_t f, double angle, double separator_angle_deg) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "subdomain %u has a new angle of %.6g degrees < %g (internal error)", f, angle,
                separator_angle_deg);
  throw DecompositionError(buf, f, sub.face_area(f), separator_angle_deg);
}

// The interior pieces of face f inside a corner of its rings split that
// corner: each one next to a separator of the corner makes a new angle with
// it (a separator crosses an interior segment only at a vertex, on both sides).
void check_inner_angles(const Subdivision& sub, std::uint32_t f, double separator_angle_deg, double bound) {
  const Face& face = sub.faces[f];
  if (face.inner_segments.empty()) return;
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> inner_at;  // vertex -> far ends of interior pieces
  for (const std::uint32_t seg : face.inner_segments) {
    inner_at[sub.segments[seg].a].push_back(sub.segments[seg].b);
    inner_at[sub.segments[seg].b].push_back(sub.segments[seg].a);
  }
  for (std::size_t r = 0; r < face.rings.size(); ++r) {
    const auto& ring = face.rings[r];
    const auto& segs = face.ring_segments[r];
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const auto it = inner_at.find(ring[k]);
      if (it == inner_at.end()) continue;
      const std::size_t before = (k + n - 1) % n;
      const bool out_new = sub.origin[segs[k]] == no_index, in_new = sub.origin[segs[before]] == no_index;
      if (!out_new && !in_new) continue;
      const Point v = sub.points[ring[k]], next = sub.points[ring[(k + 1) % n]], prev = sub.points[ring[before]];
      const double corner = ccw_angle_deg(v, next, prev);
      for (const std::uint32_t w : it->second) {
        const double from_out = ccw_angle_deg(v, next, sub.points[w]);
        const double to_in = ccw_angle_deg(v, sub.points[w], prev);
        if (std::abs(from_out + to_in - corner) > 1e-6) continue;  // in another corner at this vertex
        if (out_new && from_out < bound) fail_angle(sub, f, from_out, separator_angle_deg);
        if (in_new && to_in < bound) fail_angle(sub, f, to_in, separator_angle_deg);
      }
    }
  }
}

}  // namespace

void check_new_angles(const Subdivision& sub, double separator_angle_deg) {
  constexpr double tolerance_deg = angle_rounding_bound_deg;  // the splits keep a margin far above it
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    check_inner_angles(sub, f, separator_angle_deg, separator_angle_deg - tolerance_deg);
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
        if (angle < separator_angle_deg - tolerance_deg) fail_angle(sub, f, angle, separator_angle_deg);
      }
    }
  }
}

}  // namespace madd::detail
