// Separator smoothing (paper Sec. 5.1): with it, more separator ends land on
// existing ends, and validity and C1 hold either way.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "medial/medial_detail.hpp"
#include "smoothing_measure.hpp"

namespace {

madd::test::SmoothingFigures run(const madd::Pslg& domain, std::uint32_t n, int iterations, unsigned threads = 1) {
  madd::DecomposeOptions o;
  o.subdomains = n;
  o.smoothing_iterations = iterations;
  o.threads = threads;
  const madd::Decomposition d = madd::decompose(domain, o);
  const madd::Verification v = madd::verify_decomposition(d, domain, n);
  for (const auto& p : v.problems) INFO(p);
  CHECK(v.ok());
  const auto f = madd::test::smoothing_figures(d, domain.points.size());
  CHECK(f.min_angle >= o.separator_angle_deg);
  return f;
}

}  // namespace

TEST_SUITE("smoothing") {

TEST_CASE("smoothing puts at least as many separator ends on existing ends") {
  for (const char* name : {"pipe.poly", "key.poly"}) {
    CAPTURE(name);
    const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name);
    const auto off = run(domain, 64, 0);
    const auto on = run(domain, 64, 1);
    INFO("off " << off.on_existing << " (" << off.ends << " ends), on " << on.on_existing << " (" << on.ends << ")");
    CHECK(on.on_existing >= off.on_existing);
    CHECK(on.ends > 0);
  }
}

TEST_CASE("smoothed decompositions stay valid, with C1, for several N and iterations") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/pipe.poly");
  for (std::uint32_t n : {2u, 7u, 33u, 200u}) {
    for (int iterations : {1, 3}) {
      CAPTURE(n);
      CAPTURE(iterations);
      run(domain, n, iterations);
    }
  }
}

TEST_CASE("smoothing is deterministic across thread counts") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  madd::DecomposeOptions o;
  o.subdomains = 100;
  o.smoothing_iterations = 2;
  o.threads = 1;
  const madd::Decomposition one = madd::decompose(domain, o);
  o.threads = 2;
  CHECK(one == madd::decompose(domain, o));
}

}  // TEST_SUITE("smoothing")

namespace {

double point_segment_distance(madd::Point p, madd::Point a, madd::Point b) {
  const double vx = b.x - a.x, vy = b.y - a.y, len2 = vx * vx + vy * vy;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * vx + (p.y - a.y) * vy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * vx), p.y - (a.y + t * vy));
}

// The distance from the middle 80% of separator a-b to segment p-q, by
// sampling the middle densely (brute force, independent of hugs_separator).
double middle_clearance(madd::Point a, madd::Point b, madd::Point p, madd::Point q) {
  double best = INFINITY;
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.1 + 0.8 * k / 400.0;
    best = std::min(best, point_segment_distance({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, p, q));
  }
  return best;
}

}  // namespace

TEST_SUITE("smoothing") {
TEST_CASE("hugs_separator: a boundary edge or point a hair from a separator's middle, not one at its ends") {
  using madd::detail::hugs_separator;
  const madd::Point a{0, 0}, b{0, 1};
  CHECK(hugs_separator(a, b, {0.005, 0.2}, {0.005, 0.8}));          // alongside, 0.5% away
  CHECK(hugs_separator(a, b, {0.005, -5}, {0.005, 5}));             // a long edge, no corner near
  CHECK(hugs_separator(a, b, {0.008, 0.5}, {0.008, 0.5}));          // a point
  CHECK(hugs_separator(a, b, {-1, 0.5}, {1, 0.5}));                 // crossing
  CHECK_FALSE(hugs_separator(a, b, {0.05, 0.2}, {0.05, 0.8}));      // 5% away
  CHECK_FALSE(hugs_separator(a, b, {0, 1}, {1, 1.02}));             // the edge at its end, at 89 degrees
  CHECK_FALSE(hugs_separator(a, b, {0.001, 0.02}, {0.001, 0.02}));  // a point by its end
}

TEST_CASE("no separator runs alongside the boundary a hair from it, with smoothing moving the ends") {
  // On Lake Ladoga, moving a separator's ends along the coast made a chord
  // 1.15 long 5e-4 from a coast segment (35,000 triangles in its strip).
  for (const std::string name : {"archipelago.poly", "estuary.poly", "spiral.poly", "key.poly", "pipe.poly"}) {
    const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name);
    for (std::uint32_t n : {16u, 64u}) {
      for (int iterations : {1, 3}) {
        madd::DecomposeOptions o;
        o.subdomains = n;
        o.smoothing_iterations = iterations;
        const madd::Decomposition d = madd::decompose(domain, o);
        // The boundary: neither separators nor interior segments (a separator
        // may cross those, or pass by a loose end of one).
        std::vector<bool> interior(d.segments.size(), false);
        for (const madd::Subdomain& sub : d.subdomains)
          for (const std::uint32_t k : sub.interior_segments) interior[k] = true;
        for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
          if (!d.is_separator(j)) continue;
          const madd::Segment s = d.segments[j];
          const madd::Point a = d.points[s.a], b = d.points[s.b];
          for (std::uint32_t k = 0; k < d.segments.size(); ++k) {
            const madd::Segment t = d.segments[k];
            if (d.is_separator(k) || interior[k] || t.a == s.a || t.a == s.b || t.b == s.a || t.b == s.b) continue;
            const double clearance = middle_clearance(a, b, d.points[t.a], d.points[t.b]);
            CAPTURE(name);
            CAPTURE(n);
            CAPTURE(j);
            CAPTURE(k);
            REQUIRE(clearance >= 0.005 * std::hypot(b.x - a.x, b.y - a.y));
          }
        }
      }
    }
  }
}
}
