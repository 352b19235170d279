// Tests of the kernel's exact sums (src/kernel/exact_sum.hpp) against the big
// integers of predicates_reference.hpp, and of the rounding-error bounds of
// ring areas (src/kernel/rings.hpp) against exact areas.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernel/bracket.hpp"
#include "kernel/exact_sum.hpp"
#include "kernel/rings.hpp"
#include "madd/predicates.hpp"
#include "predicates_reference.hpp"

namespace {

using madd::Point;
using madd::detail::ExactSum;
using madd::detail::RingView;

struct Product {
  double a, b;
};

// The exact sign of sum a_i b_i, by big integers: every factor is scaled by
// one common power of two.
int reference_sign(const std::vector<Product>& terms) {
  namespace ref = madd::test_ref;
  int base = 1 << 20;
  for (const Product& t : terms)
    for (const double v : {t.a, t.b})
      if (v != 0.0) base = std::min(base, ref::exponent_of(v));
  ref::Big sum;
  for (const Product& t : terms) sum = sum + ref::to_big(t.a, base) * ref::to_big(t.b, base);
  return ref::sign(sum);
}

// A double of random sign whose exponent is uniform in [-lo, lo].
double random_double(std::mt19937_64& rng, int lo) {
  std::uniform_real_distribution<double> m(1.0, 2.0);
  std::uniform_int_distribution<int> e(-lo, lo);
  return std::ldexp(m(rng), e(rng)) * (rng() % 2 ? 1.0 : -1.0);
}

}  // namespace

TEST_SUITE("exact_sum") {

TEST_CASE("exact_sum: signs of sums of products match big integers, also when they nearly cancel") {
  std::mt19937_64 rng(13);
  for (int round = 0; round < 2000; ++round) {
    std::vector<Product> terms;
    const int n = 1 + round % 40;
    for (int i = 0; i < n; ++i) terms.push_back({random_double(rng, 1 + round % 80), random_double(rng, 30)});
    // Make the sum nearly cancel: the last term takes away the rounded sum of the others.
    if (round % 2 == 0) {
      double rounded = 0.0;
      for (const Product& t : terms) rounded += t.a * t.b;
      terms.push_back({-rounded, 1.0});
    }
    ExactSum s;
    for (const Product& t : terms) s.add_product(t.a, t.b);
    CAPTURE(round);
    CHECK(s.sign() == reference_sign(terms));
    // Taking the same terms away in another order leaves exactly nothing.
    std::shuffle(terms.begin(), terms.end(), rng);
    for (const Product& t : terms) s.add_product(-t.a, t.b);
    CHECK(s.is_zero());
  }
}

TEST_CASE("exact_sum: a long sum of products of coordinates near 1e9 cancels exactly to zero") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(1e9, 1e9 + 1.0);
  std::vector<Product> terms(200000);
  for (Product& t : terms) t = {u(rng), u(rng)};
  ExactSum s;
  for (const Product& t : terms) s.add_product(t.a, t.b);
  CHECK(s.approximate() == doctest::Approx(2e23).epsilon(1e-6));
  for (std::size_t i = terms.size(); i-- > 0;) s.add_product(-terms[i].a, terms[i].b);
  CHECK(s.is_zero());
}

TEST_CASE("exact_sum: magnitude_at_most decides |sum| <= bound exactly, on either side of zero") {
  for (const double sign : {1.0, -1.0}) {
    ExactSum s;
    s.add(sign);
    s.add(sign * 0x1p-80);  // |sum| = 1 + 2^-80, between 1 and the next double
    CHECK_FALSE(s.magnitude_at_most(1.0));
    CHECK(s.magnitude_at_most(std::nextafter(1.0, 2.0)));
    CHECK(s.sign() == static_cast<int>(sign));
    CHECK(s.approximate() == sign);
    CHECK(s.magnitude_bound() >= 1.0);
    CHECK(s.magnitude_bound() <= 1.0 + 1e-15);
  }
  ExactSum zero;
  CHECK(zero.magnitude_at_most(0.0));
  zero.add_product(3.0, 0.1);
  zero.add_product(-0.1, 3.0);
  CHECK(zero.is_zero());
  CHECK(zero.sign() == 0);
}

TEST_CASE("exact_sum: twice a triangle's area has orient2d's sign on nearly collinear triangles far from the origin") {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> small(-1000, 1000);
  int zeros = 0;
  for (int round = 0; round < 20000; ++round) {
    // a, b and c = a + s (b - a) / 4 on an integer grid near 2^10 .. 2^40, so
    // exactly collinear; then c is nudged by 0 to 3 ulps.
    const double offset = std::ldexp(1.0, 10 + round % 31);
    const Point a{offset + small(rng), offset + small(rng)};
    const double dx = small(rng), dy = small(rng);
    const Point b{a.x + 4 * dx, a.y + 4 * dy};
    const double steps = 1 + round % 3;
    Point c{a.x + steps * dx, a.y + steps * dy};
    for (int nudge = 0; nudge < round % 4; ++nudge) c.x = std::nextafter(c.x, round % 8 < 4 ? 0.0 : 1e300);
    const double o = madd::orient2d(a, b, c);
    const int want = o > 0 ? 1 : (o < 0 ? -1 : 0);
    zeros += want == 0;
    CHECK(madd::detail::triangle_twice_area_exact(a, b, c).sign() == want);
    // c lies between a and b along b - a (up to its nudge across the line).
    if (dx != 0 || dy != 0) CHECK(madd::detail::dot_of_differences_exact(c, a, b, a).sign() > 0);
  }
  CHECK(zeros > 1000);  // exactly collinear cases did occur
}

