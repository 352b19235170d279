// verify_decomposition(): recomputes every validity invariant of docs/quality.md
// from the decomposition and the input domain, trusting neither.
#include <algorithm>
#include <cmath>

#include "kernel/exact_sum.hpp"
#include "kernel/number_format.hpp"
#include "kernel/rings.hpp"
#include "pslg/validate_detail.hpp"
#include "madd/decomposition.hpp"
#include "quality/metrics_detail.hpp"
#include "quality/verify_decomposition_detail.hpp"
#include "triangulation/exact_area.hpp"

namespace madd {

namespace {

using detail::ExactSum;
using detail::Orientation;
using detail::ProblemLog;
using detail::RingLocation;
using detail::RingView;
using detail::locate_in_ring;
using detail::point_text;

std::string sub_name(std::size_t s) { return "subdomain " + std::to_string(s); }

// Index ranges and sizes; everything after relies on these.
bool check_structure(const Decomposition& d, const Pslg& domain, ProblemLog& log) {
  const std::size_t before = log.count();
  const auto np = d.points.size();
  if (d.segment_origin.size() != d.segments.size()) log.add("segment_origin and segments differ in size");
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const Segment& g = d.segments[s];
    if (g.a >= np || g.b >= np || g.a == g.b) log.add("segment " + std::to_string(s) + " has bad endpoints");
    if (s < d.segment_origin.size() && d.segment_origin[s] != no_index && d.segment_origin[s] >= domain.segments.size())
      log.add("segment " + std::to_string(s) + " comes from a nonexistent input segment");
  }
  if (np < domain.points.size() || !std::equal(domain.points.begin(), domain.points.end(), d.points.begin()))
    log.add("the input points are not the first points, with the same indices");
  if (d.holes != domain.holes) log.add("the hole points differ from the input's");
  if (d.regions != domain.regions) log.add("the regions differ from the input's");
  for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
    const Subdomain& sub = d.subdomains[s];
    if (sub.rings.empty() || sub.ring_segments.size() != sub.rings.size()) {
      log.add(sub_name(s) + " has no rings, or rings and ring_segments differ in count");
      continue;
    }
    if (!std::all_of(sub.interior_segments.begin(), sub.interior_segments.end(),
                     [&](std::uint32_t g) { return g < d.segments.size(); }) ||
        !std::all_of(sub.interior_points.begin(), sub.interior_points.end(),
                     [&](std::uint32_t p) { return p < domain.points.size(); }))
      log.add(sub_name(s) + " names an interior segment or point out of range");
    if (sub.hole_points.size() + 1 != sub.rings.size())
      log.add(sub_name(s) + " has " + std::to_string(sub.rings.size() - 1) + " hole rings but " +
              std::to_string(sub.hole_points.size()) + " hole points");
    for (std::size_t r = 0; r < sub.rings.size(); ++r) {
      const auto& ring = sub.rings[r];
      const auto& segs = sub.ring_segments[r];
      const bool ok = ring.size() >= 3 && segs.size() == ring.size() &&
                      std::all_of(ring.begin(), ring.end(), [&](std::uint32_t p) { return p < np; }) &&
                      std::all_of(segs.begin(), segs.end(), [&](std::uint32_t g) { return g < d.segments.size(); });
      if (!ok) log.add(sub_name(s) + " ring " + std::to_string(r) + " is malformed (size or index out of range)");
    }
  }
  return log.count() == before;
}

struct Use {
  std::uint32_t subdomain;
  bool forward;  // walked from segment.a to segment.b
};

