// Tests of resolve_intersections() (include/madd/intersections.hpp): the
// pieces meet only at endpoints, lie on their segments, cover them; one new
// vertex per crossing, one shared vertex where several segments cross at a
// point; overlaps merged; checked against O(n^2) exact brute force.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "hull_points.hpp"
#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

using madd::Point;

namespace {

// Proper crossing of two segments with four distinct endpoints, exactly.
bool properly_cross(Point a, Point b, Point c, Point d) {
  const double o1 = madd::orient2d(a, b, c), o2 = madd::orient2d(a, b, d);
  const double o3 = madd::orient2d(c, d, a), o4 = madd::orient2d(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

double length_of(const madd::Pslg& p) {
  double sum = 0;
  for (const madd::Segment& s : p.segments) sum += madd::distance(p.points[s.a], p.points[s.b]);
  return sum;
}

// Distance from q to the line through a and b.
double off_line(Point a, Point b, Point q) { return std::abs(madd::cross(b - a, q - a)) / madd::distance(a, b); }

using madd::test::hull_point_count;

void check_resolved(const madd::Pslg& input, const madd::ResolvedPslg& r) {
  madd::validate_pslg(r.pslg);  // nothing crosses or overlaps any more
  CHECK(r.pslg.points.size() == input.points.size() + r.new_vertices);
  CHECK(std::equal(input.points.begin(), input.points.end(), r.pslg.points.begin()));
  REQUIRE(r.source_segment.size() == r.pslg.segments.size());
  for (std::size_t k = 0; k < r.pslg.segments.size(); ++k) {
    const madd::Segment& whole = input.segments[r.source_segment[k]];
    const Point a = input.points[whole.a], b = input.points[whole.b];
    const double tolerance = 1e-14 * (1 + std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}));
    for (const std::uint32_t v : {r.pslg.segments[k].a, r.pslg.segments[k].b})
      CHECK(off_line(a, b, r.pslg.points[v]) <= tolerance);
  }
  CHECK(r.pslg == madd::resolve_intersections(input).pslg);  // deterministic
}

}  // namespace

TEST_SUITE("intersections") {

TEST_CASE("random crossing segments: one new vertex per crossing pair, the pieces cover the segments") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int round = 0; round < 10; ++round) {
    madd::Pslg p;
    const int n = 10 + 4 * round;
    for (int k = 0; k < n; ++k) {
      p.points.push_back({u(rng), u(rng)});
      p.points.push_back({u(rng), u(rng)});
      p.segments.push_back({2U * k, 2U * k + 1, k + 1});
    }
    std::size_t pairs = 0;
    for (std::size_t s = 0; s < p.segments.size(); ++s)
      for (std::size_t t = s + 1; t < p.segments.size(); ++t)
        pairs += properly_cross(p.points[p.segments[s].a], p.points[p.segments[s].b], p.points[p.segments[t].a],
                                p.points[p.segments[t].b]);
    madd::ValidatePslgOptions allow;
    allow.allow_intersections = true;
    madd::validate_pslg(p, {}, allow);
    const madd::ResolvedPslg r = madd::resolve_intersections(p);
    CAPTURE(round);
    CHECK(r.crossings == pairs);
    CHECK(r.new_vertices == pairs);  // random: no three segments meet at one point
    CHECK(r.overlaps == 0);
    CHECK(r.pslg.segments.size() == p.segments.size() + 2 * pairs);
    CHECK(length_of(r.pslg) == doctest::Approx(length_of(p)).epsilon(1e-12));
    for (std::size_t k = 0; k < r.pslg.segments.size(); ++k)
      CHECK(r.pslg.segments[k].marker == p.segments[r.source_segment[k]].marker);
    check_resolved(p, r);
    // Every vertex is in the convex hull's triangulation: Euler's formula.
    madd::TriangulateOptions hull;
    hull.convex_hull = true;
    const madd::Triangulation tri = madd::triangulate(r.pslg, hull);
    CHECK(madd::verify_triangulation(tri, &r.pslg, hull).ok());
    CHECK(tri.triangle_count() == 2 * r.pslg.points.size() - 2 - hull_point_count(r.pslg.points));
  }
}

