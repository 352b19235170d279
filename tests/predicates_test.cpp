// Tests for the adaptive-exact predicates. Every sign is checked against an
// independent exact evaluation: __int128 for small integer inputs, and the
// big-integer reference of predicates_reference.hpp for arbitrary doubles.
#include "madd/predicates.hpp"

#include "predicates_reference.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

namespace {

using madd::incircle;
using madd::orient2d;
using madd::Point;

using namespace madd::test_ref;

int sgn(double v) { return (v > 0.0) - (v < 0.0); }
int sgn(i128 v) { return (v > 0) - (v < 0); }

// Integer references for small integer coordinates (|v| < 2^24 for incircle).
int int_orient(const std::int64_t* p) {
  const i128 acx = p[0] - p[4], acy = p[1] - p[5], bcx = p[2] - p[4], bcy = p[3] - p[5];
  return sgn(acx * bcy - acy * bcx);
}

int int_incircle(const std::int64_t* p) {
  const i128 adx = p[0] - p[6], ady = p[1] - p[7], bdx = p[2] - p[6], bdy = p[3] - p[7];
  const i128 cdx = p[4] - p[6], cdy = p[5] - p[7];
  return sgn((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
             (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady));
}

double naive_orient(Point a, Point b, Point c) { return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x); }

double naive_incircle(Point a, Point b, Point c, Point d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

// Moves v by k ulps (k may be negative).
double ulps(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

Point scaled(Point p, int e) { return {std::ldexp(p.x, e), std::ldexp(p.y, e)}; }

// Shewchuk's Fig. 1 experiment: a 64x64 ulp grid around (0.5, 0.5), tested
// against the line through (12, 12) and (24, 24).
std::vector<Point> ulp_grid(double cx, double cy, int half) {
  std::vector<Point> pts;
  for (int i = -half; i < half; ++i)
    for (int j = -half; j < half; ++j) pts.push_back({ulps(cx, i), ulps(cy, j)});
  return pts;
}

// A point on the circle of radius r around c at angle t, rounded, then nudged
// by (i, j) ulps: almost, but usually not exactly, cocircular.
Point near_circle(Point c, double r, double t, int i, int j) {
  return {ulps(c.x + r * std::cos(t), i), ulps(c.y + r * std::sin(t), j)};
}

}  // namespace

TEST_SUITE("predicates") {

TEST_CASE("orient2d on Shewchuk's ulp grid matches exact arithmetic") {
  const Point b{12.0, 12.0};
  const Point c{24.0, 24.0};
  int naive_wrong = 0;
  int zeros = 0;
  for (const Point a : ulp_grid(0.5, 0.5, 32)) {
    const int expect = exact_orient(a, b, c);
    REQUIRE(sgn(orient2d(a, b, c)) == expect);
    REQUIRE(sgn(orient2d(b, c, a)) == expect);
    REQUIRE(sgn(orient2d(c, a, b)) == expect);
    naive_wrong += sgn(naive_orient(a, b, c)) != expect;
    zeros += expect == 0;
  }
  // The grid is only meaningful if plain floating point gets it wrong, and the
  // exact diagonal (x == y) must come out zero.
  CHECK(naive_wrong > 100);
  CHECK(zeros == 64);
}

TEST_CASE("orient2d near-degenerate with inexact differences") {
  // Points far apart in magnitude so that a - c is not representable and
  // stages C and D of the adaptive evaluation are exercised.
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> k(-3, 3);
  for (int n = 0; n < 20000; ++n) {
    const Point a{u(rng) * 1e-3, u(rng) * 1e-3};
    const Point c{u(rng) * 1e3, u(rng) * 1e3};
    const double t = std::ldexp(u(rng), n % 40 - 20);
    const Point b{ulps(a.x + t * (c.x - a.x), k(rng)), ulps(a.y + t * (c.y - a.y), k(rng))};
    const int expect = exact_orient(a, b, c);
    REQUIRE(sgn(orient2d(a, b, c)) == expect);
    REQUIRE(sgn(orient2d(b, a, c)) == -expect);
  }
}

TEST_CASE("orient2d exactly collinear integer points give zero") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
  std::uniform_int_distribution<std::int64_t> step(-1000, 1000);
  for (int n = 0; n < 5000; ++n) {
    const std::int64_t x0 = coord(rng), y0 = coord(rng), dx = step(rng), dy = step(rng);
    const std::int64_t s = step(rng), t = step(rng);
    const Point a{double(x0), double(y0)};
    const Point b{double(x0 + s * dx), double(y0 + s * dy)};
    const Point c{double(x0 + t * dx), double(y0 + t * dy)};
    REQUIRE(orient2d(a, b, c) == 0.0);
  }
}

TEST_CASE("orient2d random integers match __int128") {
  std::mt19937_64 rng(99);
  for (const std::int64_t range :
       {std::int64_t{3}, std::int64_t{1} << 20, std::int64_t{1} << 52, std::int64_t{1} << 60}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int n = 0; n < 20000; ++n) {
      std::int64_t p[6];
      for (auto& v : p) {
        v = coord(rng);
        v = static_cast<std::int64_t>(static_cast<double>(v));  // keep it representable
      }
      const Point a{double(p[0]), double(p[1])}, b{double(p[2]), double(p[3])}, c{double(p[4]), double(p[5])};
      REQUIRE(sgn(orient2d(a, b, c)) == int_orient(p));
    }
  }
}

TEST_CASE("orient2d huge and tiny coordinates") {
  // Power-of-two scaling is exact, so signs must not change. Valid range for
  // orient2d is about 1e-137 .. 1e153 (see src/kernel/predicates.cpp).
  const Point b{12.0, 12.0};
  const Point c{24.0, 24.0};
  for (const int e : {498, 300, -300, -440}) {
    CAPTURE(e);
    for (const Point a : ulp_grid(0.5, 0.5, 8)) {
      const int expect = exact_orient(a, b, c);
      REQUIRE(sgn(orient2d(scaled(a, e), scaled(b, e), scaled(c, e))) == expect);
    }
  }
  const Point h{1e150, -1e150};
  CHECK(orient2d(h, {-1e150, 1e150}, {0.0, 0.0}) == 0.0);
  CHECK(orient2d(h, {-1e150, 1e150}, {0.0, 1e-150}) == -2.0);  // exact: -2e300 - 2 + 2e300
  CHECK(orient2d({ulps(1e150, 1), 1e150}, {-1e150, -1e150}, {0.0, 0.0}) < 0.0);
}

TEST_CASE("orient2d translation invariance") {
  // Integers up to 2^58 next to small ones (so differences are inexact), shifted
  // by multiples of 2^10 below 2^52; inexact shifts are skipped.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::int64_t> big(0, std::int64_t{1} << 58);
  std::uniform_int_distribution<std::int64_t> small(-50, 50);
  int tested = 0;
  for (int n = 0; n < 20000; ++n) {
    const double base = double(big(rng) & ~std::int64_t{1023});
    const Point a{base, base};
    const Point b{double(small(rng)), double(small(rng))};
    const Point c{base * 0.5 + double(small(rng) % 3 * 1024), base * 0.5 + double(small(rng) % 3 * 1024)};
    const double t = double((big(rng) >> 6) & ~std::int64_t{1023}) * (n % 2 ? 1.0 : -1.0);
    const Point ta{a.x + t, a.y - t}, tb{b.x + t, b.y - t}, tc{c.x + t, c.y - t};
    const auto exact = [t](Point p, Point q) { return exact_sum(p.x, t, q.x) && exact_sum(p.y, -t, q.y); };
    if (!exact(a, ta) || !exact(b, tb) || !exact(c, tc)) continue;
    ++tested;
    const int expect = exact_orient(a, b, c);
    REQUIRE(sgn(orient2d(a, b, c)) == expect);
    REQUIRE(exact_orient(ta, tb, tc) == expect);
    REQUIRE(sgn(orient2d(ta, tb, tc)) == expect);
  }
  CHECK(tested > 1000);
}

TEST_CASE("incircle near-cocircular ulp perturbations match exact arithmetic") {
  int naive_wrong = 0;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);
  const Point centres[] = {{0.0, 0.0}, {0.1, -0.3}, {1e3 + 0.25, 7.0}, {-3e-4, 2e5}};
  for (const Point ctr : centres) {
    for (const double r : {1.0, 1e-3, 37.5}) {
      for (int n = 0; n < 400; ++n) {
        const Point a = near_circle(ctr, r, ang(rng), 0, 0);
        const Point b = near_circle(ctr, r, ang(rng), 0, 0);
        const Point c = near_circle(ctr, r, ang(rng), 0, 0);
        const Point d = near_circle(ctr, r, ang(rng), n % 5 - 2, n / 5 % 5 - 2);
        const int expect = exact_incircle(a, b, c, d);
        const double got = incircle(a, b, c, d);
        REQUIRE(sgn(got) == expect);
        REQUIRE(sgn(incircle(b, a, c, d)) == -expect);
        REQUIRE(sgn(incircle(d, b, c, a)) == -expect);
        REQUIRE(sgn(incircle(b, c, a, d)) == expect);
        naive_wrong += sgn(naive_incircle(a, b, c, d)) != expect;
      }
    }
  }
  CHECK(naive_wrong > 100);  // the inputs really are hard for plain floating point
}

