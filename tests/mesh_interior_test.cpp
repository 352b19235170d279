// The mesher with interior constraints and regions (docs/mesh.md, "Interior
// constraints and regions"), on the hand-made decomposition of
// tests/interior_fixture.hpp: interior segments kept edge for edge with the
// subdomain on both sides, isolated vertices as mesh vertices, the angle
// bound away from the small input angles, the regional area bound, the
// region attributes against a point-in-polygon classification, and the same
// mesh for any thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "interior_fixture.hpp"
#include "madd/mesh.hpp"
#include "madd/predicates.hpp"
#include "mesh/discretise.hpp"
#include "mesh_fixtures.hpp"

namespace {

using madd::Mesh;
using madd::Point;

double smallest_angle(const Mesh& m, std::size_t t) {
  double best = 180;
  for (int i = 0; i < 3; ++i)
    best = std::min(best, madd::degrees(madd::angle_at(m.points[m.triangles[t][i]], m.points[m.triangles[t][(i + 1) % 3]],
                                                       m.points[m.triangles[t][(i + 2) % 3]])));
  return best;
}

// Each undirected triangle edge -> the triangles that have it.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges_of(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> out;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.triangles[t][(i + 1) % 3], b = m.triangles[t][(i + 2) % 3];
      out[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  return out;
}

// Distance from q to the line through a and b, over |ab|.
double off_line(Point a, Point b, Point q) { return std::abs(madd::cross(b - a, q - a)) / madd::dot(b - a, b - a); }

Mesh mesh_fixture(double q, double area, unsigned threads) {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  madd::MeshOptions o = madd::test::options_for(2, q, area);
  o.decomposition.threads = threads;
  madd::MeshReport report;
  return madd::mesh_decomposition(f.decomposition, f.domain, o, report);  // verify_mesh runs inside
}

} // namespace

TEST_CASE("mesh interior: each interior input segment is a chain of mesh edges, triangles of its subdomain on both sides") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  const Mesh m = mesh_fixture(30, 0.05, 1);
  const auto edges = edges_of(m);
  // Vertex adjacency through triangle edges.
  std::map<std::uint32_t, std::set<std::uint32_t>> next;
  for (const auto& [e, users] : edges) {
    next[e.first].insert(e.second);
    next[e.second].insert(e.first);
  }
  for (const std::uint32_t s : f.interior_input_segments) {
    const madd::Segment& seg = f.domain.segments[s];
    const Point a = f.domain.points[seg.a], b = f.domain.points[seg.b];
    const std::uint32_t owner = b.x <= 2 && a.x <= 2 ? 0 : 1;
    // Walk from a to b through mesh vertices on the segment, each step forward.
    std::uint32_t cur = seg.a;
    std::size_t steps = 0;
    while (cur != seg.b) {
      std::uint32_t step = madd::no_index;
      for (const std::uint32_t w : next[cur]) {
        const Point p = m.points[w];
        if (off_line(a, b, p) > 1e-12 || madd::dot(p - m.points[cur], b - a) <= 0) continue;
        if (madd::dot(p - a, b - a) > madd::dot(b - a, b - a) * (1 + 1e-12)) continue;
        step = w;
      }
      REQUIRE(step != madd::no_index);  // the chain goes on along the segment
      const auto& users = edges.at({std::min(cur, step), std::max(cur, step)});
      REQUIRE(users.size() == 2);
      CHECK(m.triangle_subdomain[users[0]] == owner);
      CHECK(m.triangle_subdomain[users[1]] == owner);
      cur = step;
      ++steps;
    }
    CHECK(steps >= 1);
  }
  // The mesh segments on interior pieces carry the input's markers.
  for (const madd::MeshSegment& s : m.segments) {
    const std::uint32_t origin = m.decomposition.segment_origin[s.piece];
    if (origin != madd::no_index) CHECK(s.marker == f.domain.segments[origin].marker);
  }
}

TEST_CASE("mesh interior: isolated input vertices are vertices of their subdomain's triangles") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  const Mesh m = mesh_fixture(30, 0.05, 1);
  for (const std::uint32_t v : f.isolated) {
    bool found = false;
    for (std::uint32_t t = m.subdomain_first_triangle[1]; t < m.subdomain_first_triangle[2]; ++t)
      found |= std::find(m.triangles[t].begin(), m.triangles[t].end(), v) != m.triangles[t].end();
    CHECK(found);
    CHECK(m.points[v] == f.domain.points[v]);
    CHECK(m.point_markers[v] == 0);
  }
}

