// metrics() on hand-made decompositions with known figures, and
// verify_decomposition() on good and deliberately broken ones.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/rings.hpp"
#include "madd/metrics.hpp"
#include "madd/predicates.hpp"
#include "quality/decile.hpp"
#include "quality/metrics_detail.hpp"
#include "metrics_fixtures.hpp"

namespace {

using namespace madd;
using madd::detail::decile;
using madd::test::Fixture;

bool mentions(const Verification& v, const std::string& text) {
  return std::any_of(v.problems.begin(), v.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

std::string all_problems(const Verification& v) {
  std::string s;
  for (const auto& p : v.problems) s += p + "\n";
  return s;
}

}  // namespace

TEST_SUITE("metrics") {

TEST_CASE("square split at x = 0.5: four right angles, separator length 1, balanced") {
  const Fixture f = test::square_halves();
  const Metrics m = metrics(f.decomposition);
  CHECK(m.subdomains == 2);
  CHECK(m.separator_segments == 1);
  CHECK(m.new_angles == 4);
  CHECK(m.angle_min == doctest::Approx(90));
  CHECK(m.angle_p10 == doctest::Approx(90));
  CHECK(m.angle_median == doctest::Approx(90));
  CHECK(m.angle_p90 == doctest::Approx(90));
  CHECK(m.boundary_angles == 4);
  CHECK(m.boundary_angle_median == doctest::Approx(90));
  CHECK(m.domain_area == doctest::Approx(1));
  CHECK(m.separator_length == doctest::Approx(1));
  CHECK(m.separator_length_norm == doctest::Approx(1));
  CHECK(m.mean_separator_per_subdomain == doctest::Approx(1));
  CHECK(m.max_separator_over_area_norm == doctest::Approx(2 * std::sqrt(0.5)));
  CHECK(m.max_area_over_mean == doctest::Approx(1));
  CHECK(m.min_area_over_mean == doctest::Approx(1));
  CHECK(m.max_weight_over_mean == doctest::Approx(1));
  // The split boundary pieces (length 0.5) are the shortest new segments.
  CHECK(m.shortest_new_segment_norm == doctest::Approx(0.5 / std::sqrt(0.5)));
}

TEST_CASE("quadrants: twelve right angles, eight of them on the boundary") {
  const Metrics m = metrics(test::square_quadrants().decomposition);
  CHECK(m.new_angles == 12);
  CHECK(m.boundary_angles == 8);
  CHECK(m.angle_min == doctest::Approx(90));
  CHECK(m.separator_length == doctest::Approx(2));
  CHECK(m.mean_separator_per_subdomain == doctest::Approx(1));
  CHECK(m.max_area_over_mean == doctest::Approx(1));
}

TEST_CASE("annulus halves and the surrounded square") {
  const Metrics a = metrics(test::annulus_halves().decomposition);
  CHECK(a.domain_area == doctest::Approx(12));
  CHECK(a.new_angles == 8);
  CHECK(a.angle_min == doctest::Approx(90));
  CHECK(a.separator_length == doctest::Approx(2));

  const Metrics s = metrics(test::surrounded().decomposition);
  CHECK(s.domain_area == doctest::Approx(9));
  CHECK(s.new_angles == 8);  // 4 x 270 deg seen from outside, 4 x 90 from inside
  CHECK(s.angle_min == doctest::Approx(90));
  CHECK(s.angle_median == doctest::Approx(180));
  CHECK(s.boundary_angles == 0);
  CHECK(std::isnan(s.boundary_angle_median));
  CHECK(s.max_area_over_mean == doctest::Approx(8.0 / 4.5));
  CHECK(s.min_area_over_mean == doctest::Approx(1.0 / 4.5));
}

TEST_CASE("deciles follow Python's statistics.quantiles exclusive method") {
  // statistics.quantiles([1,2,3,4,5,6,7,8,9,10], n=10) = [1.1, 2.2, ..., 9.9]
  std::vector<double> v{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  CHECK(decile(v, 1) == doctest::Approx(1.1));
  CHECK(decile(v, 5) == doctest::Approx(5.5));
  CHECK(decile(v, 9) == doctest::Approx(9.9));
  // statistics.quantiles([10, 20, 30], n=10) = [4.0, 8.0, ..., 36.0]: Python
  // extrapolates beyond the data for small samples, and so do we (ddcheck.py agrees).
  std::vector<double> w{10, 20, 30};
  CHECK(decile(w, 1) == doctest::Approx(4));
  CHECK(decile(w, 9) == doctest::Approx(36));
  CHECK(std::isnan(decile({5}, 1)));
}

TEST_CASE("verify_decomposition accepts every hand-made decomposition") {
  for (const Fixture& f : test::all_fixtures()) {
    const Verification v =
        verify_decomposition(f.decomposition, f.domain, static_cast<std::uint32_t>(f.decomposition.subdomains.size()));
    INFO(all_problems(v));
    CHECK(v.ok());
  }
}

TEST_CASE("verify_decomposition: wrong count") {
  const Fixture f = test::square_halves();
  const Verification v = verify_decomposition(f.decomposition, f.domain, 3);
  CHECK(mentions(v, "expected 3 subdomains, found 2"));
}

TEST_CASE("verify_decomposition: crossing separators (overlap)") {
  // Two triangles over the unit square whose diagonals cross.
  const Fixture f = test::make_fixture({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {},
                                       {{{{0, 1, 2}}, {0.8, 0.2}, {}}, {{{1, 3, 0}}, {0.2, 0.2}, {}}});
  const Verification v = verify_decomposition(f.decomposition, f.domain, 2);
  INFO(all_problems(v));
  CHECK(mentions(v, "cross"));
}

TEST_CASE("verify_decomposition: a separator without its twin") {
  Fixture f = test::square_halves();
  Decomposition& d = f.decomposition;
  // Subdomain 1 walks its own copy of the separator instead of sharing it.
  const auto it = std::find(d.segment_origin.begin(), d.segment_origin.end(), no_index);
  const auto sep = static_cast<std::uint32_t>(it - d.segment_origin.begin());
  d.segments.push_back(d.segments[sep]);
  d.segment_origin.push_back(no_index);
  for (auto& s : d.subdomains[1].ring_segments[0])
    if (s == sep) s = static_cast<std::uint32_t>(d.segments.size() - 1);
  const Verification v = verify_decomposition(d, f.domain, 2);
  INFO(all_problems(v));
  CHECK(mentions(v, "in 1 subdomain rings instead of 2"));
}

TEST_CASE("verify_decomposition: T-junction") {
  // Right half split again at y = 0.5; the left half does not know the new vertex.
  const Fixture f = test::make_fixture(
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {0.5, 1}, {0.5, 0.5}, {1, 0.5}}, 4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
      {}, {{{{0, 4, 5, 3}}, {0.25, 0.5}, {}}, {{{4, 1, 7, 6}}, {0.75, 0.25}, {}}, {{{6, 7, 2, 5}}, {0.75, 0.75}, {}}});
  const Verification v = verify_decomposition(f.decomposition, f.domain, 3);
  INFO(all_problems(v));
  CHECK(mentions(v, "T-junction"));
}

TEST_CASE("verify_decomposition: an angle below the bound") {
  // Slanted separator from (0.3, 0) to (0.7, 1): angles of about 68.2 and 111.8 deg.
  Fixture f =
      test::make_fixture({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.3, 0}, {0.7, 1}}, 4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {},
                         {{{{0, 4, 5, 3}}, {0.2, 0.5}, {}}, {{{4, 1, 2, 5}}, {0.8, 0.5}, {}}});
  f.decomposition.separator_angle_deg = 60;
  CHECK(verify_decomposition(f.decomposition, f.domain, 2).ok());
  f.decomposition.separator_angle_deg = 70;
  const Verification v = verify_decomposition(f.decomposition, f.domain, 2);
  CHECK(mentions(v, "new angle of 68.19"));
  const Metrics m = metrics(f.decomposition);
  CHECK(m.angle_min == doctest::Approx(std::atan2(1.0, 0.4) * 180 / M_PI));
}

TEST_CASE("verify_decomposition: interior point, hole point, orientation, area") {
  Fixture f = test::rectangle_with_hole();
  f.decomposition.subdomains[1].interior_point = {0.5, 0.5};  // inside subdomain 0's hole
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "interior point"));

  f = test::rectangle_with_hole();
  f.decomposition.subdomains[0].hole_points[0] = {0.1, 0.1};
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "hole point"));

  f = test::square_halves();
  std::reverse(f.decomposition.subdomains[0].rings[0].begin(), f.decomposition.subdomains[0].rings[0].end());
  CHECK(!verify_decomposition(f.decomposition, f.domain, 2).ok());

  f = test::square_halves();
  f.decomposition.subdomains[0].area = 0.4;
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "claims area"));
}

