// Tests for delaunay(), triangulate() and verify_triangulation(): brute-force
// checks on small inputs, degenerate inputs, constrained domains with holes;
// and `madd triangulate` of a points-only .node file, run as a program.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "hull_points.hpp"
#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "triangulation/exact_area.hpp"
#include "random_points.hpp"

namespace {

using madd::Point;

using madd::test::random_points;

using madd::test::hull_point_count;

std::string problems(const madd::Verification& v) {
  std::string s;
  for (const auto& p : v.problems) s += p + "\n";
  return s;
}

// Every triangle's circumcircle is empty of every input point (exact incircle),
// and the triangle count is 2n - h - 2.
void check_brute_force_delaunay(const std::vector<Point>& pts, const madd::Triangulation& tri) {
  for (const auto& t : tri.triangles) {
    for (const Point& p : pts) {
      REQUIRE(madd::incircle(pts[t[0]], pts[t[1]], pts[t[2]], p) <= 0);
    }
  }
  CHECK(tri.triangle_count() == 2 * pts.size() - hull_point_count(pts) - 2);
}

double total_area(const madd::Triangulation& tri) {
  double a = 0;
  for (const auto& t : tri.triangles) a += madd::signed_area(tri.points[t[0]], tri.points[t[1]], tri.points[t[2]]);
  return a;
}

// Closed ring of points appended to `pslg`, each edge one segment.
void add_ring(madd::Pslg& pslg, const std::vector<Point>& ring, int marker) {
  const auto base = static_cast<std::uint32_t>(pslg.points.size());
  const auto n = static_cast<std::uint32_t>(ring.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    pslg.points.push_back(ring[i]);
    pslg.segments.push_back({base + i, base + (i + 1) % n, marker});
  }
}

std::vector<Point> circle(std::size_t n, Point c, double r, double phase, bool cw) {
  std::vector<Point> pts(n);
  const double s = cw ? -1.0 : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = phase + s * 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    pts[i] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  return pts;
}

// A random star-shaped polygon with `k` circular holes (like gen_poly.py star).
madd::Pslg star_with_holes(std::size_t n, std::size_t k, std::size_t m, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  madd::Pslg pslg;
  std::vector<Point> outer(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (static_cast<double>(i) + 0.1 + 0.8 * u(rng)) / static_cast<double>(n);
    const double r = 1 + 0.1 * std::cos(3 * t) + 0.05 * std::sin(5 * t) +
                     0.3 * (2 * std::numbers::pi / static_cast<double>(n)) * (u(rng) - 0.5);
    outer[i] = {r * std::cos(t), r * std::sin(t)};
  }
  add_ring(pslg, outer, 1);
  const double rh = 0.12 / std::sqrt(static_cast<double>(std::max<std::size_t>(k, 1)));
  for (std::size_t h = 0; h < k; ++h) {
    // Holes on a ring of radius 0.45, far enough apart not to touch.
    const double a = 2 * std::numbers::pi * static_cast<double>(h) / static_cast<double>(k);
    const Point c{0.45 * std::cos(a), 0.45 * std::sin(a)};
    add_ring(pslg, circle(m, c, rh, u(rng), true), static_cast<int>(h + 2));
    pslg.holes.push_back(c);
  }
  return pslg;
}

// Points as a Triangle .node file with 1-based ids.
std::string node_text(const std::vector<Point>& pts) {
  std::string text = std::to_string(pts.size()) + " 2 0 0\n";
  char line[96];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::snprintf(line, sizeof line, "%zu %.17g %.17g\n", i + 1, pts[i].x, pts[i].y);
    text += line;
  }
  return text;
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Reads Triangle's .ele and .neigh files (1-based ids, -1 for no neighbour)
// back into `tri`.
void read_ele_neigh(const std::string& ele, const std::string& neigh, madd::Triangulation& tri) {
  std::istringstream e(ele), n(neigh);
  std::size_t count = 0, corners = 0, attributes = 0, neigh_count = 0, sides = 0;
  e >> count >> corners >> attributes;
  n >> neigh_count >> sides;
  REQUIRE(corners == 3);
  REQUIRE(neigh_count == count);
  tri.triangles.resize(count);
  tri.neighbours.resize(count);
  tri.segment_of.assign(count, {madd::no_index, madd::no_index, madd::no_index});
  for (std::size_t t = 0; t < count; ++t) {
    long long id = 0, nid = 0;
    e >> id;
    n >> nid;
    REQUIRE(id == static_cast<long long>(t + 1));
    REQUIRE(nid == id);
    for (int i = 0; i < 3; ++i) {
      long long v = 0, u = 0;
      e >> v;
      n >> u;
      tri.triangles[t][i] = static_cast<std::uint32_t>(v - 1);
      tri.neighbours[t][i] = u < 0 ? madd::no_index : static_cast<std::uint32_t>(u - 1);
    }
  }
  REQUIRE(e);
  REQUIRE(n);
}

void check_constrained(const madd::Pslg& pslg) {
  const madd::Triangulation tri = madd::triangulate(pslg);
  const madd::Verification v = madd::verify_triangulation(tri, &pslg);
  CHECK_MESSAGE(v.ok(), problems(v));
  CHECK(tri == madd::triangulate(pslg));  // deterministic
}

// Issue 13: an outside run of fuzz_triangulate found this needle, 1e11 long
// and 0.02 wide near (1e9, 1e9). Its 4 triangles (Triangle makes the same 4)
// are right, exactly; the check summed floating-point triangle areas, off by
// 208 in 990159056 (relative 2e-7), against a fixed relative 1e-9.
constexpr const char* issue13_needle = "6 2 0 0\n"
                                       "1 1040000000.0 100000000030\n"
                                       "2 1000000000.02 1000000000.0\n"
                                       "3 1000000000.01 1000000000.004\n"
                                       "4 1000000000.006 1000000000.004\n"
                                       "5 1000000000.006 1000000000.008\n"
                                       "6 1000000000.0 1000000000.008\n"
                                       "6 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 5 1\n5 5 6 1\n6 6 1 1\n0\n";

// A needle from `base` towards direction `angle`, `length` long, whose blunt
// end is a zigzag of 5 vertices `width` across: cancellation in every
// floating-point area of it grows with length / width.
madd::Pslg needle(Point base, double angle, double length, double width) {
  const double c = std::cos(angle), s = std::sin(angle);
  madd::Pslg p;
  p.first_index = 0;
  p.points.push_back({base.x + length * c, base.y + length * s});
  for (int k = 4; k >= 0; --k) {
    const double across = width * k / 4, back = (k % 2) * width / 5;
    p.points.push_back({base.x + across * s - back * c, base.y - across * c - back * s});
  }
  for (std::uint32_t k = 0; k < 6; ++k) p.segments.push_back({k, (k + 1) % 6, 0});
  return p;
}

}  // namespace