TEST_CASE("incircle exactly cocircular integer points give zero") {
  // Lattice points on x^2 + y^2 = 5^2 * 13^2 * 17^2, translated.
  const std::int64_t r2 = 5 * 5 * 13 * 13 * 17 * 17;
  std::vector<std::pair<std::int64_t, std::int64_t>> on;
  for (std::int64_t x = -1105; x <= 1105; ++x) {
    const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(double(r2 - x * x))));
    if (x * x + y * y == r2) {
      on.push_back({x, y});
      if (y != 0) on.push_back({x, -y});
    }
  }
  REQUIRE(on.size() > 20);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::size_t> pick(0, on.size() - 1);
  std::uniform_int_distribution<std::int64_t> shift(-(std::int64_t{1} << 20), std::int64_t{1} << 20);
  for (int n = 0; n < 3000; ++n) {
    const double sx = double(shift(rng)), sy = double(shift(rng));
    Point p[4];
    for (auto& q : p) {
      const auto& v = on[pick(rng)];
      q = {double(v.first) + sx, double(v.second) + sy};
    }
    REQUIRE(incircle(p[0], p[1], p[2], p[3]) == 0.0);
  }
}

TEST_CASE("incircle rectangles of mixed magnitude reach the exact stage") {
  // The corners of an axis-parallel rectangle are exactly cocircular for any
  // doubles. With sides spanning many binades the differences are inexact and
  // the error bounds of stages A-C cannot decide, so the exact stage must.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> ex(-40, 40);
  std::uniform_int_distribution<int> k(-2, 2);
  for (int n = 0; n < 3000; ++n) {
    const double x1 = std::ldexp(u(rng), ex(rng)), x2 = std::ldexp(u(rng), ex(rng));
    const double y1 = std::ldexp(u(rng), ex(rng)), y2 = std::ldexp(u(rng), ex(rng));
    const Point a{x1, y1}, b{x2, y1}, c{x2, y2}, d{x1, y2};
    REQUIRE(incircle(a, b, c, d) == 0.0);
    REQUIRE(incircle(d, a, c, b) == 0.0);
    const Point e{ulps(x1, k(rng)), ulps(y2, k(rng))};
    const int expect = exact_incircle(a, b, c, e);
    REQUIRE(sgn(incircle(a, b, c, e)) == expect);
    REQUIRE(sgn(incircle(e, b, c, a)) == -expect);
  }
}

