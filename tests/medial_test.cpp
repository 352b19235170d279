// Junction triangles, G_D and its contraction (paper Sec. 3, Algorithms 1-2).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "madd/medial.hpp"
#include "medial/medial_detail.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace {

using madd::detail::BoundaryLinks;
using madd::Point;
using madd::Triangulation;
constexpr std::uint32_t none = madd::no_index;

// A regular hexagon split into a central triangle (0,2,4) and three ears.
Triangulation hexagon() {
  Triangulation t;
  for (int i = 0; i < 6; ++i) {
    const double a = i * std::numbers::pi / 3.0;
    t.points.push_back({std::cos(a), std::sin(a)});
  }
  t.triangles = {{0, 2, 4}, {0, 1, 2}, {2, 3, 4}, {4, 5, 0}};
  t.neighbours = {{2, 3, 1}, {none, 0, none}, {none, 0, none}, {none, 0, none}};
  t.segment_of = {{none, none, none}, {1, none, 0}, {3, none, 2}, {5, none, 4}};
  return t;
}

// Ring links of a single counter-clockwise ring 0..n-1.
std::vector<BoundaryLinks> ring_links(std::uint32_t n) {
  std::vector<BoundaryLinks> links(n);
  for (std::uint32_t i = 0; i < n; ++i) links[i] = {(i + n - 1) % n, (i + 1) % n, 1.0f};
  return links;
}

// A star-shaped polygon with wobbly radius, as a Pslg (one ring, fixed seed).
madd::Pslg wobbly_polygon(std::uint32_t n, std::uint32_t seed) {
  madd::Pslg p;
  p.first_index = 0;
  std::uint32_t state = seed;
  for (std::uint32_t i = 0; i < n; ++i) {
    state = state * 1664525u + 1013904223u;
    const double r = 1.0 + 0.35 * ((state >> 8) / double(1u << 24));
    const double a = 2.0 * std::numbers::pi * i / n;
    p.points.push_back({r * std::cos(a), r * std::sin(a)});
    p.segments.push_back({i, (i + 1) % n, 1});
  }
  return p;
}

// Smallest angle between the segment at->towards and the ring edges at `at`,
// recomputed here with plain trigonometry (independent of boundary_angle).
double reference_angle(Point at, Point prev, Point next, Point towards) {
  auto dir = [](Point from, Point to) { return std::atan2(to.y - from.y, to.x - from.x); };
  auto ccw = [](double from, double to) {
    double d = to - from;
    while (d < 0) d += 2 * std::numbers::pi;
    while (d >= 2 * std::numbers::pi) d -= 2 * std::numbers::pi;
    return d * 180.0 / std::numbers::pi;
  };
  const double a1 = ccw(dir(at, next), dir(at, towards));
  const double a2 = ccw(dir(at, towards), dir(at, prev));
  return std::min(a1, a2);
}

}  // namespace