TEST_CASE("segments crossing at one point that no double holds share one new vertex") {
  // Lines through c = (1/3, 1/7) in several directions, their ends rounded.
  const Point c{1.0 / 3.0, 1.0 / 7.0};
  madd::Pslg p;
  const int lines = 5;
  for (int k = 0; k < lines; ++k) {
    const double angle = 0.3 + 0.6 * k;
    const Point d{std::cos(angle), std::sin(angle)};
    p.points.push_back({c.x - d.x, c.y - d.y});
    p.points.push_back({c.x + 0.7 * d.x, c.y + 0.7 * d.y});
    p.segments.push_back({2U * k, 2U * k + 1, 0});
  }
  const madd::ResolvedPslg r = madd::resolve_intersections(p);
  CHECK(r.crossings == lines * (lines - 1) / 2);
  CHECK(r.new_vertices == 1);
  CHECK(r.pslg.segments.size() == 2 * lines);
  CHECK(madd::distance(r.pslg.points.back(), c) < 1e-15);
  check_resolved(p, r);
}

TEST_CASE("overlapping and repeated collinear segments become one chain of pieces") {
  // On y = 0: [0, 2], [1, 3], [2.5, 4], and [0, 2] again reversed.
  madd::Pslg p;
  p.points = {{0, 0}, {2, 0}, {1, 0}, {3, 0}, {2.5, 0}, {4, 0}};
  p.segments = {{0, 1, 7}, {2, 3, 8}, {4, 5, 9}, {1, 0, 10}};
  const madd::ResolvedPslg r = madd::resolve_intersections(p);
  CHECK(r.new_vertices == 0);
  CHECK(r.crossings == 0);
  CHECK(r.overlaps == 4);              // [0,2]-[1,3], [1,3]-[2.5,4], and the repeat with both
  CHECK(r.pslg.segments.size() == 5);  // between 0, 1, 2, 2.5, 3, 4
  CHECK(length_of(r.pslg) == 4.0);
  check_resolved(p, r);
  // The first segment in input order keeps each piece (and its marker).
  for (std::size_t k = 0; k < r.pslg.segments.size(); ++k) {
    const double mid = 0.5 * (r.pslg.points[r.pslg.segments[k].a].x + r.pslg.points[r.pslg.segments[k].b].x);
    CHECK(r.pslg.segments[k].marker == (mid < 2 ? 7 : mid < 3 ? 8 : 9));
  }
}

TEST_CASE("a vertex lying on a segment, alone or at a crossing, splits it exactly") {
  madd::Pslg p;
  p.points = {{0, 0}, {1, 1}, {0, 1}, {1, 0}, {0.5, 0.5}, {0.25, 0.25}};
  p.segments = {{0, 1, 0}, {2, 3, 0}};
  const madd::ResolvedPslg r = madd::resolve_intersections(p);
  CHECK(r.new_vertices == 0);  // the crossing point is vertex 4
  CHECK(r.pslg.segments.size() == 5);
  check_resolved(p, r);
}

TEST_CASE("attributes of a new vertex are interpolated along a segment through it") {
  madd::Pslg p;
  p.points = {{0, 0}, {2, 0}, {1, -1}, {1, 1}};
  p.attributes_per_point = 1;
  p.attributes = {0.0, 4.0, 5.0, 5.0};
  p.point_markers = {1, 2, 3, 4};
  p.segments = {{0, 1, 0}, {2, 3, 0}};
  const madd::ResolvedPslg r = madd::resolve_intersections(p);
  REQUIRE(r.new_vertices == 1);
  CHECK(r.pslg.points[4] == Point{1, 0});
  CHECK(r.pslg.point_markers[4] == 0);
  const double a = r.pslg.attribute(4, 0);
  CHECK((a == doctest::Approx(2.0) || a == doctest::Approx(5.0)));
}

}  // TEST_SUITE("intersections")