TEST_CASE("verify_decomposition: a hole ring outside the outer ring, or inside another hole") {
  // Subdomain 0 of "surrounded" claims the square [4,5]^2 (far outside) as a hole.
  Fixture f = test::surrounded();
  Decomposition& d = f.decomposition;
  const auto base = static_cast<std::uint32_t>(d.points.size());
  for (const Point p : {Point{4, 4}, Point{4, 5}, Point{5, 5}, Point{5, 4}}) d.points.push_back(p);
  std::vector<std::uint32_t> ring{base, base + 1, base + 2, base + 3}, segs;
  for (std::uint32_t k = 0; k < 4; ++k) {
    d.segments.push_back({ring[k], ring[(k + 1) % 4], 0});
    d.segment_origin.push_back(no_index);
    segs.push_back(static_cast<std::uint32_t>(d.segments.size() - 1));
  }
  d.subdomains[0].rings.push_back(ring);
  d.subdomains[0].ring_segments.push_back(segs);
  d.subdomains[0].hole_points.push_back({4.5, 4.5});
  CHECK(mentions(verify_decomposition(d, f.domain, 2), "lies outside its outer ring"));

  // Now a hole [1.25,1.75]^2 inside the hole [1,2]^2 of subdomain 0.
  f = test::surrounded();
  Decomposition& e = f.decomposition;
  const auto first = static_cast<std::uint32_t>(e.points.size());
  for (const Point p : {Point{1.25, 1.25}, Point{1.25, 1.75}, Point{1.75, 1.75}, Point{1.75, 1.25}})
    e.points.push_back(p);
  ring = {first, first + 1, first + 2, first + 3};
  segs.clear();
  for (std::uint32_t k = 0; k < 4; ++k) {
    e.segments.push_back({ring[k], ring[(k + 1) % 4], 0});
    e.segment_origin.push_back(no_index);
    segs.push_back(static_cast<std::uint32_t>(e.segments.size() - 1));
  }
  e.subdomains[0].rings.push_back(ring);
  e.subdomains[0].ring_segments.push_back(segs);
  e.subdomains[0].hole_points.push_back({1.5, 1.5});
  CHECK(mentions(verify_decomposition(e, f.domain, 2), "lies inside hole ring 1"));
}

