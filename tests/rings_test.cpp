// Tests of the kernel's ring geometry (src/kernel/rings.hpp): area,
// orientation and exact point location, against exact integer references.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "kernel/rings.hpp"
#include "madd/geometry.hpp"
#include "predicates_reference.hpp"

using madd::Point;
using madd::detail::locate_in_ring;
using madd::detail::Orientation;
using madd::detail::ring_orientation;
using madd::detail::ring_signed_area;
using madd::detail::RingLocation;
using madd::detail::RingView;
using madd::detail::winding_number;
using madd::detail::WindingIndex;

namespace {

using Ring = std::vector<Point>;

Ring reversed(Ring ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

Ring translated(Ring ring, Point by) {
  for (Point& p : ring) p = p + by;
  return ring;
}

// ---- Exact references on half-integer coordinates: twice a coordinate is an
// integer, and every product below fits in 64 bits. ----

struct Twice {
  std::int64_t x, y;
};

Twice twice(Point p) { return {std::llround(2 * p.x), std::llround(2 * p.y)}; }

std::int64_t cross_of(Twice o, Twice a, Twice b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// 8 * signed area, by a fan of triangles from `apex` (not a ring vertex).
std::int64_t eight_times_area(const Ring& ring, Point apex) {
  std::int64_t sum = 0;
  for (std::size_t k = 0; k < ring.size(); ++k)
    sum += cross_of(twice(apex), twice(ring[k]), twice(ring[(k + 1) % ring.size()]));
  return sum;
}

// On edge ab: collinear and between the ends (the dot product test, not the box test).
bool reference_on_edge(Point a, Point b, Point p) {
  const Twice ta = twice(a), tb = twice(b), tp = twice(p);
  const std::int64_t dot = (ta.x - tp.x) * (tb.x - tp.x) + (ta.y - tp.y) * (tb.y - tp.y);
  return cross_of(tp, ta, tb) == 0 && dot <= 0;
}

bool reference_on_ring(const Ring& ring, Point p) {
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (reference_on_edge(ring[k], ring[(k + 1) % ring.size()], p)) return true;
  return false;
}

// Winding number as the total turning angle seen from p, over 2 pi. Correct
// for p off the ring (each term is well inside (-pi, pi) away from the ring,
// and the sum is an integer multiple of 2 pi up to tiny rounding).
int reference_winding(const Ring& ring, Point p) {
  double turn = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k] - p, b = ring[(k + 1) % ring.size()] - p;
    turn += std::atan2(madd::cross(a, b), madd::dot(a, b));
  }
  return static_cast<int>(std::lround(turn / (2 * std::numbers::pi)));
}

// The documented tie-break of winding_number: a point on the ring counts as
// p + (e, e^2) for an infinitesimal e. On a half-integer grid within +-10,
// e = 1e-4 is small enough: every edge not through p is at least ~1/60 away,
// and for an edge through p the e^2 step cannot outweigh the e step.
Point nudged(Point p) { return {p.x + 1e-4, p.y + 1e-8}; }

// A random simple counter-clockwise polygon with integer vertices in
// [-r, r]^2: points sorted by angle around a centre that is not a grid point,
// one point per direction, kept only when no angular gap reaches pi (so that
// each edge has its own sector and the polygon is simple).
Ring random_star_polygon(std::mt19937& rng, int r, int count) {
  std::uniform_int_distribution<int> coordinate(-r, r);
  const Twice centre{1, 0};  // (0.5, 0) doubled
  while (true) {
    std::vector<Twice> ps;
    for (int k = 0; k < count; ++k) ps.push_back({2 * coordinate(rng), 2 * coordinate(rng)});
    const auto upper = [&](Twice p) { return p.y > centre.y || (p.y == centre.y && p.x > centre.x); };
    const auto before = [&](Twice p, Twice q) {
      if (upper(p) != upper(q)) return upper(p);
      return cross_of(centre, p, q) > 0;
    };
    std::sort(ps.begin(), ps.end(), before);
    std::vector<Twice> kept;
    for (Twice p : ps)
      if (kept.empty() || before(kept.back(), p)) kept.push_back(p);  // one point per direction
    if (kept.size() < 3) continue;
    bool gaps_below_pi = true;
    for (std::size_t k = 0; k < kept.size(); ++k)
      gaps_below_pi = gaps_below_pi && cross_of(centre, kept[k], kept[(k + 1) % kept.size()]) > 0;
    if (!gaps_below_pi) continue;
    Ring ring;
    for (Twice p : kept) ring.push_back({static_cast<double>(p.x) / 2, static_cast<double>(p.y) / 2});
    return ring;
  }
}

std::vector<Point> half_grid(int r) {
  std::vector<Point> out;
  for (int i = -2 * r - 2; i <= 2 * r + 2; ++i)
    for (int j = -2 * r - 2; j <= 2 * r + 2; ++j) out.push_back({i / 2.0, j / 2.0});
  return out;
}

const Ring unit_square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

}  // namespace