TEST_SUITE("triangulation") {
TEST_CASE("brute-force Delaunay on small random sets") {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    for (std::size_t n : {3u, 4u, 5u, 10u, 50u, 300u}) {
      const auto pts = random_points(n, seed * 1000 + static_cast<unsigned>(n));
      const madd::Triangulation tri = madd::delaunay(pts);
      CAPTURE(n);
      CAPTURE(seed);
      CHECK_MESSAGE(madd::verify_triangulation(tri).ok(), problems(madd::verify_triangulation(tri)));
      check_brute_force_delaunay(pts, tri);
    }
  }
}

TEST_CASE("large random sets verify and are deterministic") {
  for (std::size_t n : {1000u, 20000u, 100000u}) {
    const auto pts = random_points(n, 77);
    const madd::Triangulation tri = madd::delaunay(pts);
    const auto v = madd::verify_triangulation(tri);
    CHECK_MESSAGE(v.ok(), problems(v));
    CHECK(tri.triangle_count() == 2 * n - hull_point_count(pts) - 2);
    CHECK(tri == madd::delaunay(pts));
  }
}

TEST_CASE("integer lattice (massively cocircular)") {
  for (int side : {2, 3, 7, 40}) {
    std::vector<Point> pts;
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) pts.push_back({static_cast<double>(i), static_cast<double>(j)});
    const madd::Triangulation tri = madd::delaunay(pts);
    const auto v = madd::verify_triangulation(tri);
    CHECK_MESSAGE(v.ok(), problems(v));
    CHECK(tri.triangle_count() == 2 * static_cast<std::size_t>((side - 1) * (side - 1)));
    CHECK(total_area(tri) == doctest::Approx((side - 1) * (side - 1)));
    check_brute_force_delaunay(pts, tri);
  }
}