TEST_CASE("verify_decomposition: a gap is not full cover") {
  // Only the left half of the square is present.
  Fixture f = test::square_halves();
  f.decomposition.subdomains.pop_back();
  const Verification v = verify_decomposition(f.decomposition, f.domain, 1);
  INFO(all_problems(v));
  CHECK(mentions(v, "gap or an overlap"));
  CHECK(mentions(v, "instead of 2"));
}

TEST_CASE("verify_decomposition: a stored area must match its rings within rings_area's own error bound") {
  // 1e-12 off: far below the former tolerance of 1e-9 of the domain's area,
  // far above what rings_area can round to on the unit square.
  Fixture f = test::square_halves();
  REQUIRE(verify_decomposition(f.decomposition, f.domain, 2).ok());
  f.decomposition.subdomains[0].area += 1e-12;
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "claims area"));
}

// A unit triangle near (1e9, 1e9) cut from a vertex interpolated on its
// sloping side (as src/split/refine.cpp places them) to the opposite corner:
// the vertex is rounded off the side by ~1e-8, which the former fixed
// tolerance of 1e-9 sqrt(area) rejected, as it did the sliver of area between
// the two halves and the triangle (more than a relative 1e-9).
Fixture triangle_far_away(Point shift) {
  const double o = 1e9;
  const Point a{o, o}, b{o + 1, o + 0.3}, c{o + 0.4, o + 1};
  const Point m = lerp(a, b, 0.6) + shift;
  Fixture f = test::make_fixture(
      {a, b, c, m}, 3, {{0, 1}, {1, 2}, {2, 0}}, {},
      {{{{0, 3, 2}}, triangle_centroid(a, m, c), {}}, {{{3, 1, 2}}, triangle_centroid(m, b, c), {}}});
  Decomposition& d = f.decomposition;
  // make_fixture finds pieces by exact incidence, which m misses: a-m and m-b are pieces of side 0.
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    const std::uint32_t lo = std::min(d.segments[g].a, d.segments[g].b),
                        hi = std::max(d.segments[g].a, d.segments[g].b);
    if (hi == 3 && lo <= 1) {
      d.segment_origin[g] = 0;
      d.segments[g].marker = 1;
    }
  }
  for (Subdomain& sub : d.subdomains) sub.area = sub.weight = detail::rings_area(d.points, sub.rings);
  d.separator_angle_deg = 20;  // the cut makes angles of 26.9 and 35.5 degrees at c
  return f;
}

