// triangulate() of general PSLGs (include/madd/triangulation.hpp): isolated
// vertices, interior and dangling segments, vertices on segments, point sets,
// no enclosing boundary, with and without the convex hull option. Counts come
// from Euler's formula, areas from shoelace sums, the kept triangles from an
// independent point-in-polygon test; verify_triangulation checks the rest.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "hull_points.hpp"
#include "madd/intersections.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

using madd::Point;

namespace {

const madd::TriangulateOptions hull_option{true};

using madd::test::hull_point_count;

double area_of(const madd::Triangulation& tri) {
  double a = 0;
  for (const auto& t : tri.triangles) a += madd::signed_area(tri.points[t[0]], tri.points[t[1]], tri.points[t[2]]);
  return a;
}

std::set<std::array<std::uint32_t, 3>> triangle_set(const madd::Triangulation& tri) {
  std::set<std::array<std::uint32_t, 3>> out;
  for (auto t : tri.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

void check_verified(const madd::Triangulation& tri, const madd::Pslg& p, const madd::TriangulateOptions& o) {
  const madd::Verification v = madd::verify_triangulation(tri, &p, o);
  CHECK_MESSAGE(v.ok(), (v.ok() ? std::string() : v.problems.front()));
}

// Strictly inside a counter-clockwise convex polygon, exactly.
bool inside_convex(const std::vector<Point>& poly, Point q) {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (!(madd::orient2d(poly[i], poly[(i + 1) % poly.size()], q) > 0)) return false;
  return true;
}

struct Scene {
  madd::Pslg pslg;
  std::vector<std::vector<Point>> polygons;  // closed, convex, counter-clockwise, disjoint
};

// Disjoint regular polygons on a grid of cells, random points (some inside
// the polygons), short open segments between the polygons, and four far
// corner points so the hull is a square well away from everything else.
Scene random_scene(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  madd::Pslg& p = s.pslg;
  p.points = {{-1, -1}, {6, -1}, {6, 6}, {-1, 6}};
  for (int cx = 0; cx < 5; ++cx) {
    for (int cy = 0; cy < 5; ++cy) {
      if (u(rng) < 0.4) {
        // A polygon in this cell.
        const int n = 3 + static_cast<int>(rng() % 6);
        const double r = 0.25 + 0.2 * u(rng), phase = u(rng);
        std::vector<Point> poly;
        const auto base = static_cast<std::uint32_t>(p.points.size());
        for (int k = 0; k < n; ++k) {
          const double a = phase + 2 * std::numbers::pi * k / n;
          poly.push_back({cx + 0.5 + r * std::cos(a), cy + 0.5 + r * std::sin(a)});
          p.points.push_back(poly.back());
          p.segments.push_back(
              {base + static_cast<std::uint32_t>(k), base + static_cast<std::uint32_t>((k + 1) % n), 0});
        }
        for (int k = static_cast<int>(rng() % 3); k > 0; --k)
          p.points.push_back({cx + 0.5 + 0.1 * (u(rng) - 0.5), cy + 0.5 + 0.1 * (u(rng) - 0.5)});  // inside it
        s.polygons.push_back(poly);
      } else if (u(rng) < 0.5) {
        // A dangling segment in the cell's corner, and a lone point.
        const auto base = static_cast<std::uint32_t>(p.points.size());
        p.points.push_back({cx + 0.05 + 0.1 * u(rng), cy + 0.05 + 0.1 * u(rng)});
        p.points.push_back({cx + 0.3 + 0.5 * u(rng), cy + 0.3 + 0.5 * u(rng)});
        p.segments.push_back({base, base + 1, 0});
        p.points.push_back({cx + 0.9, cy + 0.1 + 0.8 * u(rng)});
      }
    }
  }
  return s;
}

}  // namespace

TEST_SUITE("triangulate_pslg") {

TEST_CASE("random scenes: -c covers the hull (2n - 2 - h triangles), -p keeps exactly the polygons") {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    CAPTURE(seed);
    const Scene scene = random_scene(seed);
    const madd::Pslg& p = scene.pslg;
    madd::validate_pslg(p);
    const madd::Triangulation all = madd::triangulate(p, hull_option);
    check_verified(all, p, hull_option);
    CHECK(all.triangle_count() == 2 * p.points.size() - 2 - hull_point_count(p.points));
    CHECK(area_of(all) == doctest::Approx(49.0));

    const madd::Triangulation kept = madd::triangulate(p);
    check_verified(kept, p, {});
    // Per polygon of B vertices with I points inside: 2 (B + I) - B - 2 triangles.
    std::size_t expected = 0;
    double polygon_area = 0;
    for (const auto& poly : scene.polygons) {
      std::size_t inside = 0;
      for (const Point& q : p.points) inside += inside_convex(poly, q);
      expected += poly.size() + 2 * inside - 2;
      for (std::size_t k = 0; k < poly.size(); ++k)
        polygon_area += 0.5 * madd::cross(poly[k], poly[(k + 1) % poly.size()]);
    }
    CHECK(kept.triangle_count() == expected);
    CHECK(area_of(kept) == doctest::Approx(polygon_area));
    // Removal only: the kept triangles are triangles of the hull's CDT, each
    // with its centroid inside a polygon.
    const auto hull_triangles = triangle_set(all);
    for (const auto& t : triangle_set(kept)) {
      CHECK(hull_triangles.count(t) == 1);
      const Point c = (1.0 / 3.0) * (p.points[t[0]] + p.points[t[1]] + p.points[t[2]]);
      CHECK(std::any_of(scene.polygons.begin(), scene.polygons.end(),
                        [&](const auto& poly) { return inside_convex(poly, c); }));
    }
    // A hole point outside every polygon removes, with -c, what -p removes.
    madd::Pslg holed = p;
    holed.holes = {{-0.5, -0.5}};
    const madd::Triangulation carved = madd::triangulate(holed, hull_option);
    check_verified(carved, holed, hull_option);
    CHECK(triangle_set(carved) == triangle_set(kept));
    CHECK(madd::triangulate(p, hull_option) == all);  // deterministic
  }
}

TEST_CASE("isolated vertices, a vertex on a segment, T-, Y-junctions and dangling ends inside a square") {
  // The unit square; inside it an open polyline with a spur (a Y-junction at
  // (0.5, 0.5)), a segment from the boundary vertex (0, 0) inwards, a
  // segment ending exactly inside the polyline's first piece (a T-junction),
  // a point exactly on the bottom side, and lone points.
  madd::Pslg p;
  p.points = {{0, 0},      {1, 0},     {1, 1},       {0, 1},       {0.25, 0.5}, {0.5, 0.5}, {0.75, 0.75},
              {0.5, 0.25}, {0.2, 0.1}, {0.375, 0.5}, {0.375, 0.9}, {0.5, 0},    {0.9, 0.2}, {0.1, 0.8}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {5, 6, 2}, {5, 7, 3}, {0, 8, 4}, {10, 9, 5}};
  madd::validate_pslg(p);
  CHECK_NOTHROW(madd::validate(p));  // a domain with interior constraints, as decompose takes
  for (const madd::TriangulateOptions& o : {madd::TriangulateOptions{}, hull_option}) {
    const madd::Triangulation tri = madd::triangulate(p, o);
    check_verified(tri, p, o);
    // Every vertex is in the square; five lie on its boundary (4 corners and (0.5, 0)).
    CHECK(tri.triangle_count() == 2 * p.points.size() - 5 - 2);
    CHECK(area_of(tri) == doctest::Approx(1.0));
  }
}

TEST_CASE("no enclosing boundary: open polylines and points; -p keeps nothing, -c the hull") {
  madd::Pslg p;
  p.points = {{0, 0}, {2, 1}, {4, 0}, {1, 3}, {3, 3}, {2, 2}, {5, 2}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {3, 4, 0}};
  const madd::Triangulation none = madd::triangulate(p);
  check_verified(none, p, {});
  CHECK(none.triangle_count() == 0);
  CHECK(none.points == p.points);
  const madd::Triangulation hull = madd::triangulate(p, hull_option);
  check_verified(hull, p, hull_option);
  CHECK(hull.triangle_count() == 2 * p.points.size() - 2 - hull_point_count(p.points));
}

TEST_CASE("a point set keeps its convex hull with or without the option; all collinear gives nothing") {
  madd::Pslg p;
  p.points = {{0, 0}, {1, 0}, {0.5, 0.8}, {0.4, 0.3}, {2, 2}};
  for (const madd::TriangulateOptions& o : {madd::TriangulateOptions{}, hull_option}) {
    const madd::Triangulation tri = madd::triangulate(p, o);
    check_verified(tri, p, o);
    CHECK(tri.triangle_count() == 2 * p.points.size() - 2 - hull_point_count(p.points));
  }
  madd::Pslg line;
  line.points = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  line.segments = {{0, 3, 0}};
  const madd::Triangulation tri = madd::triangulate(line, hull_option);
  CHECK(tri.triangle_count() == 0);
  check_verified(tri, line, hull_option);
}

TEST_CASE("holes: a hole point removes its face, with and without the hull; one outside the hull does nothing") {
  // Two unit squares side by side sharing an edge, a hole point in the right one.
  madd::Pslg p;
  p.points = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}, {3, 3}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {4, 5, 0}, {5, 0, 0}, {1, 4, 0}};
  p.holes = {{1.5, 0.5}, {10, 10}};
  const madd::Triangulation left = madd::triangulate(p);
  check_verified(left, p, {});
  CHECK(area_of(left) == doctest::Approx(1.0));
  CHECK(left.triangle_count() == 2);
  const madd::Triangulation hull = madd::triangulate(p, hull_option);
  check_verified(hull, p, hull_option);
  // The hull is (0, 0), (2, 0), (3, 3), (0, 1): shoelace (0 + 6 + 3 + 0) / 2;
  // less the right square.
  CHECK(area_of(hull) == doctest::Approx(4.5 - 1.0));
}

