// C3, balance: the largest subdomain stays close to the mean. Near-square
// faces, whose medial axis is an X, are where the partial separators of the
// circumcentre approximation alone cannot balance a split (docs/algorithm.md,
// "Balance"); the chord fallback must, without giving up validity or C1.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "decomposition_check.hpp"
#include "split/chord.hpp"
#include "split/refine.hpp"
#include "subdivision/subdivision.hpp"

namespace {

using madd::Point;
using madd::Pslg;

Pslg ring(const std::vector<Point>& pts) {
  Pslg p;
  p.first_index = 0;
  const auto n = static_cast<std::uint32_t>(pts.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    p.points.push_back(pts[i]);
    p.segments.push_back({i, (i + 1) % n, 0});
  }
  return p;
}

// The unit square, each corner moved by up to 8% of the side: an X-shaped medial axis.
Pslg near_square(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  return ring({{0 + jitter(rng), 0 + jitter(rng)},
               {1 + jitter(rng), 0 + jitter(rng)},
               {1 + jitter(rng), 1 + jitter(rng)},
               {0 + jitter(rng), 1 + jitter(rng)}});
}

madd::Metrics checked(const Pslg& domain, std::uint32_t n, double min_angle = 60.0) {
  return madd::test::checked_decomposition(domain, n, min_angle);
}

}  // namespace

TEST_SUITE("balance") {

TEST_CASE("near-square quadrilaterals split in two nearly equal halves") {
  // Corners jittered by up to 8% of the side: every one is an X-shaped medial
  // axis, and a chord between two opposite sides balances it within a few percent.
  std::mt19937_64 rng(7);
  for (int k = 0; k < 20; ++k) {
    CAPTURE(k);
    const Pslg quad = near_square(rng);
    const madd::Metrics m = checked(quad, 2);
    CHECK(m.max_area_over_mean <= 1.06);
  }
}

// Graded by background weights (Sec. 5.2, case 2, as madd mesh balances
// expected triangles), the chord fallback weighs a side as the bisection
// does: the weight of the samples inside it. Each side's samples are summed
// here by a point-in-polygon test of its own.
TEST_CASE("near-square quadrilaterals graded by weight samples split in two nearly equal weights") {
  std::mt19937_64 rng(11);
  std::vector<madd::ValuedPoint> samples;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const Point at{(i + 0.5) / 40.0, (j + 0.5) / 40.0};
      samples.push_back({at, 1.0 + 4.0 * at.x * at.x});  // five times heavier at x = 1
    }
  for (int k = 0; k < 12; ++k) {
    CAPTURE(k);
    const Pslg quad = near_square(rng);
    madd::DecomposeOptions options;
    options.subdomains = 2;
    options.threads = 1;
    options.weight_samples = samples;
    options.gradation = 100.0;  // the samples, not the area, decide
    const madd::Decomposition d = madd::decompose(quad, options);
    const madd::Verification check = madd::verify_decomposition(d, quad, 2);
    REQUIRE(check.ok());
    double inside[2] = {0.0, 0.0}, total = 0.0;
    for (const madd::ValuedPoint& s : samples) {
      bool in_quad = false, in_first = false;
      const auto crosses = [&](const std::vector<Point>& poly) {
        bool in = false;
        for (std::size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++)
          if ((poly[a].y > s.at.y) != (poly[b].y > s.at.y) &&
              s.at.x < poly[b].x + (poly[a].x - poly[b].x) * (s.at.y - poly[b].y) / (poly[a].y - poly[b].y))
            in = !in;
        return in;
      };
      in_quad = crosses(quad.points);
      std::vector<Point> first;
      for (const std::uint32_t v : d.subdomains[0].rings[0]) first.push_back(d.points[v]);
      in_first = crosses(first);
      if (!in_quad) continue;
      total += s.value;
      inside[in_first ? 0 : 1] += s.value;
    }
    CHECK(std::max(inside[0], inside[1]) <= 1.08 * 0.5 * total);
  }
}

// A chord keeps clear of the boundary along its middle, as every separator
// does (medial/medial_detail.hpp, hugs_separator): here the shortest chord that
// halves the rectangle would pass a hair below the tip of a spike of coast
// hanging from its top (its tip 0.5% of the chord's length above it).
TEST_CASE("the chord fallback keeps clear of a spike's tip a hair from the halving line") {
  const Pslg spiked = ring({{0, 0}, {1, 0}, {1, 1.3}, {0.31, 1.3}, {0.3, 0.652}, {0.29, 1.3}, {0, 1.3}});
  const auto sub = madd::detail::Subdivision::from_domain(spiked);
  const madd::detail::FaceDomain fd = madd::detail::refine_face(sub, 0, 0.01);
  madd::detail::ChordOptions o;
  o.min_quality = 0.5;
  const std::optional<madd::detail::Chord> chord = madd::detail::best_chord(fd, o);
  REQUIRE(chord.has_value());
  REQUIRE(chord->result.edges.size() == 1);
  const Point a = chord->result.edges[0].a.p, b = chord->result.edges[0].b.p;
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const Point tip{0.3, 0.652};
  double clearance = INFINITY;  // from the middle 80% to the tip, sampled densely
  for (int t = 0; t <= 400; ++t) {
    const double u = 0.1 + 0.8 * t / 400.0;
    clearance = std::min(clearance, std::hypot(a.x + u * (b.x - a.x) - tip.x, a.y + u * (b.y - a.y) - tip.y));
  }
  CHECK(clearance >= 0.01 * length);
  CHECK(chord->quality >= 0.9);  // and it still balances
}