TEST_CASE("verify_decomposition: a vertex rounded off a sloping side far from the origin is accepted; farther off it "
          "is not") {
  const Fixture rounded = triangle_far_away({0, 0});
  REQUIRE(orient2d(rounded.domain.points[0], rounded.domain.points[1], rounded.decomposition.points[3]) != 0.0);
  const Verification v = verify_decomposition(rounded.decomposition, rounded.domain, 2);
  INFO(all_problems(v));
  CHECK(v.ok());
  // 1e-5 across the side: no interpolation rounds that far at 1e9 (bound ~6e-7).
  const Fixture moved = triangle_far_away({-3e-6, 1e-5});
  const Verification w = verify_decomposition(moved.decomposition, moved.domain, 2);
  INFO(all_problems(w));
  CHECK(mentions(w, "leaves input segment 0"));
}

TEST_CASE("verify_decomposition: the pieces of an input segment form one chain from its first end to its second") {
  // The separator x = 0.5 of square_halves passed off as a piece of the bottom side.
  Fixture f = test::square_halves();
  Decomposition& d = f.decomposition;
  for (std::uint32_t g = 0; g < d.segments.size(); ++g)
    if (d.is_separator(g)) {
      d.segment_origin[g] = 0;
      d.segments[g].marker = 1;
    }
  const Verification v = verify_decomposition(d, f.domain, 2);
  INFO(all_problems(v));
  CHECK(mentions(v, "leaves input segment 0"));
  CHECK(mentions(v, "pieces branch at (0.5, 0)"));
}

TEST_CASE("verify_decomposition: wrong marker and malformed indices do not crash") {
  Fixture f = test::square_halves();
  f.decomposition.segments[0].marker = 7;
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "marker"));
  f = test::square_halves();
  f.decomposition.subdomains[0].rings[0][1] = 999;
  CHECK(mentions(verify_decomposition(f.decomposition, f.domain, 2), "malformed"));
}

}  // TEST_SUITE("metrics")

// The new-angle measure decides the side of 180 degrees exactly: near a
// straight corner the rounded cross product can have the wrong sign, which
// would read a corner of almost 0 degrees as one of almost 360 (and the
// reverse). On Shewchuk's ulp grid around (0.5, 0.5) with (12, 12) and (24, 24)
// such points exist; for each, the angle must agree with orient2d.
TEST_SUITE("metrics") {

TEST_CASE("new angles: the side of 180 degrees follows orient2d where the rounded cross product errs") {
  const madd::Point next{12.0, 12.0}, prev{24.0, 24.0};
  int wrong_sign = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const madd::Point at{std::nextafter(0.5, 1.0) + i * 0x1p-53, 0.5 + j * 0x1p-53};
      const madd::Point u{next.x - at.x, next.y - at.y}, v{prev.x - at.x, prev.y - at.y};
      const double naive = u.x * v.y - u.y * v.x;
      const double exact = madd::orient2d(at, next, prev);
      if (exact == 0.0) continue;
      if ((naive > 0.0) != (exact > 0.0)) ++wrong_sign;
      const double angle = madd::detail::interior_angle_deg(prev, at, next);
      CHECK((exact > 0.0) == (angle < 180.0));
    }
  }
  REQUIRE(wrong_sign > 0);  // the grid does hold such points, so the test is not vacuous
}

}  // TEST_SUITE("metrics")
