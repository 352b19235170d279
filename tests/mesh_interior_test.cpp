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
#include <random>
#include <set>
#include <sstream>
#include <utility>

#include "interior_fixture.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_output.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "mesh/discretise.hpp"
#include "quality/area_bound.hpp"
#include "mesh/work.hpp"
#include "mesh_fixtures.hpp"

namespace {

using madd::Mesh;
using madd::Point;

double smallest_angle(const Mesh& m, std::size_t t) {
  double best = 180;
  for (int i = 0; i < 3; ++i)
    best =
        std::min(best, madd::degrees(madd::angle_at(m.points[m.triangles[t][i]], m.points[m.triangles[t][(i + 1) % 3]],
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
  return madd::mesh_decomposition(f.decomposition, f.domain, o).mesh;  // verify_mesh runs inside
}

}  // namespace

TEST_CASE(
    "mesh interior: each interior input segment is a chain of mesh edges, triangles of its subdomain on both sides") {
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
    CHECK(m.triangles.size() < 20000);       // refinement ended, and not at the budget
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

TEST_CASE("mesh interior: discretise splits interior pieces, keeps them interior, and resolves an isolated vertex near "
          "a separator") {
  madd::test::InteriorFixture f = madd::test::interior_fixture();
  // An isolated vertex 0.01 from the separator x = 2: the separator's pieces
  // near it must be no longer than half that distance.
  f.domain.points.push_back({2.01, 1.0});
  f.decomposition.points.push_back({2.01, 1.0});
  f.decomposition.subdomains[1].interior_points.push_back(17);
  madd::MeshSizeOptions size;
  size.max_triangle_area = 0.05;
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
  for (const madd::Subdomain& s : d.subdomains)
    CHECK(std::is_sorted(s.interior_segments.begin(), s.interior_segments.end()));
  // The mesh of it still verifies.
  madd::MeshOptions o = madd::test::options_for(2, 30, 0.05);
  CHECK_NOTHROW(madd::mesh_decomposition(f.decomposition, f.domain, o));
}

namespace {

madd::Pslg estuary() { return madd::read_domain(MADD_DATA_DIR "/estuary.poly"); }

}  // namespace

TEST_CASE(
    "mesh interior: the estuary through mesh(): interior segments kept, survey points as vertices, the loop's region") {
  const madd::Pslg domain = estuary();
  madd::MeshOptions o = madd::test::options_for(4, 30, 0.0);
  const Mesh m = madd::mesh(domain, o);
  CHECK(m.subdomain_count() == 4);
  // Every input vertex is a mesh vertex (isolated survey points included).
  std::vector<int> used(m.points.size(), 0);
  for (const auto& t : m.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  for (std::uint32_t v = 0; v < domain.points.size(); ++v) CHECK(used[v] == 1);
  // Every input segment is covered by mesh segments lying on it, their
  // lengths adding up to its own; those inside the domain have triangles of
  // one subdomain on both sides.
  const auto edges = edges_of(m);
  std::vector<double> covered(domain.segments.size(), 0.0);
  for (const madd::MeshSegment& s : m.segments) {
    const std::uint32_t origin = m.decomposition.segment_origin[s.piece];
    if (origin == madd::no_index) continue;
    const madd::Segment& in = domain.segments[origin];
    const Point a = domain.points[in.a], b = domain.points[in.b];
    CHECK(off_line(a, b, m.points[s.a]) < 1e-12);
    CHECK(off_line(a, b, m.points[s.b]) < 1e-12);
    covered[origin] += madd::distance(m.points[s.a], m.points[s.b]);
    const auto& users = edges.at({std::min(s.a, s.b), std::max(s.a, s.b)});
    if (users.size() == 2) CHECK(m.triangle_subdomain[users[0]] == m.triangle_subdomain[users[1]]);
  }
  std::size_t interior_edges = 0;
  for (const auto& [e, users] : edges)
    if (users.size() == 2 && m.triangle_subdomain[users[0]] == m.triangle_subdomain[users[1]])
      for (const madd::MeshSegment& s : m.segments)
        interior_edges += std::min(s.a, s.b) == e.first && std::max(s.a, s.b) == e.second;
  CHECK(interior_edges > 20);
  for (std::uint32_t i = 0; i < domain.segments.size(); ++i) {
    const double length = madd::distance(domain.points[domain.segments[i].a], domain.points[domain.segments[i].b]);
    CHECK(covered[i] == doctest::Approx(length).epsilon(1e-12));
  }
  // The loop (input vertices 10, 11, 12: a triangle) holds the region:
  // attribute 2 and area at most 0.05 inside, attribute 0 outside.
  const std::vector<Point> loop = {domain.points[10], domain.points[11], domain.points[12]};
  std::size_t inside = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& c = m.triangles[t];
    const Point g = madd::triangle_centroid(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
    const bool in = madd::test::inside_convex(loop, g);
    inside += in;
    CHECK(m.triangle_attribute[t] == (in ? 2.0 : 0.0));
    if (in) CHECK(madd::triangle_area(m.points[c[0]], m.points[c[1]], m.points[c[2]]) <= 0.05 * (1 + 1e-12));
  }
  CHECK(inside >= 30);  // area 1.5 in triangles of at most 0.05
  // Below the bound only at the small input angles (the groyne meets the
  // levee at 19.8 degrees).
  CHECK(m.shortfall.total() == m.shortfall.input_angle);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (smallest_angle(m, t) < 30 - 1e-9)
      // Near it: within the first pieces of the arms (about 0.6 long here,
      // depending on where the separators split the levee).
      for (const std::uint32_t v : m.triangles[t]) CHECK(madd::distance(m.points[v], domain.points[20]) < 1.0);
}

TEST_CASE("mesh interior: the estuary's mesh is the same for 1, 2 and 3 threads") {
  const madd::Pslg domain = estuary();
  madd::MeshOptions o = madd::test::options_for(6, 30, 0.02);
  const Mesh one = madd::mesh(domain, o);
  o.decomposition.threads = 2;
  CHECK(one == madd::mesh(domain, o));
  o.decomposition.threads = 3;
  CHECK(one == madd::mesh(domain, o));
}

TEST_CASE("mesh interior: the .edge file gives interior-segment edges their marker, separators 0") {
  const Mesh m = mesh_fixture(30, 0.05, 1);
  const std::vector<std::uint32_t> owner = madd::interior_segment_owners(m.decomposition);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> want;  // 1-based vertex ids
  for (const madd::MeshSegment& s : m.segments)
    if (owner[s.piece] != madd::no_index || m.decomposition.is_separator(s.piece))
      want[{std::min(s.a, s.b) + 1, std::max(s.a, s.b) + 1}] = s.marker;
  std::istringstream in(madd::format_mesh_edge(m, 1));
  std::size_t count = 0, markers = 0, found = 0;
  in >> count >> markers;
  for (std::size_t e = 0; e < count; ++e) {
    std::uint32_t id = 0, a = 0, b = 0;
    int marker = 0;
    in >> id >> a >> b >> marker;
    const auto it = want.find({std::min(a, b), std::max(a, b)});
    if (it == want.end()) continue;
    CHECK(marker == it->second);
    ++found;
  }
  CHECK(found == want.size());
}

TEST_CASE("mesh interior: the work estimate counts a region's finer bound (the Steiner point budget follows it)") {
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  const madd::MeshSizeOptions none;
  const madd::detail::AreaBound field(none);
  const std::vector<double> work = madd::detail::expected_triangles(madd::discretise(f.decomposition, none),
                                                                    madd::detail::DomainWork(f.domain, field));
  REQUIRE(work.size() == 2);
  // The loop's unit of area at 0.002: some 775 triangles in subdomain 1,
  // where the size bound alone (none) expects a few along the pieces.
  CHECK(work[1] > 500);
  CHECK(work[1] > 5 * work[0]);
  // And what it was refined to agrees within a factor of two.
  const Mesh m = mesh_fixture(30, 0.0, 1);
  const double made = m.subdomain_first_triangle[2] - m.subdomain_first_triangle[1];
  CHECK(made > 0.5 * work[1]);
  CHECK(made < 2.0 * work[1]);
}

namespace {

double segment_distance(Point a, Point b, Point c, Point d) {
  const auto point_segment = [](Point p, Point u, Point v) {
    const Point uv = v - u;
    const double t = std::clamp(madd::dot(p - u, uv) / madd::dot(uv, uv), 0.0, 1.0);
    return madd::distance(p, u + t * uv);
  };
  const bool crosses =
      madd::orient2d(a, b, c) * madd::orient2d(a, b, d) < 0 && madd::orient2d(c, d, a) * madd::orient2d(c, d, b) < 0;
  if (crosses) return 0.0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

// The square [0, 10]^2 with `count` random disjoint interior segments (at
// least 0.2 apart and from the boundary), three isolated vertices and two
// region points (the later's attribute wins: the segments close no face).
madd::Pslg random_interior_domain(std::uint32_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  madd::Pslg p;
  p.first_index = 0;
  p.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  std::vector<std::pair<Point, Point>> placed;
  while (static_cast<int>(placed.size()) < count) {
    const Point c{1 + 8 * u(rng), 1 + 8 * u(rng)};
    const double angle = 2 * std::numbers::pi * u(rng), half = 0.25 + 0.75 * u(rng);
    const Point d{half * std::cos(angle), half * std::sin(angle)};
    const Point a = c - d, b = c + d;
    bool ok = std::min({a.x, a.y, b.x, b.y}) > 0.2 && std::max({a.x, a.y, b.x, b.y}) < 9.8;
    for (const auto& s : placed) ok = ok && segment_distance(a, b, s.first, s.second) > 0.2;
    if (!ok) continue;
    placed.emplace_back(a, b);
    const auto i = static_cast<std::uint32_t>(p.points.size());
    p.points.push_back(a);
    p.points.push_back(b);
    p.segments.push_back({i, i + 1, 2 + static_cast<int>(placed.size())});
  }
  for (int k = 0; k < 3;) {
    const Point q{0.5 + 9 * u(rng), 0.5 + 9 * u(rng)};
    bool ok = true;
    for (const auto& s : placed) ok = ok && segment_distance(q, q, s.first, s.second) > 0.2;
    if (!ok) continue;
    p.points.push_back(q);
    ++k;
  }
  p.has_segment_markers = true;
  p.regions = {{{0.1, 0.1}, 7.0, 0.05}, {{9.9, 9.9}, 4.0 + seed, 0.5}};
  return p;
}

}  // namespace

TEST_CASE("mesh interior: random interior segments and isolated vertices, N = 1 and 3, q 30: verified, every attribute "
          "the later region's") {
  int decomposed = 0;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    for (const std::uint32_t n : {1u, 3u}) {
      CAPTURE(seed);
      CAPTURE(n);
      const madd::Pslg domain = random_interior_domain(seed, n == 1 ? 8 : 4);
      madd::validate(domain);
      madd::MeshOptions o = madd::test::options_for(n, 30, 0.0);
      Mesh m;
      try {
        m = madd::mesh(domain, o);  // verify_mesh runs inside: InternalError on any broken invariant
      } catch (const madd::DecompositionError& e) {
        REQUIRE(n > 1);                                        // one subdomain needs no separator
        MESSAGE("not decomposed: " << std::string(e.what()));  // the decomposition's limits, not the mesher's
        continue;
      }
      decomposed += n > 1;
      CHECK(m.shortfall.total() == 0);  // disjoint segments: no small input angle anywhere
      for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        CHECK(m.triangle_attribute[t] == 4.0 + seed);
        const auto& c = m.triangles[t];
        CHECK(madd::triangle_area(m.points[c[0]], m.points[c[1]], m.points[c[2]]) <= 0.5 * (1 + 1e-12));
      }
      // Every input vertex a mesh vertex.
      std::vector<int> used(m.points.size(), 0);
      for (const auto& t : m.triangles)
        for (const std::uint32_t v : t) used[v] = 1;
      for (std::uint32_t v = 0; v < domain.points.size(); ++v) CHECK(used[v] == 1);
    }
  }
  CHECK(decomposed >= 2);
}

TEST_CASE("mesh interior: a Y junction of interior segments with a 10-degree sector terminates; below the bound only "
          "inside that sector") {
  madd::Pslg p;
  p.first_index = 0;
  const double a10 = 10.0 * std::numbers::pi / 180.0;
  p.points = {{0, 0},    {4, 0}, {4, 4}, {0, 4}, {2, 2}, {3.2, 2}, {2 + 1.2 * std::cos(a10), 2 + 1.2 * std::sin(a10)},
              {1.2, 2.8}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {4, 6, 2}, {4, 7, 2}};
  madd::validate(p);
  for (const double q : {28.0, 32.0}) {
    CAPTURE(q);
    const Mesh m = madd::mesh(p, madd::test::options_for(1, q, 0.0));
    CHECK(m.shortfall.total() == m.shortfall.input_angle);
    CHECK(m.shortfall.total() > 0);
    CHECK(m.triangles.size() < 20000);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (smallest_angle(m, t) >= q - 1e-9) continue;
      const auto& c = m.triangles[t];
      const Point g = madd::triangle_centroid(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
      const double direction = std::atan2(g.y - 2, g.x - 2);
      CHECK(direction > 0);
      CHECK(direction < a10);
      CHECK(madd::distance(g, {2, 2}) < 1.2);
    }
  }
}

TEST_CASE("mesh interior: an interior segment leaving the boundary at 0.3 degrees terminates") {
  madd::Pslg p;
  p.first_index = 0;
  const double tiny = 0.3 * std::numbers::pi / 180.0;
  p.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 0}, {2 + 1.5 * std::cos(tiny), 1.5 * std::sin(tiny)}};
  p.segments = {{0, 4, 1}, {4, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}};
  madd::validate(p);
  for (const double q : {25.0, 30.0, 33.0}) {
    CAPTURE(q);
    const Mesh m = madd::mesh(p, madd::test::options_for(1, q, 0.0));
    CHECK(m.shortfall.total() == m.shortfall.input_angle);
    CHECK(m.triangles.size() < 20000);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (smallest_angle(m, t) >= q - 1e-9) continue;
      for (const std::uint32_t v : m.triangles[t]) {
        const Point x = m.points[v];
        CHECK(x.x >= 2 - 1e-12);  // inside the wedge between y = 0 and the segment
        CHECK(x.y <= (x.x - 2) * std::tan(tiny) + 1e-12);
      }
    }
  }
}