TEST_CASE("incircle random integers match __int128") {
  std::mt19937_64 rng(77);
  for (const std::int64_t range : {std::int64_t{2}, std::int64_t{8}, std::int64_t{1} << 24}) {
    std::uniform_int_distribution<std::int64_t> coord(-range, range);
    for (int n = 0; n < 20000; ++n) {
      std::int64_t p[8];
      for (auto& v : p) v = coord(rng);
      const Point a{double(p[0]), double(p[1])}, b{double(p[2]), double(p[3])};
      const Point c{double(p[4]), double(p[5])}, d{double(p[6]), double(p[7])};
      REQUIRE(sgn(incircle(a, b, c, d)) == int_incircle(p));
    }
  }
}

TEST_CASE("incircle huge and tiny coordinates") {
  // Valid range for incircle is about 1e-60 .. 1e76 (see src/kernel/predicates.cpp).
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);
  for (const int e : {240, 100, -100, -190}) {
    CAPTURE(e);
    for (int n = 0; n < 500; ++n) {
      const Point ctr{0.3, -0.7};
      const Point a = near_circle(ctr, 2.0, ang(rng), 0, 0);
      const Point b = near_circle(ctr, 2.0, ang(rng), 0, 0);
      const Point c = near_circle(ctr, 2.0, ang(rng), 0, 0);
      const Point d = near_circle(ctr, 2.0, ang(rng), n % 3 - 1, n / 3 % 3 - 1);
      const int expect = exact_incircle(a, b, c, d);
      REQUIRE(sgn(incircle(scaled(a, e), scaled(b, e), scaled(c, e), scaled(d, e))) == expect);
    }
  }
  CHECK(incircle({1e75, 0.0}, {0.0, 1e75}, {-1e75, 0.0}, {0.0, -1e75}) == 0.0);
  CHECK(incircle({1e75, 0.0}, {0.0, 1e75}, {-1e75, 0.0}, {0.0, ulps(-1e75, -1)}) < 0.0);
  CHECK(incircle({1e75, 0.0}, {0.0, 1e75}, {-1e75, 0.0}, {0.0, ulps(-1e75, 1)}) > 0.0);
}