TEST_CASE("rings: the unit square either way round, with points inside, outside, on edges and on vertices") {
  for (const bool ccw : {true, false}) {
    CAPTURE(ccw);
    const Ring ring = ccw ? unit_square : reversed(unit_square);
    const RingView view(ring);
    CHECK(ring_signed_area(view) == (ccw ? 1.0 : -1.0));
    CHECK(ring_orientation(view) == (ccw ? Orientation::counter_clockwise : Orientation::clockwise));
    CHECK(locate_in_ring(view, {0.5, 0.5}) == RingLocation::inside);
    CHECK(winding_number(view, {0.5, 0.5}) == (ccw ? 1 : -1));
    for (const Point p : ring) CHECK(locate_in_ring(view, p) == RingLocation::on_ring);
    for (const Point p : {Point{0.5, 0}, Point{1, 0.5}, Point{0.5, 1}, Point{0, 0.5}})
      CHECK(locate_in_ring(view, p) == RingLocation::on_ring);
    // On an edge's line but beyond its ends, at a vertex's height, far away.
    for (const Point p :
         {Point{2, 0}, Point{-1, 0}, Point{1, 2}, Point{0, -3}, Point{-1, 1}, Point{2, 1}, Point{5, 5}}) {
      CHECK(locate_in_ring(view, p) == RingLocation::outside);
      CHECK(winding_number(view, p) == 0);
    }
    // One ulp off an edge, either side.
    const double below_one = std::nextafter(1.0, 0.0), above_one = std::nextafter(1.0, 2.0);
    CHECK(locate_in_ring(view, {below_one, 0.5}) == RingLocation::inside);
    CHECK(locate_in_ring(view, {above_one, 0.5}) == RingLocation::outside);
    CHECK(locate_in_ring(view, {0.5, std::nextafter(0.0, 1.0)}) == RingLocation::inside);
    CHECK(locate_in_ring(view, {0.5, std::nextafter(0.0, -1.0)}) == RingLocation::outside);
  }
}

TEST_CASE("rings: an index cycle and the same ring as points agree") {
  // The square's corners scattered through a larger point array, plus a hole.
  const std::vector<Point> points{{9, 9}, {1, 1},       {0, 0},       {7, 7},       {0, 1},
                                  {1, 0}, {0.25, 0.25}, {0.25, 0.75}, {0.75, 0.75}, {0.75, 0.25}};
  const std::vector<std::uint32_t> cycle{2, 5, 1, 4};
  const std::vector<std::uint32_t> hole{6, 7, 8, 9};  // clockwise
  const RingView indexed(points, cycle);
  const RingView direct(unit_square);
  REQUIRE(indexed.size() == 4);
  for (std::size_t k = 0; k < 4; ++k) {
    CHECK(indexed[k] == direct[k]);
    CHECK(indexed.after(k) == direct.after(k));
  }
  CHECK(ring_signed_area(indexed) == ring_signed_area(direct));
  for (const Point p : half_grid(1)) CHECK(locate_in_ring(indexed, p) == locate_in_ring(direct, p));
  CHECK(ring_orientation(RingView(points, hole)) == Orientation::clockwise);
  const std::vector<std::vector<std::uint32_t>> rings{cycle, hole};
  CHECK(madd::detail::rings_area(points, rings) == 1.0 - 0.25);
}