// The stored area is rings_area of the subdomain's rings, computed in floating
// point; it must equal the exact area up to that computation's own error bound
// (kernel/rings.cpp derives it). A tolerance relative to the domain's area
// would be both too loose for a small subdomain and, for a needle far from the
// origin, too tight for the rounding of a long ring.
void check_area_claim(const Decomposition& d, std::uint32_t s, const ExactSum& twice, ProblemLog& log) {
  const Subdomain& sub = d.subdomains[s];
  bool ok = std::isfinite(2.0 * sub.area);
  if (ok) {
    ExactSum error = twice;
    error.add(-2.0 * sub.area);  // exact: doubling a finite double (well inside the range)
    ok = error.magnitude_at_most(2.0 * detail::rings_area_error(d.points, sub.rings));
  }
  if (!ok)
    log.add(sub_name(s) + " claims area " + detail::number_text(sub.area) + " but its rings enclose " +
            detail::number_text(0.5 * twice.approximate()));
}

// Rings closed and consistent with their segments; one CCW outer ring with CW
// holes inside it ("connected"); areas as claimed. Returns the uses of each
// segment; adds twice each subdomain's area, exactly, to `covered`.
std::vector<std::vector<Use>> check_rings(const Decomposition& d, ExactSum& covered, ProblemLog& log) {
  std::vector<std::vector<Use>> uses(d.segments.size());
  for (std::uint32_t s = 0; s < d.subdomains.size(); ++s) {
    const Subdomain& sub = d.subdomains[s];
    ExactSum twice;
    for (std::size_t r = 0; r < sub.rings.size(); ++r) {
      const auto& ring = sub.rings[r];
      const std::size_t n = ring.size();
      for (std::size_t k = 0; k < n; ++k) {
        const Segment& g = d.segments[sub.ring_segments[r][k]];
        const std::uint32_t p = ring[k], q = ring[(k + 1) % n];
        if (!((g.a == p && g.b == q) || (g.a == q && g.b == p))) {
          log.add(sub_name(s) + " ring " + std::to_string(r) + " position " + std::to_string(k) + ": segment " +
                  std::to_string(sub.ring_segments[r][k]) + " does not join its ring vertices");
          continue;
        }
        uses[sub.ring_segments[r][k]].push_back({s, g.a == p});
      }
      twice.add(detail::ring_twice_area_exact(RingView(d.points, ring)));
      const Orientation turn = detail::ring_orientation(RingView(d.points, ring));
      if (r == 0 && turn != Orientation::counter_clockwise)
        log.add(sub_name(s) + " outer ring is not counter-clockwise");
      if (r > 0 && turn != Orientation::clockwise)
        log.add(sub_name(s) + " hole ring " + std::to_string(r) + " is not clockwise");
      if (r > 0) {
        const Point probe = midpoint(d.points[ring[0]], d.points[ring[1]]);
        if (locate_in_ring(RingView(d.points, sub.rings[0]), probe) == RingLocation::outside)
          log.add(sub_name(s) + " hole ring " + std::to_string(r) +
                  " lies outside its outer ring (not one connected polygon)");
        // A hole inside another hole would be a second, separate piece. Quadratic
        // in the hole count, so only checked where that stays cheap.
        for (std::size_t q = 1; q < sub.rings.size() && sub.rings.size() <= 1000; ++q)
          if (q != r && locate_in_ring(RingView(d.points, sub.rings[q]), probe) == RingLocation::inside)
            log.add(sub_name(s) + " hole ring " + std::to_string(r) + " lies inside hole ring " + std::to_string(q) +
                    " (not one connected polygon)");
      }
    }
    check_area_claim(d, s, twice, log);
    covered.add(twice);
  }
  return uses;
}

