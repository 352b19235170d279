// Interior constraints in the decomposition (docs/algorithm.md, "Interior
// segments"): every kind of interior segment and isolated vertex stays inside
// exactly one subdomain, a separator meets one only at a vertex, at angles
// >= Phi0 on both sides, and nothing depends on the thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/geometry.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"

namespace {

using madd::Decomposition;
using madd::Point;
using madd::Pslg;

// A 4 x 2 rectangle holding every kind of interior constraint.
Pslg constrained_rectangle() {
  Pslg p;
  p.points = {{0, 0},     {4, 0},     {4, 2},     {0, 2}, {0.5, 0.5}, {1.2, 0.9}, {1.5, 1.6},  // 4-6: an open polyline
              {2.4, 0.4}, {3.2, 0.4}, {2.8, 1.0},  // 7-9: a closed loop (a region)
              {2.0, 2.0}, {2.1, 1.4},              // 10-11: a segment from the boundary
              {3.0, 1.6}, {3.6, 1.6}, {3.3, 1.2},  // 12-14: a T: 14-15 ends on 12-13,
              {3.3, 1.6},                          // 15: at a vertex inside it
              {1.0, 0.2}, {0.6, 1.6}};             // 16-17: isolated vertices
  p.segments = {
      {0, 1, 1}, {1, 2, 1}, {2, 3, 1},   {3, 0, 1},   {4, 5, 2},   {5, 6, 2}, {7, 8, 3},
      {8, 9, 3}, {9, 7, 3}, {10, 11, 4}, {12, 13, 5}, {15, 14, 5}, {5, 11, 6}};  // a Y at 5 (with 4-5, 5-6); joins the
                                                                                 // boundary segment's end
  p.has_segment_markers = true;
  p.regions.push_back({{2.8, 0.6}, 7.0, 0.01});
  return p;
}

double length(const Decomposition& d, std::uint32_t s) {
  return madd::distance(d.points[d.segments[s].a], d.points[d.segments[s].b]);
}

bool inside(const Decomposition& d, const madd::Subdomain& s, Point p) {
  const auto in_ring = [&](const std::vector<std::uint32_t>& ring) {  // crossing number, brute force
    bool c = false;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point a = d.points[ring[k]], b = d.points[ring[(k + 1) % ring.size()]];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) c = !c;
    }
    return c;
  };
  if (!in_ring(s.rings[0])) return false;
  for (std::size_t r = 1; r < s.rings.size(); ++r)
    if (in_ring(s.rings[r])) return false;
  return true;
}

void check_interior(const Decomposition& d, const Pslg& domain, std::uint32_t n, double phi) {
  const madd::Verification verification = madd::verify_decomposition(d, domain, n);
  for (const auto& problem : verification.problems) INFO(problem);
  REQUIRE(verification.ok());
  // Per input segment with the domain on both sides: its pieces, all interior, sum to its length.
  std::vector<int> owners(d.segments.size(), 0);
  for (const madd::Subdomain& s : d.subdomains)
    for (const std::uint32_t g : s.interior_segments) {
      ++owners[g];
      const Point mid = madd::midpoint(d.points[d.segments[g].a], d.points[d.segments[g].b]);
      CHECK(inside(d, s, mid));
    }
  std::map<std::uint32_t, double> interior_length;
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    CHECK(owners[g] <= 1);
    if (owners[g] == 1) {
      CHECK(!d.is_separator(g));
      const int marker = domain.segments[d.segment_origin[g]].marker;
      CHECK(d.segments[g].marker == (domain.has_segment_markers && marker != 0 ? marker : 1));
      interior_length[d.segment_origin[g]] += length(d, g);
    }
  }
  for (const auto& [input, total] : interior_length) {
    const madd::Segment& s = domain.segments[input];
    CHECK(total == doctest::Approx(madd::distance(domain.points[s.a], domain.points[s.b])).epsilon(1e-12));
  }
  // Every isolated input vertex in exactly one subdomain, inside it.
  std::vector<int> degree(domain.points.size(), 0);
  for (const madd::Segment& s : domain.segments) ++degree[s.a], ++degree[s.b];
  std::vector<int> named(domain.points.size(), 0);
  for (const madd::Subdomain& s : d.subdomains)
    for (const std::uint32_t p : s.interior_points) {
      ++named[p];
      CHECK(inside(d, s, d.points[p]));
    }
  for (std::size_t p = 0; p < domain.points.size(); ++p) {
    bool on_segment = degree[p] > 0;
    for (const madd::Segment& s : domain.segments)
      on_segment = on_segment || (madd::orient2d(domain.points[s.a], domain.points[s.b], domain.points[p]) == 0.0 &&
                                  madd::distance(domain.points[s.a], domain.points[p]) +
                                          madd::distance(domain.points[p], domain.points[s.b]) <=
                                      madd::distance(domain.points[s.a], domain.points[s.b]) * (1 + 1e-15));
    CHECK(named[p] == (on_segment ? 0 : 1));
  }
  // No separator passes through an isolated vertex (exact).
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    if (!d.is_separator(g)) continue;
    for (std::size_t p = 0; p < domain.points.size(); ++p) {
      if (named[p] == 0) continue;
      const Point a = d.points[d.segments[g].a], b = d.points[d.segments[g].b], q = d.points[p];
      const bool on = madd::orient2d(a, b, q) == 0.0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
                      std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
      CHECK(!on);
    }
  }
  // Every separator meeting an interior piece at a vertex makes an angle >= Phi0 with it.
  std::map<std::uint32_t, std::vector<std::uint32_t>> separator_ends, interior_ends;
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    auto& at = d.is_separator(g) ? separator_ends : interior_ends;
    if (!d.is_separator(g) && owners[g] == 0) continue;
    at[d.segments[g].a].push_back(d.segments[g].b);
    at[d.segments[g].b].push_back(d.segments[g].a);
  }
  int crossings = 0;
  for (const auto& [v, seps] : separator_ends) {
    const auto it = interior_ends.find(v);
    if (it == interior_ends.end()) continue;
    ++crossings;
    for (const std::uint32_t s : seps)
      for (const std::uint32_t w : it->second)
        CHECK(madd::degrees(madd::angle_at(d.points[v], d.points[s], d.points[w])) >= phi - 1e-7);
  }
  MESSAGE("N " << n << " Phi0 " << phi << ": " << crossings << " crossings");
}