TEST_CASE("mesh interior: every angle >= q but at the 2.9-degree angle between the dangling segment and the boundary") {
  for (const double q : {25.0, 30.0, 33.0}) {
    CAPTURE(q);
    const madd::test::InteriorFixture f = madd::test::interior_fixture();
    const Mesh m = mesh_fixture(q, 0.0, 1);  // no size bound: only the features and the angles grade the mesh
    CHECK(m.triangles.size() < 20000);        // refinement ended, and not at the budget
    CHECK(m.shortfall.limit == 0);
    CHECK(m.shortfall.total() == m.shortfall.input_angle);
    const Point corner = f.domain.points[6];
    std::size_t below = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (smallest_angle(m, t) >= q - 1e-9) continue;
      ++below;
      // Within the wedge between the boundary x = 0 and the dangling
      // segment: x below the segment's line at that height.
      for (const std::uint32_t v : m.triangles[t]) {
        const Point p = m.points[v];
        CHECK(p.y >= corner.y - 1e-12);
        CHECK(p.y <= 1.8 + 1e-12);
        CHECK(p.x <= 0.05 * (p.y - 1.0) + 1e-12);
      }
    }
    CHECK(below == m.shortfall.total());
  }
}

TEST_CASE("mesh interior: the region's area bound holds inside the loop, the global bound elsewhere") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  const Mesh m = mesh_fixture(30, 0.05, 1);
  std::size_t inside = 0;
  for (const auto& t : m.triangles) {
    const Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    const double area = madd::triangle_area(a, b, c);
    const bool in_loop = madd::test::inside_convex(f.loop, madd::triangle_centroid(a, b, c));
    inside += in_loop;
    CHECK(area <= (in_loop ? 0.002 : 0.05) * (1 + 1e-12));
  }
  // The loop holds 1 unit of area: at least 500 triangles of at most 0.002.
  CHECK(inside >= 500);
}

TEST_CASE("mesh interior: region attributes equal a point-in-polygon classification of the centroids") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  for (const double area : {0.0, 0.05}) {
    const Mesh m = mesh_fixture(30, area, 1);
    REQUIRE(m.triangle_attribute.size() == m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& c = m.triangles[t];
      const Point g = madd::triangle_centroid(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
      // Inside the loop: region 1 (5); outside: regions 0 and 2 share the
      // face across the separator, and the later, 2 (3), wins.
      CHECK(m.triangle_attribute[t] == (madd::test::inside_convex(f.loop, g) ? 5.0 : 3.0));
    }
  }
}

TEST_CASE("mesh interior: the same mesh for 1, 2 and 3 threads") {
  const Mesh one = mesh_fixture(30, 0.01, 1);
  CHECK(one == mesh_fixture(30, 0.01, 2));
  CHECK(one == mesh_fixture(30, 0.01, 3));
}

TEST_CASE("mesh interior: discretise splits interior pieces, keeps them interior, and resolves an isolated vertex near a separator") {
  madd::test::InteriorFixture f = madd::test::interior_fixture();
  // An isolated vertex 0.01 from the separator x = 2: the separator's pieces
  // near it must be no longer than half that distance.
  f.domain.points.push_back({2.01, 1.0});
  f.decomposition.points.push_back({2.01, 1.0});
  f.decomposition.subdomains[1].interior_points.push_back(17);
  madd::MeshSizeOptions size;
  size.max_area = 0.05;
  const madd::Decomposition d = madd::discretise(f.decomposition, size);
  const std::vector<std::uint32_t> owner = madd::interior_segment_owners(d);
  std::size_t interior = 0;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    const Point a = d.points[d.segments[j].a], b = d.points[d.segments[j].b];
    CHECK(madd::distance(a, b) <= 1.2408 * std::sqrt(0.05));
    if (owner[j] != madd::no_index) {
      ++interior;
      CHECK(d.segment_origin[j] != madd::no_index);
      CHECK(owner[j] == (a.x < 2 ? 0u : 1u));
    }
    // No separator piece's diametral circle holds the vertex (with the size
    // bound alone, pieces of 0.26 would).
    if (d.is_separator(j)) CHECK(madd::distance(madd::midpoint(a, b), Point{2.01, 1.0}) > 0.5 * madd::distance(a, b));
  }
  CHECK(interior > 7);
  for (const madd::Subdomain& s : d.subdomains) CHECK(std::is_sorted(s.interior_segments.begin(), s.interior_segments.end()));
  // The mesh of it still verifies.
  madd::MeshOptions o = madd::test::options_for(2, 30, 0.05);
  madd::MeshReport report;
  CHECK_NOTHROW(madd::mesh_decomposition(f.decomposition, f.domain, o, report));
}