TEST_CASE("rings: degenerate rings have no area and no orientation, and hold only the points on them") {
  const Ring empty, one{{1, 1}}, two{{0, 0}, {2, 1}};
  const Ring collinear{{0, 0}, {1, 1}, {3, 3}, {2, 2}};
  for (const Ring* ring : {&empty, &one, &two, &collinear}) {
    const RingView view(*ring);
    CHECK(ring_signed_area(view) == 0.0);
    CHECK(ring_orientation(view) == Orientation::degenerate);
    CHECK(winding_number(view, {0.5, 0.25}) == 0);
    CHECK(locate_in_ring(view, {5, 5}) == RingLocation::outside);
  }
  CHECK(locate_in_ring(RingView(one), {1, 1}) == RingLocation::on_ring);
  CHECK(locate_in_ring(RingView(two), {1, 0.5}) == RingLocation::on_ring);
  CHECK(locate_in_ring(RingView(collinear), {2.5, 2.5}) == RingLocation::on_ring);
  CHECK(locate_in_ring(RingView(collinear), {4, 4}) == RingLocation::outside);
}

TEST_CASE("rings: area equals an exact integer triangle fan, also far from the origin") {
  std::mt19937 rng(20240611);
  for (int trial = 0; trial < 300; ++trial) {
    const Ring ccw = random_star_polygon(rng, 10, 3 + trial % 30);
    CAPTURE(trial);
    for (const Ring& ring : {ccw, reversed(ccw)}) {
      const std::int64_t exact = eight_times_area(ring, {-3.5, 7});  // apex off the ring's first vertex
      CHECK(8.0 * ring_signed_area(RingView(ring)) == static_cast<double>(exact));
      // Differences from vertex 0 are exact even at 2^40, where a shoelace
      // over absolute coordinates would lose the area entirely.
      const Ring far = translated(ring, {0x1p40, -0x1p40});
      CHECK(8.0 * ring_signed_area(RingView(far)) == static_cast<double>(exact));
      const Orientation expected = exact > 0 ? Orientation::counter_clockwise : Orientation::clockwise;
      CHECK(ring_orientation(RingView(ring)) == expected);
      CHECK(ring_orientation(RingView(far)) == expected);
    }
  }
}

TEST_CASE("rings: point location matches exact references on random polygons, including edges and vertices") {
  std::mt19937 rng(7);
  const std::vector<Point> queries = half_grid(10);
  int on = 0, in = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Ring ccw = random_star_polygon(rng, 10, 4 + trial % 20);
    for (const Ring& ring : {ccw, reversed(ccw)}) {
      const RingView view(ring);
      for (const Point p : queries) {
        CAPTURE(p.x);
        CAPTURE(p.y);
        if (reference_on_ring(ring, p)) {
          ++on;
          CHECK(locate_in_ring(view, p) == RingLocation::on_ring);
          CHECK(winding_number(view, p) == reference_winding(ring, nudged(p)));
        } else {
          const int winding = reference_winding(ring, p);
          in += winding != 0;
          CHECK(winding_number(view, p) == winding);
          CHECK(locate_in_ring(view, p) == (winding != 0 ? RingLocation::inside : RingLocation::outside));
        }
      }
    }
  }
  // The grid really hit the boundary and the inside, many times.
  CHECK(on > 1000);
  CHECK(in > 10000);
}