TEST_CASE("the data/pslg inputs triangulate and verify; the crossing lanes once resolved") {
  for (const char* name : {"estuary.poly", "survey.poly", "crossing_lanes.poly"}) {
    CAPTURE(name);
    madd::PolyFile f = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/pslg/" + name);
    madd::ValidatePslgOptions allow;
    allow.allow_intersections = true;
    madd::validate_pslg(f.pslg, f.source, allow);
    const madd::Pslg p = madd::resolve_intersections(f.pslg).pslg;
    for (const madd::TriangulateOptions& o : {madd::TriangulateOptions{}, hull_option}) {
      const madd::Triangulation tri = madd::triangulate(p, o);
      check_verified(tri, p, o);
    }
  }
  // estuary (data/generate.py, estuary()): 25 vertices in the water (all but
  // the one in the hole), 10 of them on the shore and the hole's boundary,
  // one hole: 2 * 25 - 10 - 2 + 2 triangles; the shore is convex, so -c
  // keeps the same. crossing_lanes: 16 vertices and 4 new ones, all inside
  // the rectangle but its 4 corners: 2 * 20 - 4 - 2.
  const madd::Pslg estuary = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/pslg/estuary.poly").pslg;
  CHECK(madd::triangulate(estuary).triangle_count() == 40);
  CHECK(madd::triangulate(estuary, hull_option).triangle_count() == 40);
  const madd::ResolvedPslg lanes =
      madd::resolve_intersections(madd::read_poly_file(std::string(MADD_DATA_DIR) + "/pslg/crossing_lanes.poly").pslg);
  CHECK(lanes.new_vertices == 4);  // (4, 2) where three lanes meet, and where E crosses A, B and D
  CHECK(madd::triangulate(lanes.pslg).triangle_count() == 34);
}