// A face with islands: the chord runs from the outer ring to the outer
// ring, keeps off every island, and counts each island's area on its side.
TEST_CASE("near-square quadrilaterals with an island split in two nearly equal areas") {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> place(0.15, 0.7);
  for (int k = 0; k < 12; ++k) {
    CAPTURE(k);
    Pslg quad = near_square(rng);
    const Point at{place(rng), place(rng)};  // a speck of an island, 0.03 x 0.02, anywhere but at the edges
    const auto first = static_cast<std::uint32_t>(quad.points.size());
    for (const Point corner : {Point{0, 0}, Point{0, 0.02}, Point{0.03, 0.02}, Point{0.03, 0}})
      quad.points.push_back({at.x + corner.x, at.y + corner.y});
    for (std::uint32_t i = 0; i < 4; ++i) quad.segments.push_back({first + i, first + (i + 1) % 4, 0});
    quad.holes.push_back({at.x + 0.015, at.y + 0.01});
    CHECK(checked(quad, 2).max_area_over_mean <= 1.06);
  }
}

TEST_CASE("a square with one corner cut off balances at N = 2, 3 and 4") {
  const Pslg cut = ring({{0.3, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.3}, {0.12, 0.1}});
  for (std::uint32_t n : {2u, 3u, 4u}) {
    CAPTURE(n);
    CHECK(checked(cut, n).max_area_over_mean <= 1.1);
  }
}

TEST_CASE("a U shape: the balancing chord never crosses the notch") {
  // The straight cut through the middle would cross the notch; whatever
  // separator is chosen, verify_decomposition (inside checked) proves it lies
  // inside the domain.
  const Pslg u = ring({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.6}, {1, 0.6}, {1, 2}, {0, 2}});
  for (std::uint32_t n : {2u, 3u, 5u}) {
    CAPTURE(n);
    CHECK(checked(u, n).max_area_over_mean <= 1.3);
  }
}

TEST_CASE("at Phi0 = 70 the chord still meets the angle bound at both ends") {
  const Pslg quad = ring({{0, 0}, {1.1, 0.05}, {1, 1}, {-0.05, 0.95}});
  for (std::uint32_t n : {2u, 7u}) {
    CAPTURE(n);
    checked(quad, n, 70.0);
  }
}

TEST_CASE("C3: largest area / mean area <= 1.3 on the bundled domains") {
  for (const char* name : {"pipe.poly", "key.poly", "spiral.poly", "thin_annulus.poly", "l_shape.poly",
                           "near_collinear.poly", "comb.poly"}) {
    const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name);
    for (std::uint32_t n : {64u, 500u, 1000u}) {
      CAPTURE(name);
      CAPTURE(n);
      CHECK(checked(domain, n).max_area_over_mean <= 1.3);
    }
  }
}

// Rebalancing (docs/algorithm.md, "Rebalancing"): the cases below exceed 1.25
// without it (checked, so the test cannot pass vacuously) and must come within
// repair_balance_above x the mean with it, valid, at Phi0, separators no longer.
TEST_CASE("rebalancing brings the largest subdomain within 1.2 x the mean where splits alone cannot") {
  struct Case {
    const char* file;
    std::uint32_t n;
    double phi;
  };
  for (const Case c : {Case{"comb.poly", 16, 60.0}, Case{"estuary.poly", 16, 60.0}}) {
    CAPTURE(c.file);
    CAPTURE(c.n);
    const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + c.file);
    madd::DecomposeOptions o;
    o.subdomains = c.n;
    o.separator_angle_deg = c.phi;
    o.threads = 1;
    o.repair_balance_above = 0.0;
    const madd::Metrics off = madd::metrics(madd::decompose(domain, o));
    REQUIRE(off.max_area_over_mean > 1.25);
    o.repair_balance_above = 1.2;
    const madd::Decomposition d = madd::decompose(domain, o);
    const madd::Verification check = madd::verify_decomposition(d, domain, c.n);
    INFO((check.ok() ? std::string() : check.problems.front()));
    CHECK(check.ok());
    const madd::Metrics on = madd::metrics(d);
    CHECK(on.max_area_over_mean <= 1.2);
    CHECK(on.angle_min >= c.phi - 1e-9);
    // Each repair may add sqrt(mean area) of separator (C2): on the comb at
    // N = 16, whose teeth the splits cut at their roots (1.76 a subdomain;
    // 9.3 when chords could run lengthwise a hair from a tooth), the repairs
    // add 11% (1.95).
    CHECK(on.mean_separator_per_subdomain <= 1.15 * off.mean_separator_per_subdomain);
    // One repair at a time in a fixed order, its candidate unions tried two
    // or three at a time and weighed in order: the thread count changes nothing.
    for (const unsigned threads : {2u, 3u}) {
      o.threads = threads;
      CHECK(madd::decompose(domain, o) == d);
    }
  }
}