TEST_CASE("rings: the faces of a subdivision give every point of the domain to exactly one face") {
  // The square [0, 4]^2 cut by a zigzag from (0, 1) to (4, 3) into a lower
  // and an upper face, both counter-clockwise.
  const std::vector<Point> zigzag{{0, 1}, {1, 2}, {2, 0.5}, {3, 3.5}, {4, 3}};
  Ring lower{{0, 0}, {4, 0}};
  for (auto it = zigzag.rbegin(); it != zigzag.rend(); ++it) lower.push_back(*it);
  Ring upper{{4, 4}, {0, 4}};
  for (const Point p : zigzag) upper.push_back(p);
  const Ring domain{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  for (const Point p : half_grid(3)) {
    CAPTURE(p.x);
    CAPTURE(p.y);
    const int faces = (winding_number(RingView(lower), p) != 0) + (winding_number(RingView(upper), p) != 0);
    CHECK(faces == (winding_number(RingView(domain), p) != 0 ? 1 : 0));
    CHECK(faces == (reference_winding(domain, nudged(p)) != 0 ? 1 : 0));
  }
}

TEST_CASE("rings: signs are exact for points a few ulps from an edge and nearly collinear triangles") {
  using madd::test_ref::exact_orient;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> ulps(-4, 4);
  const auto nudge = [&](double v) {
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) v = std::nextafter(v, k > 0 ? 1e300 : -1e300);
    return v;
  };
  int counts[3] = {0, 0, 0};  // outside, on_ring, inside
  for (int trial = 0; trial < 2000; ++trial) {
    const Point a{unit(rng), unit(rng)}, b{unit(rng) + 1.0, unit(rng) + 1.0}, c{unit(rng), unit(rng) + 3.0};
    const Ring triangle{a, b, c};
    const int turn = exact_orient(a, b, c);
    REQUIRE(turn != 0);
    // Points within a few ulps of the edge ab's line: the float crossing
    // computation cannot tell their side; orient2d must.
    const double t = unit(rng);
    const Point p{nudge(a.x + t * (b.x - a.x)), nudge(a.y + t * (b.y - a.y))};
    const int sides[3] = {exact_orient(a, b, p) * turn, exact_orient(b, c, p) * turn, exact_orient(c, a, p) * turn};
    const bool outside = sides[0] < 0 || sides[1] < 0 || sides[2] < 0;
    const bool on_edge = !outside && (sides[0] == 0 || sides[1] == 0 || sides[2] == 0);
    const RingLocation expected = outside   ? RingLocation::outside
                                  : on_edge ? RingLocation::on_ring
                                            : RingLocation::inside;
    ++counts[static_cast<int>(expected)];
    for (const Ring& ring : {triangle, reversed(triangle)}) CHECK(locate_in_ring(RingView(ring), p) == expected);
    // A nearly collinear triangle a, p, b: its orientation is the exact sign.
    const int flat = exact_orient(a, p, b);
    const Orientation want = flat > 0   ? Orientation::counter_clockwise
                             : flat < 0 ? Orientation::clockwise
                                        : Orientation::degenerate;
    CHECK(ring_orientation(RingView(Ring{a, p, b})) == want);
  }
  // The nudged points really straddle the edge.
  CHECK(counts[0] > 200);
  CHECK(counts[2] > 200);
}

TEST_CASE("rings: the winding index gives winding_number's answer for a face with holes, on edges and vertices too") {
  // A face and two holes as index cycles, queried on a half grid (so many
  // points lie at the height of a vertex or on an edge, where the half-open
  // rule decides) and at random points: the sum over the rings, exactly.
  std::mt19937 rng(11);
  const std::vector<Point> queries = half_grid(10);
  for (int trial = 0; trial < 20; ++trial) {
    const Ring outer = random_star_polygon(rng, 10, 6 + trial);
    std::vector<Point> points = outer;
    std::vector<std::vector<std::uint32_t>> rings(1);
    for (std::uint32_t k = 0; k < outer.size(); ++k) rings[0].push_back(k);
    // Two small holes, clockwise, wherever they fall (the sum is what is compared).
    for (const Point c : {Point{3, 4}, Point{6, 5}}) {
      std::vector<std::uint32_t> hole;
      for (const Point d : {Point{0, 0}, Point{0, 1}, Point{1, 1}, Point{1, 0}}) {
        hole.push_back(static_cast<std::uint32_t>(points.size()));
        points.push_back(c + d);
      }
      rings.push_back(hole);
    }
    const WindingIndex index(points, rings);
    std::uniform_real_distribution<double> coordinate(-1.0, 11.0);
    std::vector<Point> all = queries;
    for (int k = 0; k < 500; ++k) all.push_back({coordinate(rng), coordinate(rng)});
    for (const Point p : all) {
      int expected = 0;
      for (const auto& ring : rings) expected += winding_number(RingView(points, ring), p);
      CAPTURE(p.x);
      CAPTURE(p.y);
      CHECK(index.winding(p) == expected);
    }
  }
}