TEST_CASE("exactly cocircular integer points") {
  // All integer points with x^2 + y^2 = 5525 (= 5^2 * 13 * 17): many, exactly on one circle.
  std::vector<Point> pts;
  for (int x = -75; x <= 75; ++x)
    for (int y = -75; y <= 75; ++y)
      if (x * x + y * y == 5525) pts.push_back({static_cast<double>(x), static_cast<double>(y)});
  REQUIRE(pts.size() >= 16);
  const madd::Triangulation tri = madd::delaunay(pts);
  CHECK(madd::verify_triangulation(tri).ok());
  CHECK(tri.triangle_count() == pts.size() - 2);
  CHECK(tri == madd::delaunay(pts));
}

TEST_CASE("points on a circle and a regular polygon") {
  const auto pts = circle(5000, {0.5, -2.0}, 3.0, 0.1, false);
  const madd::Triangulation tri = madd::delaunay(pts);
  const auto v = madd::verify_triangulation(tri);
  CHECK_MESSAGE(v.ok(), problems(v));
  CHECK(tri.triangle_count() == 2 * pts.size() - hull_point_count(pts) - 2);
  madd::Pslg poly;
  add_ring(poly, circle(20000, {0, 0}, 1.0, 0.0, false), 1);
  check_constrained(poly);
}

TEST_CASE("collinear points give no triangles") {
  std::vector<Point> line;
  for (int i = 0; i < 1000; ++i) line.push_back({0.5 * i, 3.0 - 0.25 * i});
  std::shuffle(line.begin(), line.end(), std::mt19937(3));
  CHECK(madd::delaunay(line).triangle_count() == 0);
  CHECK(madd::delaunay(std::vector<Point>{}).triangle_count() == 0);
  CHECK(madd::delaunay(std::vector<Point>{{1, 1}}).triangle_count() == 0);
  CHECK(madd::delaunay(std::vector<Point>{{1, 1}, {2, 2}}).triangle_count() == 0);
  line.push_back(line[17]);
  CHECK_THROWS_AS(madd::delaunay(line), madd::InvalidInputError);
}

TEST_CASE("collinear prefix then a point off the line") {
  std::vector<Point> pts;
  for (int i = 0; i < 100; ++i) pts.push_back({static_cast<double>(i), 0.0});
  pts.push_back({50.0, 1.0});
  pts.push_back({50.0, -1.0});
  const madd::Triangulation tri = madd::delaunay(pts);
  CHECK(madd::verify_triangulation(tri).ok());
  check_brute_force_delaunay(pts, tri);
}

TEST_CASE("duplicate points are rejected") {
  auto pts = random_points(500, 9);
  pts.push_back(pts[123]);
  try {
    (void)madd::delaunay(pts);
    FAIL("no error");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == madd::InputProblem::duplicate_vertex);
    CHECK(e.ids() == std::vector<std::int64_t>{123, 500});
  }
  CHECK_THROWS_AS(madd::delaunay(std::vector<Point>{{0, 0}, {0, 0}, {1, 0}}), madd::InvalidInputError);
}