TEST_CASE("rebalancing changes nothing where every subdomain is within the bound") {
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  madd::DecomposeOptions o;
  o.subdomains = 64;
  o.threads = 1;
  o.repair_balance_above = 0.0;
  const madd::Decomposition off = madd::decompose(domain, o);
  const madd::Metrics m = madd::metrics(off);
  REQUIRE(m.max_area_over_mean < 1.3);
  o.repair_balance_above = m.max_area_over_mean * 1.001;  // nothing above the bound
  CHECK(madd::decompose(domain, o) == off);
}

TEST_CASE("the archipelago: within 1.25 at every N and Phi0 the sweep uses") {
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/archipelago.poly");
  for (const double phi : {60.0, 70.0}) {
    for (const std::uint32_t n : {16u, 100u, 500u, 2000u}) {
      CAPTURE(phi);
      CAPTURE(n);
      CHECK(checked(domain, n, phi).max_area_over_mean <= 1.25);
    }
  }
}

// A face with thousands of samples is searched with them merged: at most
// the given count, every one a sample of the input (so inside the face), the
// weight conserved cell by cell; a face with no more is searched as it is.
TEST_CASE("chord search: many samples are merged on a grid, their weight kept") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<madd::ValuedPoint> samples;
  for (int i = 0; i < 5000; ++i) samples.push_back({{3.0 * unit(random), unit(random)}, 0.5 + unit(random)});
  CHECK(madd::detail::merged_for_chords(samples, 5000).empty());
  const std::vector<madd::ValuedPoint> merged = madd::detail::merged_for_chords(samples, 512);
  REQUIRE(!merged.empty());
  CHECK(merged.size() <= 512);
  double total = 0.0, merged_total = 0.0, west = 0.0, merged_west = 0.0;  // west: x < 1, a cell boundary
  for (const madd::ValuedPoint& p : samples) total += p.value, west += p.at.x < 1.0 ? p.value : 0.0;
  for (const madd::ValuedPoint& p : merged) {
    CHECK(std::find_if(samples.begin(), samples.end(), [&](const madd::ValuedPoint& q) { return q.at == p.at; }) !=
          samples.end());
    merged_total += p.value;
    merged_west += p.at.x < 1.0 ? p.value : 0.0;
  }
  CHECK(merged_total == doctest::Approx(total).epsilon(1e-12));
  // A 22 x 22 grid over [0, 3]: cells 3/22 wide, so x = 1 cuts cells, and
  // the weight west of it moves by at most the cells it cuts (1/22 of it).
  CHECK(std::abs(merged_west - west) < total / 22.0);
}

}  // TEST_SUITE("balance")

TEST_CASE("rebalancing works on background weights too: the heaviest subdomain comes down, every rule kept") {
  // Weights concentrated in one corner of the pipe (a dense coastline, say):
  // the heaviest subdomain is well above the mean without the repair.
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/pipe.poly");
  madd::DecomposeOptions o;
  o.subdomains = 32;
  o.threads = 1;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const madd::Decomposition plain = madd::decompose(domain, o);
  for (const madd::Subdomain& s : plain.subdomains) {
    // One sample per subdomain interior point, heavier to the left.
    o.weight_samples.push_back({s.interior_point, (s.interior_point.x < 0 ? 20.0 : 1.0) * (1.0 + u(rng))});
  }
  o.gradation = 1.0;
  o.repair_balance_above = 0.0;
  const madd::Metrics off = madd::metrics(madd::decompose(domain, o));
  REQUIRE(off.max_weight_over_mean > 1.2);
  o.repair_balance_above = 1.1;
  const madd::Decomposition d = madd::decompose(domain, o);
  const madd::Verification check = madd::verify_decomposition(d, domain, o.subdomains);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
  const madd::Metrics on = madd::metrics(d);
  CHECK(on.max_weight_over_mean < off.max_weight_over_mean);
  CHECK(on.angle_min >= 60.0 - 1e-9);
  // The weights of the result are the samples inside each subdomain, found anew.
  double total = 0;
  for (const madd::Subdomain& s : d.subdomains) total += s.weight;
  double expected = 0;
  for (const madd::ValuedPoint& v : o.weight_samples) expected += v.value;
  CHECK(total == doctest::Approx(o.boundary_refinement * madd::domain_area(domain) + expected).epsilon(1e-9));
  for (const unsigned threads : {2u, 3u}) {
    o.threads = threads;
    CHECK(madd::decompose(domain, o) == d);
  }
}