// Conforming: a separator in exactly two rings of different subdomains in
// opposite directions, a boundary piece in exactly one, an interior piece in
// none and in the interior segments of exactly one subdomain.
void check_uses(const Decomposition& d, const std::vector<std::vector<Use>>& uses, ProblemLog& log) {
  std::vector<std::uint32_t> interior_of(d.segments.size(), 0);
  for (const Subdomain& sub : d.subdomains)
    for (const std::uint32_t g : sub.interior_segments) ++interior_of[g];
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    const auto& u = uses[g];
    if (interior_of[g] != 0) {
      if (d.is_separator(g) || interior_of[g] != 1 || !u.empty())
        log.add("interior segment " + std::to_string(g) + " " + point_text(d.points[d.segments[g].a]) + "-" +
                point_text(d.points[d.segments[g].b]) + " is in " + std::to_string(interior_of[g]) +
                " subdomains' interior segments and " + std::to_string(u.size()) +
                " rings (an interior piece of an input segment is in one subdomain's, and in no ring)");
      continue;
    }
    const std::string name = "segment " + std::to_string(g) + " " + point_text(d.points[d.segments[g].a]) + "-" +
                             point_text(d.points[d.segments[g].b]);
    if (d.is_separator(g)) {
      if (u.size() != 2)
        log.add("separator " + name + " is in " + std::to_string(u.size()) + " subdomain rings instead of 2");
      else if (u[0].forward == u[1].forward || u[0].subdomain == u[1].subdomain)
        log.add("separator " + name + " is not walked in opposite directions by two different subdomains");
    } else if (u.size() != 1) {
      log.add("boundary piece " + name + " is in " + std::to_string(u.size()) + " subdomain rings instead of 1");
    }
  }
}

// Every point on a segment, or one of the input's isolated vertices, named by
// exactly one subdomain; no two points at the same place.
void check_points(const Decomposition& d, const Pslg& domain, ProblemLog& log) {
  std::vector<std::uint8_t> used(d.points.size(), 0);
  for (const Segment& g : d.segments) used[g.a] = used[g.b] = 1;
  // On an input segment: an endpoint, or inside one (the segment is split there).
  std::vector<std::uint8_t> on_input(domain.points.size(), 1);
  const detail::DomainPieces pieces = detail::trace_domain_pieces(domain, detail::has_vertex_inside_segment(domain));
  for (const std::uint32_t p : pieces.isolated) on_input[p] = 0;
  std::vector<std::uint32_t> named(domain.points.size(), 0);
  for (const Subdomain& sub : d.subdomains)
    for (const std::uint32_t p : sub.interior_points) ++named[p];
  for (std::size_t p = 0; p < domain.points.size(); ++p) {
    const std::uint32_t want = on_input[p] ? 0 : 1;
    if (named[p] != want)
      log.add("point " + std::to_string(p) + " " + point_text(d.points[p]) + " is an interior point of " +
              std::to_string(named[p]) + " subdomains instead of " + std::to_string(want) +
              (want ? " (it is on no input segment)" : " (it is on an input segment)"));
    if (!on_input[p]) used[p] = 1;
  }
  for (std::size_t p = 0; p < d.points.size(); ++p)
    if (used[p] == 0) log.add("point " + std::to_string(p) + " " + point_text(d.points[p]) + " is on no segment");
  std::vector<std::uint32_t> order(d.points.size());
  for (std::uint32_t p = 0; p < order.size(); ++p) order[p] = p;
  const auto less = [&](std::uint32_t i, std::uint32_t j) {
    return d.points[i].x < d.points[j].x || (d.points[i].x == d.points[j].x && d.points[i].y < d.points[j].y);
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t k = 1; k < order.size(); ++k)
    if (d.points[order[k]] == d.points[order[k - 1]])
      log.add("points " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]) + " coincide at " +
              point_text(d.points[order[k]]));
}

bool strictly_inside(const Decomposition& d, const Subdomain& sub, Point p) {
  bool inside = locate_in_ring(RingView(d.points, sub.rings[0]), p) == RingLocation::inside;
  for (std::size_t r = 1; r < sub.rings.size() && inside; ++r)
    inside = locate_in_ring(RingView(d.points, sub.rings[r]), p) == RingLocation::outside;
  return inside;
}