TEST_CASE("near-degenerate perturbations of a few ulps") {
  std::mt19937 rng(5);
  std::vector<Point> pts;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      double x = 1.0 + i * 0.125, y = 2.0 + j * 0.125;
      for (int k = static_cast<int>(rng() % 4); k > 0; --k) x = std::nextafter(x, (rng() & 1) ? 10.0 : -10.0);
      for (int k = static_cast<int>(rng() % 4); k > 0; --k) y = std::nextafter(y, (rng() & 1) ? 10.0 : -10.0);
      pts.push_back({x, y});
    }
  }
  // Nearly collinear too: a line with ulp noise.
  for (int i = 0; i < 200; ++i) {
    double y = 0.1 + 0.3 * (0.01 * i);
    for (int k = static_cast<int>(rng() % 3); k > 0; --k) y = std::nextafter(y, 1.0);
    pts.push_back({0.01 * i - 1.0, y});
  }
  const madd::Triangulation tri = madd::delaunay(pts);
  const auto v = madd::verify_triangulation(tri);
  CHECK_MESSAGE(v.ok(), problems(v));
  check_brute_force_delaunay(pts, tri);
}

TEST_CASE("square with a square hole") {
  madd::Pslg pslg;
  add_ring(pslg, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 1);
  add_ring(pslg, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}, 2);
  pslg.holes.push_back({2, 2});
  const madd::Triangulation tri = madd::triangulate(pslg);
  CHECK(tri.triangle_count() == 8);
  CHECK(total_area(tri) == doctest::Approx(12.0));
  check_constrained(pslg);
  for (std::uint32_t t = 0; t < tri.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) CHECK((tri.neighbours[t][i] == madd::no_index) == tri.is_constrained(t, i));
  }
}

TEST_CASE("a segment through a vertex is split there") {
  madd::Pslg pslg;
  add_ring(pslg, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}, 1);
  pslg.points.push_back({1, 0});  // on segment 0
  pslg.points.push_back({1, 2});  // on segment 2
  const madd::Triangulation tri = madd::triangulate(pslg);
  const auto v = madd::verify_triangulation(tri, &pslg);
  CHECK_MESSAGE(v.ok(), problems(v));
  CHECK(total_area(tri) == doctest::Approx(4.0));
  CHECK(tri.triangle_count() == 4);
}

TEST_CASE("long segments crossing many Delaunay edges") {
  madd::Pslg pslg;
  std::vector<Point> outer;
  for (int i = 0; i < 100; ++i) outer.push_back({static_cast<double>(i), 0.0});
  for (int i = 0; i < 100; ++i) outer.push_back({100.0, static_cast<double>(i)});
  for (int i = 100; i > 0; --i) outer.push_back({static_cast<double>(i), 100.0});
  for (int i = 100; i > 0; --i) outer.push_back({0.0, static_cast<double>(i)});
  add_ring(pslg, outer, 1);
  add_ring(pslg, {{5, 49.9}, {5, 50.1}, {95, 50.1}, {95, 49.9}}, 2);  // thin slot, clockwise
  add_ring(pslg, {{49.95, 5}, {49.95, 45}, {50.05, 45}, {50.05, 5}}, 3);
  pslg.holes.push_back({50, 50});
  pslg.holes.push_back({50, 20});
  check_constrained(pslg);
  const madd::Triangulation tri = madd::triangulate(pslg);
  CHECK(total_area(tri) == doctest::Approx(100.0 * 100.0 - 90 * 0.2 - 40 * 0.1));
}