TEST_CASE("bracket: the exact value lies in the filter's interval; decisive answers agree with the exact ones") {
  // Random and nearly degenerate (collinear, nudged by ulps) configurations
  // far from the origin: every exact value within estimate +- error, and the
  // filter decisive on most random ones.
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> small(-1000, 1000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided = 0, undecided_degenerate = 0;
  const auto within = [](const madd::detail::Bracket& q, const ExactSum& exact) {
    // |exact - estimate| <= error, decided exactly.
    ExactSum difference = exact;
    difference.add(-q.estimate);
    return difference.magnitude_at_most(q.error);
  };
  for (int round = 0; round < 20000; ++round) {
    const double offset = std::ldexp(1.0, round % 41);
    Point a{offset + small(rng), offset + small(rng)}, b{a.x + 4.0 * small(rng), a.y + 4.0 * small(rng)};
    Point c = round % 2 == 0 ? Point{a.x + (b.x - a.x) / 4 * (1 + round % 3), a.y + (b.y - a.y) / 4 * (1 + round % 3)}
                             : Point{offset * (1 + unit(rng)), offset * (1 + unit(rng))};
    for (int nudge = 0; nudge < round % 3; ++nudge) c.y = std::nextafter(c.y, 1e300);
    const madd::detail::Bracket area = madd::detail::triangle_twice_area_bracket(a, b, c);
    const ExactSum exact_area = madd::detail::triangle_twice_area_exact(a, b, c);
    REQUIRE(within(area, exact_area));
    CHECK(exact_area.magnitude_at_most(area.magnitude_bound()));
    const double some = std::abs(exact_area.approximate()) * unit(rng) * 2.0;
    const double bound = std::abs(some);
    if (area.certainly_at_most(bound)) CHECK(exact_area.magnitude_at_most(bound));
    if (area.certainly_above(bound)) CHECK(!exact_area.magnitude_at_most(bound));
    const madd::detail::Bracket along = madd::detail::dot_of_differences_bracket(c, a, b, a);
    const ExactSum exact_along = madd::detail::dot_of_differences_exact(c, a, b, a);
    REQUIRE(within(along, exact_along));
    if (along.certainly_positive()) CHECK(exact_along.sign() > 0);
    CHECK(exact_along.magnitude_at_most(along.magnitude_bound()));
    if (round % 2 == 1) decided += along.certainly_positive() || exact_along.sign() <= 0 ? 1 : 0;
    if (round % 2 == 0 && exact_area.is_zero()) undecided_degenerate += area.certainly_above(0.0) ? 0 : 1;
  }
  CHECK(decided > 9900);               // random points: the filter decides (nearly) all
  CHECK(undecided_degenerate > 1000);  // exactly collinear: never wrongly decided away from zero
}

TEST_CASE("rings: ring_signed_area and rings_area stay within their error bounds, on needles far from the origin") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int round = 0; round < 500; ++round) {
    // A needle: a long spike from a small base, with a zigzag along the base.
    const double offset = std::ldexp(1.0, round % 37), length = std::ldexp(1.0, 10 + round % 27);
    const double angle = 6.283 * u(rng), width = 1e-3 + u(rng);
    std::vector<Point> ring{{offset + length * std::cos(angle), offset + length * std::sin(angle)}};
    const int base_points = 2 + round % 30;
    for (int k = 0; k < base_points; ++k) {
      const double across = width * k / (base_points - 1), back = (k % 2) * width * 0.1;
      ring.push_back({offset + across * std::sin(angle) - back * std::cos(angle),
                      offset - across * std::cos(angle) - back * std::sin(angle)});
    }
    CAPTURE(round);
    const double area = madd::detail::ring_signed_area(RingView(ring));
    const double bound = madd::detail::ring_signed_area_error(RingView(ring));
    ExactSum error = madd::detail::ring_twice_area_exact(RingView(ring));
    error.add(-2.0 * area);
    CHECK(error.magnitude_at_most(2.0 * bound));
    // With a hole (the same needle shrunk towards its base, clockwise), through rings_area.
    std::vector<Point> points = ring;
    std::vector<std::vector<std::uint32_t>> rings(2);
    for (std::uint32_t k = 0; k < ring.size(); ++k) rings[0].push_back(k);
    for (std::size_t k = ring.size(); k-- > 0;) {
      rings[1].push_back(static_cast<std::uint32_t>(points.size()));
      points.push_back({ring[1].x + 0.5 * (ring[k].x - ring[1].x), ring[1].y + 0.5 * (ring[k].y - ring[1].y)});
    }
    const double total = madd::detail::rings_area(points, rings);
    ExactSum total_error = madd::detail::ring_twice_area_exact(RingView(points, rings[0]));
    total_error.add(madd::detail::ring_twice_area_exact(RingView(points, rings[1])));
    total_error.add(-2.0 * total);
    CHECK(total_error.magnitude_at_most(2.0 * madd::detail::rings_area_error(points, rings)));
  }
  // Not vacuous where there is nothing to cancel: a unit square at the origin.
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  CHECK(madd::detail::ring_signed_area_error(RingView(square)) < 1e-15);
}

}  // TEST_SUITE("exact_sum")