TEST_CASE("incircle translation invariance") {
  // Integer points near a circle of radius ~2^57 that passes near the origin,
  // with d close to the origin: the differences a - d are inexact. Shifts are
  // multiples of 2^10; a shift that is not exact in double is skipped.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ang(0.5, 5.5);
  std::uniform_int_distribution<std::int64_t> small(-40, 40);
  std::uniform_int_distribution<std::int64_t> shift(0, std::int64_t{1} << 52);
  const double r = std::ldexp(1.0, 57);
  int tested = 0;
  for (int n = 0; n < 3000; ++n) {
    const auto on = [&](double t) { return Point{std::round(r + r * std::cos(t)), std::round(r * std::sin(t))}; };
    const Point a = on(ang(rng)), b = on(ang(rng)), c = on(ang(rng));
    const Point d{double(small(rng)), double(small(rng))};
    const double t = double(shift(rng) & ~std::int64_t{1023}) * (n % 2 ? 1.0 : -1.0);
    const Point s{t, -t};
    const Point ta = a + s, tb = b + s, tc = c + s, td = d + s;
    const auto exact = [t](Point p, Point q) { return exact_sum(p.x, t, q.x) && exact_sum(p.y, -t, q.y); };
    const int expect = exact_incircle(a, b, c, d);
    REQUIRE(sgn(incircle(a, b, c, d)) == expect);
    if (!exact(a, ta) || !exact(b, tb) || !exact(c, tc) || !exact(d, td)) continue;
    ++tested;
    REQUIRE(sgn(incircle(ta, tb, tc, td)) == expect);
  }
  CHECK(tested > 500);
}

TEST_CASE("predicates are thread-safe: no shared state between calls") {
  // Same hard inputs evaluated concurrently must give the single-thread signs.
  std::vector<Point> pts = ulp_grid(0.5, 0.5, 16);
  const Point b{12.0, 12.0};
  const Point c{24.0, 24.0};
  std::vector<int> ref;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    ref.push_back(sgn(orient2d(pts[i], b, c)) + 3 * sgn(incircle(pts[i], b, c, pts[i + 1])));
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> workers;
  for (int w = 0; w < 4; ++w)
    workers.emplace_back([&, w] {
      for (int rep = 0; rep < 20; ++rep)
        for (std::size_t i = 0; i + 1 < pts.size(); ++i)
          mismatches[w] += ref[i] != sgn(orient2d(pts[i], b, c)) + 3 * sgn(incircle(pts[i], b, c, pts[i + 1]));
    });
  for (auto& t : workers) t.join();
  for (int m : mismatches) CHECK(m == 0);
}

}  // TEST_SUITE("predicates")