TEST_CASE("lattice domain with lattice holes and interior lattice points") {
  // Everything cocircular and collinear: boundary vertices at every integer
  // point of a 24 x 24 square, 2 x 2 square holes, and free lattice points.
  madd::Pslg pslg;
  const int n = 24;
  std::vector<Point> outer;
  for (int i = 0; i < n; ++i) outer.push_back({static_cast<double>(i), 0.0});
  for (int i = 0; i < n; ++i) outer.push_back({static_cast<double>(n), static_cast<double>(i)});
  for (int i = n; i > 0; --i) outer.push_back({static_cast<double>(i), static_cast<double>(n)});
  for (int i = n; i > 0; --i) outer.push_back({0.0, static_cast<double>(i)});
  add_ring(pslg, outer, 1);
  double hole_area = 0;
  for (int hx = 3; hx + 2 < n; hx += 6) {
    for (int hy = 3; hy + 2 < n; hy += 6) {
      const double x = hx, y = hy;
      add_ring(pslg,
               {{x, y}, {x, y + 1}, {x, y + 2}, {x + 1, y + 2}, {x + 2, y + 2}, {x + 2, y + 1}, {x + 2, y}, {x + 1, y}},
               2);
      pslg.holes.push_back({x + 1, y + 1});
      pslg.points.push_back({x + 1, y + 1});  // a free vertex inside the hole, eaten with it
      hole_area += 4;
    }
  }
  for (int i = 1; i < n; i += 2)
    for (int j = 2; j < n; j += 6) pslg.points.push_back({static_cast<double>(i), static_cast<double>(j) - 0.5});
  const madd::Triangulation tri = madd::triangulate(pslg);
  const auto v = madd::verify_triangulation(tri);
  CHECK_MESSAGE(v.ok(), problems(v));
  CHECK(total_area(tri) == doctest::Approx(n * n - hole_area));
  CHECK(tri == madd::triangulate(pslg));
}

TEST_CASE("random star polygons with holes") {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    check_constrained(star_with_holes(200 * seed, seed + 1, 16 * seed, seed));
  }
  check_constrained(star_with_holes(20000, 9, 64, 42));
}

TEST_CASE("every data file triangulates and verifies") {
  namespace fs = std::filesystem;
  const fs::path dir = MADD_DATA_DIR;
  if (!fs::exists(dir)) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".poly") continue;
    CAPTURE(entry.path().string());
    madd::Pslg pslg;
    try {
      pslg = madd::read_domain(entry.path().string());
    } catch (const madd::Error&) {
      continue;  // bad-input samples are the reader's business
    }
    check_constrained(pslg);
  }
}

TEST_CASE("issue 13: the needle 1e11 long and 0.02 wide near (1e9, 1e9) verifies, its area exactly the domain's") {
  const madd::PolyFile file = madd::parse_poly(issue13_needle);
  madd::validate(file.pslg, file.source);
  const madd::Triangulation tri = madd::triangulate(file.pslg);
  CHECK(tri.triangle_count() == 4);
  const madd::Verification v = madd::verify_triangulation(tri, &file.pslg);
  CHECK_MESSAGE(v.ok(), problems(v));
  madd::detail::ExactSum difference = madd::detail::triangles_twice_area_exact(tri);
  difference.subtract(madd::detail::domain_twice_area_exact(file.pslg));
  CHECK(difference.is_zero());
}

TEST_CASE("needles of several slopes, lengths and widths far from the origin verify") {
  for (const double offset : {1e6, 1e9, 1e11}) {
    for (const double angle : {0.3, 1.2, 2.5, 4.0}) {
      for (const double length : {1e6, 1e9, 1e11}) {
        for (const double width : {0.02, 1.0}) {
          if (width < offset * 1e-12) continue;  // not representable apart
          CAPTURE(offset);
          CAPTURE(angle);
          CAPTURE(length);
          CAPTURE(width);
          const madd::Pslg p = needle({offset, offset}, angle, length, width);
          madd::validate(p);
          check_constrained(p);
        }
      }
    }
  }
}