madd::DecomposeOptions options(std::uint32_t n, double phi = 60.0, unsigned threads = 0) {
  madd::DecomposeOptions o;
  o.subdomains = n;
  o.separator_angle_deg = phi;
  o.threads = threads;
  return o;
}

}  // namespace

TEST_SUITE("interior") {

TEST_CASE("every kind of interior constraint stays inside one subdomain, crossed only at vertices at >= Phi0") {
  const Pslg domain = constrained_rectangle();
  madd::validate(domain);
  for (const double phi : {60.0, 70.0}) {
    for (const std::uint32_t n : {2u, 5u, 16u}) {
      CAPTURE(phi);
      CAPTURE(n);
      madd::DecomposeOptions o = options(n, phi, 1);
      const Decomposition one = madd::decompose(domain, o);
      check_interior(one, domain, n, phi);
      CHECK(one.regions == domain.regions);
      o.threads = 3;
      CHECK(madd::decompose(domain, o) == one);  // bit-identical for any thread count
    }
  }
}

TEST_CASE("the bundled estuary: lanes, a levee with a spur, a groyne, a loop, survey points") {
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/estuary.poly");
  for (const double phi : {60.0, 70.0}) {
    for (const std::uint32_t n : {2u, 16u, 64u}) {
      CAPTURE(phi);
      CAPTURE(n);
      check_interior(madd::decompose(domain, options(n, phi)), domain, n, phi);
    }
  }
}

TEST_CASE("a separator crossing a lane splits it at the crossing vertex, on both sides") {
  // A lane across the middle of a long rectangle: every split must cross it.
  Pslg p;
  p.points = {{0, 0}, {4, 0}, {4, 1}, {0, 1}, {2, 0.1}, {2, 0.9}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 1}};
  const Decomposition d = madd::decompose(p, options(8));
  check_interior(d, p, 8, 60.0);
  std::size_t lane_pieces = 0;
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) lane_pieces += d.segment_origin[g] == 4 ? 1 : 0;
  CHECK(lane_pieces >= 2);  // crossed at least once
}

TEST_CASE("separators pass through the loose ends of lanes, which would otherwise wall off their fans") {
  // A 6 x 3 rectangle with nine short lanes in a grid: in a triangulation with
  // no interior points the fans around their ends cover most of the face.
  Pslg p;
  p.points = {{0, 0}, {6, 0}, {6, 3}, {0, 3}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double x = 1.0 + 2.0 * i, y = 0.5 + 1.0 * j;
      const auto a = static_cast<std::uint32_t>(p.points.size());
      p.points.push_back({x - 0.3, y});
      p.points.push_back({x + 0.3, y + 0.1});
      p.segments.push_back({a, a + 1, 2});
    }
  p.has_segment_markers = true;
  std::size_t through = 0;
  for (const std::uint32_t n : {4u, 16u, 64u}) {
    CAPTURE(n);
    const Decomposition d = madd::decompose(p, options(n));
    check_interior(d, p, n, 60.0);
    double largest = 0.0;
    for (const madd::Subdomain& s : d.subdomains) largest = std::max(largest, s.area);
    CHECK(largest * n / 18.0 <= 1.25);
    std::vector<int> separator_ends(d.points.size(), 0);
    for (std::uint32_t g = 0; g < d.segments.size(); ++g)
      if (d.is_separator(g)) ++separator_ends[d.segments[g].a], ++separator_ends[d.segments[g].b];
    for (std::uint32_t v = 4; v < p.points.size(); ++v) through += separator_ends[v] >= 2 ? 1 : 0;
  }
  CHECK(through >= 1);  // the rule is exercised
}

TEST_CASE("a square with a stub from its side and a survey point still halves evenly (the chord fallback)") {
  // The medial separators of a near-square face cut off about a third; the
  // chord that halves it must miss the stub and the point, and may not end
  // where the stub meets the side.
  Pslg p;
  p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.4}, {0.3, 0.4}, {0.7, 0.7}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 4, 1}, {4, 0, 1}, {4, 5, 2}};
  p.has_segment_markers = true;
  for (const std::uint32_t n : {2u, 3u}) {
    CAPTURE(n);
    const Decomposition d = madd::decompose(p, options(n));
    check_interior(d, p, n, 60.0);
    double largest = 0.0;
    for (const madd::Subdomain& s : d.subdomains) largest = std::max(largest, s.area);
    CHECK(largest * n <= 1.1);  // area 1
  }
}

}  // TEST_SUITE("interior")