TEST_SUITE("medial") {

TEST_CASE("boundary_angle on a straight edge and at a reflex corner") {
  CHECK(madd::boundary_angle({0, 0}, {-1, 0}, {1, 0}, {0, 1}) == doctest::Approx(90.0));
  CHECK(madd::boundary_angle({0, 0}, {-1, 0}, {1, 0}, {1, 1}) == doctest::Approx(45.0));
  CHECK(madd::boundary_angle({0, 0}, {-1, 0}, {1, 0}, {0, -1}) < 0.0);  // outside the domain
  CHECK(madd::boundary_angle({0, 0}, {-1, 0}, {1, 0}, {2, 0}) < 0.0);   // along the boundary
  // Reflex corner (270 degree wedge): a diagonal into it makes 135 degrees with both edges.
  CHECK(madd::boundary_angle({0, 0}, {0, -1}, {1, 0}, {-1, 1}) == doctest::Approx(135.0));
  CHECK(madd::boundary_angle({0, 0}, {0, -1}, {1, 0}, {-1, -2}) ==
        doctest::Approx(std::atan(0.5) * 180.0 / std::numbers::pi));
}

TEST_CASE("junction triangle: the central triangle of a hexagon, depending on Phi0") {
  const Triangulation t = hexagon();
  const auto links = ring_links(6);
  // Spokes to the hexagon corners make exactly 60 degrees with the boundary,
  // and 120 degrees with each other.
  const madd::detail::JunctionTest at55 = madd::detail::test_junction(t, 0, links, 55.0);
  CHECK(at55.junction);
  CHECK(std::abs(at55.centre.x) < 1e-12);
  CHECK(std::abs(at55.centre.y) < 1e-12);
  CHECK((at55.spoke_ok[0] && at55.spoke_ok[1] && at55.spoke_ok[2]));
  for (double a : at55.spoke_angle) CHECK(a == doctest::Approx(60.0));
  CHECK_FALSE(madd::detail::test_junction(t, 0, links, 65.0).junction);
  // The ears do not contain their circumcentre (120 degree angle) and have two boundary edges.
  for (std::uint32_t ear = 1; ear < 4; ++ear) CHECK_FALSE(madd::detail::test_junction(t, ear, links, 30.0).junction);
}

TEST_CASE("junction triangle: an obtuse-free triangle with two good spokes only") {
  // Triangle (0,0),(2,0),(1,h) inside a domain whose ring is a square around
  // it; spokes are checked against the ring edges at each vertex.
  Triangulation t;
  t.points = {{0, 0}, {2, 0}, {1, 3}, {-5, 5}};
  // Triangle 0: (0,1,2); triangle 1: (0,2,3) closes a quad 0-1-2-3 (CCW).
  t.triangles = {{0, 1, 2}, {0, 2, 3}};
  t.neighbours = {{none, 1, none}, {none, none, 0}};
  t.segment_of = {{1, none, 0}, {2, 3, none}};
  const auto links = ring_links(4);
  // Triangle 0 has only one interior edge: property 2 fails whatever Phi0.
  CHECK_FALSE(madd::detail::test_junction(t, 0, links, 10.0).junction);
}

TEST_CASE("G_D of the hexagon and its contraction") {
  const Triangulation t = hexagon();
  const auto links = ring_links(6);
  const madd::MedialGraph g = madd::detail::build_medial_graph(t, links, {55.0, false});
  REQUIRE(g.gd.vertex_count() == 6);  // three sub-triangles + three ears
  REQUIRE(g.edges.size() == 6);       // three triangle edges + three spokes
  double total = 0.0;
  for (double w : g.gd.vertex_weights) total += w;
  CHECK(total == doctest::Approx(1.5 * std::sqrt(3.0)));  // hexagon area
  for (const madd::MedialEdge& e : g.edges) {
    const bool spoke = e.from >= 6 || e.to >= 6;
    CHECK(e.acceptable == spoke);  // hexagon diagonals make 30 degrees with the boundary
  }
  // Each ear merges with its sub-triangle: three vertices, one edge per spoke.
  CHECK(g.contracted.vertex_count() == 3);
  CHECK(g.contracted.edge_count() == 3);
  CHECK(g.separators.size() == 3);
  // Unweighted lengths: each G'_D edge weighs one spoke = circumradius 1.
  for (double w : g.contracted.edge_weights) CHECK(w == doctest::Approx(1.0));
}

TEST_CASE("contraction removes exactly the unacceptable edges (random polygons)") {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const madd::Pslg p = wobbly_polygon(40 + 7 * seed, seed);
    const Triangulation t = madd::triangulate(p);
    const auto links = ring_links(static_cast<std::uint32_t>(p.points.size()));
    const double phi = 50.0 + 3.0 * seed;
    const madd::MedialGraph g = madd::detail::build_medial_graph(t, links, {phi, true});
    // The public build reads the same ring links off the triangles' outer edges.
    CHECK(madd::build_medial_graph(t, {phi, true}) == g);
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (const madd::MedialEdge& e : g.edges) {
      const std::uint32_t a = g.coarse[e.left], b = g.coarse[e.right];
      if (!e.acceptable) {
        CHECK(a == b);
        continue;
      }
      if (a != b) expected.insert({std::min(a, b), std::max(a, b)});
      // An acceptable triangle edge really makes angles >= Phi0 at both ends.
      if (e.from < p.points.size() && e.to < p.points.size()) {
        for (auto [at, to] : {std::pair{e.from, e.to}, std::pair{e.to, e.from}}) {
          const double ref =
              reference_angle(t.points[at], t.points[links[at].prev], t.points[links[at].next], t.points[to]);
          CHECK(ref >= phi - 1e-9);
        }
      }
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> got;
    for (const auto& ends : g.contracted_ends) got.insert({ends[0], ends[1]});
    CHECK(got == expected);
    CHECK(g.contracted.edge_count() == expected.size());
    // Vertex weights are conserved: both graphs weigh the polygon's area.
    double gd = 0.0, cd = 0.0;
    for (double w : g.gd.vertex_weights) gd += w;
    for (double w : g.contracted.vertex_weights) cd += w;
    CHECK(gd == doctest::Approx(madd::domain_area(p)).epsilon(1e-12));
    CHECK(cd == doctest::Approx(gd).epsilon(1e-12));
    // Every junction centre lies inside its triangle.
    for (std::uint32_t tr = 0; tr < t.triangle_count(); ++tr) {
      if (g.centre[tr] == none) continue;
      const auto& v = t.triangles[tr];
      for (int i = 0; i < 3; ++i) {
        CHECK(madd::signed_area(t.points[v[i]], t.points[v[(i + 1) % 3]], g.points[g.centre[tr]]) > 0.0);
      }
    }
  }
}

}  // TEST_SUITE("medial")