// interior_point strictly inside the subdomain; each hole point strictly
// inside its hole ring; its interior segments (their midpoints; they cross no
// ring, check_segments_disjoint) and isolated points strictly inside it.
void check_inner_points(const Decomposition& d, ProblemLog& log) {
  for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
    const Subdomain& sub = d.subdomains[s];
    if (!strictly_inside(d, sub, sub.interior_point))
      log.add(sub_name(s) + " interior point " + point_text(sub.interior_point) + " is not strictly inside it");
    for (const std::uint32_t g : sub.interior_segments) {
      const Point mid = midpoint(d.points[d.segments[g].a], d.points[d.segments[g].b]);
      if (!strictly_inside(d, sub, mid))
        log.add(sub_name(s) + " interior segment " + std::to_string(g) + " is not inside it (midpoint " +
                point_text(mid) + ")");
    }
    for (const std::uint32_t p : sub.interior_points)
      if (!strictly_inside(d, sub, d.points[p]))
        log.add(sub_name(s) + " interior point " + std::to_string(p) + " " + point_text(d.points[p]) +
                " is not strictly inside it");
    for (std::size_t h = 0; h < sub.hole_points.size() && h + 1 < sub.rings.size(); ++h)
      if (locate_in_ring(RingView(d.points, sub.rings[h + 1]), sub.hole_points[h]) != RingLocation::inside)
        log.add(sub_name(s) + " hole point " + point_text(sub.hole_points[h]) + " is not strictly inside hole ring " +
                std::to_string(h + 1));
  }
}

void check_angles(const Decomposition& d, ProblemLog& log) {
  // Phi0 less what computing the angle of the stored points can be off by.
  const double bound = d.separator_angle_deg - detail::angle_rounding_bound_deg;
  detail::for_each_new_angle(d, [&](std::uint32_t s, std::uint32_t r, std::uint32_t k, double angle) {
    if (angle < bound)
      log.add(sub_name(s) + " has a new angle of " + detail::number_text(angle) + " deg < " +
              detail::number_text(d.separator_angle_deg) + " at " + point_text(d.points[d.subdomains[s].rings[r][k]]));
  });
}

// Full cover: twice the area the subdomains cover against twice the domain's,
// both exact, so the only difference a correct decomposition can show is the
// area between the boundary pieces and their input segments, which
// check_boundary_pieces bounds (twice, `sliver`; 0 when every boundary vertex
// lies exactly on its segment). Summing floating-point ring areas instead and
// allowing a relative 1e-9 failed correct decompositions: of a unit triangle
// near (1e9, 1e9), whose rounded boundary vertices cut off slivers of 1.7e-8
// of its area, and of the issue 13 needle (1.2e-6, docs/hostile.md).
void check_cover(const ExactSum& covered, const ExactSum& domain, double sliver, ProblemLog& log) {
  ExactSum difference = covered;
  difference.subtract(domain);
  if (difference.magnitude_at_most(sliver)) return;
  log.add("the subdomains' areas add up to " + detail::number_text(0.5 * covered.approximate()) +
          " but the domain's is " + detail::number_text(0.5 * domain.approximate()) +
          ": a gap or an overlap (they differ by " + detail::number_text(0.5 * difference.approximate()) +
          ", more than the " + detail::number_text(0.5 * sliver) +
          " the rounding of boundary vertices can account for)");
}

}  // namespace

Verification verify_decomposition(const Decomposition& d, const Pslg& domain, std::uint32_t expected_count) {
  Verification result;
  ProblemLog log(result);
  if (d.subdomains.size() != expected_count)
    log.add("expected " + std::to_string(expected_count) + " subdomains, found " + std::to_string(d.subdomains.size()));
  if (!check_structure(d, domain, log)) {
    log.finish();
    return result;
  }
  ExactSum covered;
  const auto uses = check_rings(d, covered, log);
  check_uses(d, uses, log);
  const double sliver = detail::check_boundary_pieces(d, domain, log);
  check_points(d, domain, log);
  detail::check_segments_disjoint(d.points, d.segments, log);
  check_inner_points(d, log);
  check_angles(d, log);
  check_cover(covered, detail::domain_twice_area_exact(domain), sliver, log);
  log.finish();
  return result;
}

}  // namespace madd