TEST_CASE("regional attributes follow the triangles up to the segments; a later region point in the same region wins") {
  // The estuary's loop (6, 2), (8, 2), (7, 3.5) holds no vertex: one
  // triangle, with the region's attribute 2; every other kept triangle 0.
  madd::Pslg p = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/pslg/estuary.poly").pslg;
  madd::TriangulateOptions o;
  o.region_attributes = true;
  for (const bool hull : {false, true}) {
    o.convex_hull = hull;
    const madd::Triangulation tri = madd::triangulate(p, o);
    check_verified(tri, p, o);
    REQUIRE(tri.attributes.size() == tri.triangle_count());
    CHECK(std::count(tri.attributes.begin(), tri.attributes.end(), 2.0) == 1);
    CHECK(std::count(tri.attributes.begin(), tri.attributes.end(), 0.0) == 39);
    for (std::uint32_t t = 0; t < tri.triangle_count(); ++t)
      if (tri.attributes[t] == 2.0) {
        const Point c = (1.0 / 3.0) * (tri.points[tri.triangles[t][0]] + tri.points[tri.triangles[t][1]] +
                                       tri.points[tri.triangles[t][2]]);
        CHECK(inside_convex({{6, 2}, {8, 2}, {7, 3.5}}, c));
      }
  }
  // Two more region points in the water: the last one's attribute covers it;
  // one in the hole and one outside the shore change nothing.
  p.regions.push_back({{5, 1}, 7.0, -1.0});
  p.regions.push_back({{9, 4}, 9.0, -1.0});
  p.regions.push_back({{1.5, 1.2}, 11.0, -1.0});
  p.regions.push_back({{20, 20}, 13.0, -1.0});
  o.convex_hull = false;
  const madd::Triangulation tri = madd::triangulate(p, o);
  check_verified(tri, p, o);
  CHECK(std::count(tri.attributes.begin(), tri.attributes.end(), 2.0) == 1);
  CHECK(std::count(tri.attributes.begin(), tri.attributes.end(), 9.0) == 39);
  // Without the option there are none, and the triangles are the same.
  const madd::Triangulation plain = madd::triangulate(p);
  CHECK(plain.attributes.empty());
  CHECK(plain.triangles == tri.triangles);
  // The reader takes any real as an attribute, NaN too: it is still one region.
  madd::Pslg odd = p;
  odd.regions = {{{5, 1}, std::nan(""), -1.0}};
  const madd::Triangulation nan_region = madd::triangulate(odd, o);
  check_verified(nan_region, odd, o);
  CHECK(std::count_if(nan_region.attributes.begin(), nan_region.attributes.end(),
                      [](double a) { return std::isnan(a); }) == 39);
  // verify_triangulation catches an attribute that changes across an unconstrained edge.
  madd::Triangulation broken = tri;
  broken.attributes[0] += 1;
  CHECK(!madd::verify_triangulation(broken, &p, o).ok());
}

}  // TEST_SUITE("triangulate_pslg")