TEST_CASE("the area check is exact: a spare triangle of area 1e-12 beside a unit square is caught") {
  // Everything else about the spare triangle is consistent (counter-clockwise,
  // no shared edge, no segment), so only the area can tell, and it is 1e-12
  // of the domain's: below the former relative tolerance of 1e-9.
  madd::Pslg square;
  square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (std::uint32_t k = 0; k < 4; ++k) square.segments.push_back({k, (k + 1) % 4, 0});
  madd::Triangulation tri = madd::triangulate(square);
  REQUIRE(madd::verify_triangulation(tri, &square).ok());
  for (const Point p : {Point{2, 2}, Point{2 + 1e-6, 2}, Point{2, 2 + 2e-6}}) {
    square.points.push_back(p);
    tri.points.push_back(p);
  }
  tri.triangles.push_back({4, 5, 6});
  tri.neighbours.push_back({madd::no_index, madd::no_index, madd::no_index});
  tri.segment_of.push_back({madd::no_index, madd::no_index, madd::no_index});
  const madd::Verification v = madd::verify_triangulation(tri, &square);
  REQUIRE(v.problems.size() == 1);
  CHECK(v.problems.front().find("total area") != std::string::npos);
}

TEST_CASE("a points-only .node file triangulates over its convex hull") {
  // Random points inside the unit square plus points along its sides, so the
  // hull has collinear vertices that must all be triangle corners.
  std::vector<Point> pts = random_points(300, 31);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    for (const Point p : {Point{t, 0}, Point{1, t}, Point{1 - t, 1}, Point{0, 1 - t}}) {
      if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
    }
  }
  const madd::PolyFile file = madd::parse_node(node_text(pts), "points.node");
  REQUIRE(file.pslg.points == pts);
  madd::ValidateOptions options;
  options.allow_point_set = true;
  REQUIRE_NOTHROW(madd::validate(file.pslg, file.source, options));
  const madd::Triangulation tri = madd::delaunay(file.pslg.points);
  const madd::Verification v = madd::verify_triangulation(tri);
  CHECK_MESSAGE(v.ok(), problems(v));
  check_brute_force_delaunay(pts, tri);
  CHECK(total_area(tri) == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("madd triangulate FILE.node writes the Delaunay triangulation of the points") {
#ifndef MADD_CLI_PATH
  MESSAGE("skipped: the madd CLI is not built");
#else
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("madd-triangulate-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto run = [&](const std::string& name) {
    const std::string command = std::string("'") + MADD_CLI_PATH + "' triangulate -q '" + (dir / name).string() +
                                "' > '" + (dir / "log").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  std::vector<Point> pts = random_points(400, 8);
  for (int k = 0; k < 10; ++k) pts.push_back({k / 10.0, -0.5});  // collinear hull points
  std::ofstream(dir / "pts.node") << node_text(pts);
  REQUIRE_MESSAGE(run("pts.node") == 0, slurp(dir / "log"));

  madd::Triangulation tri;
  tri.points = madd::read_poly_file((dir / "pts.1.node").string()).pslg.points;
  REQUIRE(tri.points == pts);
  read_ele_neigh(slurp(dir / "pts.1.ele"), slurp(dir / "pts.1.neigh"), tri);
  const madd::Verification v = madd::verify_triangulation(tri);
  CHECK_MESSAGE(v.ok(), problems(v));
  const std::size_t h = hull_point_count(pts);
  CHECK(tri.triangle_count() == 2 * pts.size() - 2 - h);
  // Every edge once, the h hull edges (and only they) with marker 1.
  std::istringstream edges(slurp(dir / "pts.1.edge"));
  std::size_t edge_count = 0, with_markers = 0, hull_edges = 0;
  edges >> edge_count >> with_markers;
  CHECK(edge_count == (3 * tri.triangle_count() + h) / 2);
  for (std::size_t k = 0; k < edge_count; ++k) {
    long long id = 0, a = 0, b = 0, marker = -1;
    edges >> id >> a >> b >> marker;
    if (marker == 1) ++hull_edges;
  }
  CHECK(edges);
  CHECK(hull_edges == h);

  // A duplicate is refused, naming both vertices.
  pts.push_back(pts[41]);
  std::ofstream(dir / "dup.node") << node_text(pts);
  CHECK(run("dup.node") == 3);
  const std::string log = slurp(dir / "log");
  CHECK_MESSAGE(log.find("vertex 42") != std::string::npos, log);
  CHECK_MESSAGE(log.find("vertex " + std::to_string(pts.size())) != std::string::npos, log);
  std::error_code ignored;
  fs::remove_all(dir, ignored);
#endif
}

TEST_CASE("verify_triangulation catches broken triangulations") {
  const auto pts = random_points(100, 4);
  const madd::Triangulation good = madd::delaunay(pts);
  REQUIRE(madd::verify_triangulation(good).ok());
  madd::Triangulation flipped = good;
  std::swap(flipped.triangles[5][0], flipped.triangles[5][1]);
  CHECK_FALSE(madd::verify_triangulation(flipped).ok());
  madd::Triangulation unlinked = good;
  for (auto& n : unlinked.neighbours[7]) n = madd::no_index;
  CHECK_FALSE(madd::verify_triangulation(unlinked).ok());
  // A non-Delaunay but valid triangulation: flip one interior edge.
  madd::Triangulation bad = good;
  bool flipped_one = false;
  for (std::uint32_t t = 0; t < bad.triangle_count() && !flipped_one; ++t) {
    for (int i = 0; i < 3 && !flipped_one; ++i) {
      const std::uint32_t u = bad.neighbours[t][i];
      if (u == madd::no_index) continue;
      const auto a = bad.triangles[t][i], b = bad.triangles[t][(i + 1) % 3], c = bad.triangles[t][(i + 2) % 3];
      int j = 0;
      while (bad.neighbours[u][j] != t) ++j;
      const auto d = bad.triangles[u][j];
      if (madd::orient2d(pts[a], pts[b], pts[d]) > 0 && madd::orient2d(pts[d], pts[c], pts[a]) > 0) {
        bad.triangles[t] = {a, b, d};
        bad.triangles[u] = {d, c, a};
        flipped_one = true;
      }
    }
  }
  REQUIRE(flipped_one);
  CHECK_FALSE(madd::verify_triangulation(bad).ok());
}

TEST_CASE("verify_triangulation names each kind of broken adjacency") {
  const auto pts = random_points(200, 5);
  const madd::Triangulation good = madd::delaunay(pts);
  REQUIRE(madd::verify_triangulation(good).ok());
  auto says = [](const madd::Triangulation& t, const std::string& what) {
    const madd::Verification v = madd::verify_triangulation(t);
    bool found = false;
    for (const std::string& p : v.problems) found = found || p.find(what) != std::string::npos;
    return found;
  };
  // An interior edge of triangle t, as (t, i, u = the neighbour across it).
  std::uint32_t t = 0;
  int i = 0;
  while (good.neighbours[t][i] == madd::no_index) {
    if (++i == 3) {
      i = 0;
      ++t;
    }
  }
  const std::uint32_t u = good.neighbours[t][i];
  madd::Triangulation twice = good;  // a second copy of triangle t over triangle u's slot
  twice.triangles[u] = good.triangles[t];
  CHECK(says(twice, "is used twice"));
  madd::Triangulation one_way = good;  // t points elsewhere, u still points at t
  one_way.neighbours[t][i] = static_cast<std::uint32_t>((u + 1) % good.triangle_count());
  CHECK(says(one_way, "are not mutual neighbours"));
  madd::Triangulation half_constrained = good;  // only one side calls the edge a segment
  half_constrained.segment_of[t][i] = 0;
  CHECK(says(half_constrained, "disagree on segment_of"));
  madd::Triangulation dangling = good;  // a neighbour across a hull edge
  std::uint32_t h = 0;
  int k = 0;
  while (good.neighbours[h][k] != madd::no_index) {
    if (++k == 3) {
      k = 0;
      ++h;
    }
  }
  dangling.neighbours[h][k] = static_cast<std::uint32_t>((h + 1) % good.triangle_count());
  CHECK(says(dangling, "names a neighbour across an unshared edge"));
}
}  // TEST_SUITE("triangulation")
