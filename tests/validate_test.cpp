// Tests of validate() and domain_area() (include/madd/pslg.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <random>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"

namespace fs = std::filesystem;
using madd::InputProblem;
using madd::Point;

namespace {

// Appends a closed loop of points to `p`.
void add_loop(madd::Pslg& p, const std::vector<Point>& loop) {
  const auto base = static_cast<std::uint32_t>(p.points.size());
  const auto n = static_cast<std::uint32_t>(loop.size());
  for (std::uint32_t k = 0; k < n; ++k) {
    p.points.push_back(loop[k]);
    p.segments.push_back({base + k, base + (k + 1) % n, 0});
  }
}

std::vector<Point> rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

std::vector<Point> regular(Point c, double r, int n, bool clockwise = false) {
  std::vector<Point> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n * (clockwise ? -1 : 1);
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

double shoelace(const std::vector<Point>& loop) {
  double s = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) s += madd::cross(loop[k], loop[(k + 1) % loop.size()]);
  return 0.5 * s;
}

std::optional<madd::InvalidInputError> error_of(const madd::Pslg& p, const madd::ValidateOptions& o = {}) {
  try {
    madd::validate(p, {}, o);
  } catch (const madd::InvalidInputError& e) {
    return e;
  }
  return std::nullopt;
}

// Independent O(n^2) reference: do two segments share any point other than a
// common endpoint? Exact, with orient2d and coordinate comparisons only.
bool on_segment(Point a, Point b, Point q) {
  return madd::orient2d(a, b, q) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
}
bool conflict(const madd::Pslg& p, const madd::Segment& s, const madd::Segment& t) {
  const Point a = p.points[s.a], b = p.points[s.b], c = p.points[t.a], d = p.points[t.b];
  // An endpoint of one lying on the other, unless it is a shared endpoint
  // whose other ends are not on the other segment: an overlap when the two
  // are collinear; else a vertex inside a segment, which splits it (allowed).
  const bool collinear = madd::orient2d(a, b, c) == 0.0 && madd::orient2d(a, b, d) == 0.0;
  if (collinear &&
      ((!(t.a == s.a || t.a == s.b) && on_segment(a, b, c)) || (!(t.b == s.a || t.b == s.b) && on_segment(a, b, d)) ||
       (!(s.a == t.a || s.a == t.b) && on_segment(c, d, a)) || (!(s.b == t.a || s.b == t.b) && on_segment(c, d, b))))
    return true;
  if ((s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a)) return true;
  const double o1 = madd::orient2d(a, b, c), o2 = madd::orient2d(a, b, d);
  const double o3 = madd::orient2d(c, d, a), o4 = madd::orient2d(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

}  // namespace

TEST_SUITE("validate") {

TEST_CASE("every bundled domain validates") {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(MADD_DATA_DIR)) {
    if (entry.path().extension() != ".poly") continue;
    CAPTURE(entry.path().string());
    CHECK_NOTHROW(madd::read_domain(entry.path().string()));
    ++count;
  }
  CHECK(count >= 6);
}

TEST_CASE("domain_area of simple shapes") {
  madd::Pslg square;
  add_loop(square, rect(0, 0, 2, 3));
  CHECK(madd::domain_area(square) == doctest::Approx(6.0));
  madd::Pslg framed = square;
  add_loop(framed, rect(0.5, 0.5, 1.5, 1.5));
  framed.holes.push_back({1, 1});
  CHECK_NOTHROW(madd::validate(framed));
  CHECK(madd::domain_area(framed) == doctest::Approx(5.0));
  // The pipe: a 256-gon minus a 128-gon and eight 24-gons.
  const madd::Pslg pipe = madd::read_domain(std::string(MADD_DATA_DIR) + "/pipe.poly");
  const auto gon = [](double r, int n) { return 0.5 * n * r * r * std::sin(2 * std::numbers::pi / n); };
  CHECK(madd::domain_area(pipe) == doctest::Approx(gon(10, 256) - gon(4, 128) - 8 * gon(0.8, 24)).epsilon(1e-12));
  const madd::Pslg l_shape = madd::read_domain(std::string(MADD_DATA_DIR) + "/l_shape.poly");
  CHECK(madd::domain_area(l_shape) == doctest::Approx(3.0));
}

TEST_CASE("a hole touching the outer boundary at a vertex is accepted") {
  // Decision: such a vertex has degree 4 and the face walk keeps the domain
  // as one face, so it is a valid (if pinched) domain, as Triangle meshes it.
  madd::Pslg p;
  add_loop(p, rect(0, 0, 4, 4));
  p.points.push_back({2, 1});
  p.points.push_back({3, 2});
  p.points.push_back({2, 3});
  p.segments.push_back({0, 4, 0});  // the hole ring starts and ends at corner (0, 0)
  p.segments.push_back({4, 5, 0});
  p.segments.push_back({5, 6, 0});
  p.segments.push_back({6, 0, 0});
  p.holes.push_back({2, 2});
  CHECK_NOTHROW(madd::validate(p));
  const double hole = std::abs(shoelace({{0, 0}, {2, 1}, {3, 2}, {2, 3}}));
  CHECK(madd::domain_area(p) == doctest::Approx(16.0 - hole));
}

TEST_CASE("random star-shaped polygons with holes validate, area matches the shoelace formula") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(5.0, 10.0);
  for (int round = 0; round < 30; ++round) {
    const int n = 3 + round * 13;
    std::vector<Point> outer;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::numbers::pi * k / n, r = radius(rng);
      outer.push_back({r * std::cos(a), r * std::sin(a)});
    }
    madd::Pslg p;
    add_loop(p, outer);
    double area = shoelace(outer);
    if (round % 2) {
      const auto hole = regular({0.3, -0.2}, 2.0, 5 + round, round % 4 == 1);
      add_loop(p, hole);
      p.holes.push_back({0.3, -0.2});
      area -= std::abs(shoelace(hole));
    }
    CAPTURE(round);
    CHECK_NOTHROW(madd::validate(p));
    CHECK(madd::domain_area(p) == doctest::Approx(area));
  }
}

TEST_CASE("crossing detection agrees with the O(n^2) exact check on random segment sets") {
  int clean_sets = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    const int grid = seed % 3 == 0 ? 6 : 40;  // small grids: many collinear and touching cases
    const int n = 5 + static_cast<int>(seed) * 4;
    madd::Pslg p;
    std::vector<std::uint32_t> id(grid * grid, madd::no_index);
    const auto vertex = [&](int cell) {
      if (id[cell] == madd::no_index) {
        id[cell] = static_cast<std::uint32_t>(p.points.size());
        const double jitter = seed % 2 ? 0.0 : 1e-3 * (cell % 7);
        p.points.push_back({cell % grid + jitter, static_cast<double>(cell / grid)});
      }
      return id[cell];
    };
    for (int k = 0; k < n; ++k) {
      const int a = static_cast<int>(rng() % (grid * grid));
      int b = static_cast<int>(rng() % (grid * grid));
      if (seed % 4 == 1) b = std::min(grid * grid - 1, a + 1 + grid * static_cast<int>(rng() % 2));  // short
      if (b == a) b = (a + 1) % (grid * grid);
      p.segments.push_back({vertex(a), vertex(b), 0});
    }
    std::optional<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t j = 0; j < p.segments.size() && !expected; ++j)
      for (std::uint32_t i = 0; i < j && !expected; ++i)
        if (conflict(p, p.segments[i], p.segments[j])) expected = {j, i};
    CAPTURE(seed);
    const auto e = error_of(p);
    const bool reported = e && e->problem() == InputProblem::segments_intersect;
    if (!expected) ++clean_sets;
    CHECK(reported == expected.has_value());
    if (reported && expected) {
      // A genuine conflicting pair, reported later segment first.
      REQUIRE(e->ids().size() == 2);
      CHECK(e->ids()[0] > e->ids()[1]);
      const auto j = static_cast<std::uint32_t>(e->ids()[0] - 1), i = static_cast<std::uint32_t>(e->ids()[1] - 1);
      CHECK(conflict(p, p.segments[i], p.segments[j]));
      CHECK(e->points().size() == 1);
      // Below the search budget (4096 extra pair tests) the report is the first in file order.
      if (p.segments.size() <= 90) CHECK(j == expected->first);
    }
  }
  CHECK(clean_sets > 0);  // both outcomes are exercised
}

TEST_CASE("a file where every segment crosses every other fails without quadratic work") {
  madd::Pslg p;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double a = std::numbers::pi * k / n;
    p.points.push_back({std::cos(a), std::sin(a)});
    p.points.push_back({-std::cos(a) * 1.0000001, -std::sin(a) * 1.0000001});
    p.segments.push_back({static_cast<std::uint32_t>(2 * k), static_cast<std::uint32_t>(2 * k + 1), 0});
  }
  const auto e = error_of(p);
  REQUIRE(e);
  CHECK(e->problem() == InputProblem::segments_intersect);
}

TEST_CASE("each failure class is reported with ids in the file's base") {
  madd::Pslg square;
  add_loop(square, rect(0, 0, 1, 1));
  SUBCASE("duplicate vertex, 0-based") {
    madd::Pslg p = square;
    p.first_index = 0;
    p.points.push_back({-0.0, 0.0});
    p.segments.push_back({4, 2, 0});
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::duplicate_vertex);
    CHECK(e->ids() == std::vector<std::int64_t>{4, 0});
  }
  SUBCASE("vertex in the interior of a segment: a triangle touching the square there") {
    madd::Pslg p = square;
    add_loop(p, {{0.5, 0.0}, {0.6, -1}, {0.4, -1}});
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::disconnected_domain);  // the side is split there; they meet at one point
  }
  SUBCASE("hole on a vertex") {
    madd::Pslg p = square;
    p.holes.push_back({1, 1});
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::hole_on_segment);
  }
  SUBCASE("island inside a hole is a disconnected part") {
    madd::Pslg p;
    add_loop(p, rect(0, 0, 10, 10));
    add_loop(p, rect(2, 2, 8, 8));
    add_loop(p, rect(4, 4, 6, 6));
    p.holes.push_back({3, 3});
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::disconnected_domain);
    p.holes.push_back({5, 5});
    const auto e2 = error_of(p);
    REQUIRE(e2);
    CHECK(e2->problem() == InputProblem::interior_segment);  // the island lies inside removed regions
  }
  SUBCASE("hole point in the domain instead of in the hole ring") {
    madd::Pslg p;
    add_loop(p, rect(0, 0, 10, 10));
    add_loop(p, rect(2, 2, 8, 8));
    p.holes.push_back({1, 1});
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::hole_outside_domain);
  }
  SUBCASE("weights are checked only when asked") {
    madd::Pslg p = square;
    p.attributes_per_point = 1;
    p.attributes = {1.0, -2.0, 0.0, 3.0};
    CHECK_NOTHROW(madd::validate(p));
    madd::ValidateOptions o;
    o.check_weights = true;
    const auto e = error_of(p, o);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::bad_weight);
    CHECK(e->ids() == std::vector<std::int64_t>{2});
  }
  SUBCASE("coordinates outside the range of the exact predicates") {
    for (double bad : {1e308, -1e71, 1e-300, 5e-324}) {
      madd::Pslg p = square;
      p.points[3].x = bad;
      const auto e = error_of(p);
      REQUIRE(e);
      CHECK(e->problem() == InputProblem::other);
      CHECK(e->ids() == std::vector<std::int64_t>{4});
    }
    madd::Pslg p = square;
    p.points[3].x = -0.0;
    CHECK_NOTHROW(madd::validate(p));
  }
  SUBCASE("dangling chain: inside, an interior segment; outside, an open boundary") {
    madd::Pslg p = square;
    p.points.push_back({0.5, 0.5});
    p.segments.push_back({0, 4, 0});
    CHECK(!error_of(p));
    p.points.back() = {-0.5, -0.5};
    const auto e = error_of(p);
    REQUIRE(e);
    CHECK(e->problem() == InputProblem::open_boundary);
    CHECK(e->ids() == std::vector<std::int64_t>{5});  // the loose end
  }
}

TEST_CASE("long segments over a fine grid: a many-sided polygon with a comb of long teeth") {
  // Thin long teeth cross many cells; the check must stay exact.
  std::vector<Point> loop{{0, 1}};
  const int teeth = 300;
  for (int k = 0; k < teeth; ++k) {
    const double x = k * 1.0;
    if (k > 0) loop.push_back({x, 0});
    loop.push_back({x, -1000});
    loop.push_back({x + 0.5, -1000});
    if (k + 1 < teeth) loop.push_back({x + 0.5, 0});
  }
  loop.push_back({teeth - 0.5, 1});
  madd::Pslg p;
  add_loop(p, loop);
  CHECK_NOTHROW(madd::validate(p));
  CHECK(madd::domain_area(p) == doctest::Approx(std::abs(shoelace(loop))));
  // Nudge one tooth tip into its neighbour: must be caught.
  p.points[2].x = 1.0 + 1e-9;
  const auto e = error_of(p);
  REQUIRE(e);
  CHECK(e->problem() == InputProblem::segments_intersect);
}

TEST_CASE("allow_point_set: a points-only file is accepted, duplicates and bad coordinates are not") {
  const std::string text = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";
  madd::ValidateOptions points;
  points.allow_point_set = true;
  const madd::PolyFile square = madd::parse_node(text, "square.node");
  CHECK_NOTHROW(madd::validate(square.pslg, square.source, points));
  // Without the option there is still no domain.
  const auto refused = error_of(square.pslg);
  REQUIRE(refused);
  CHECK(refused->problem() == InputProblem::empty_domain);
  // Holes without segments are not a point set either.
  madd::Pslg holed = square.pslg;
  holed.holes.push_back({0.5, 0.5});
  CHECK(error_of(holed, points));

  // Vertex 5 repeats vertex 2: both named, in the file's base, at vertex 5's line.
  const madd::PolyFile dup = madd::parse_node("5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1 0\n", "dup.node");
  try {
    madd::validate(dup.pslg, dup.source, points);
    FAIL("no error");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == InputProblem::duplicate_vertex);
    std::vector<std::int64_t> ids = e.ids();
    std::sort(ids.begin(), ids.end());
    CHECK(ids == std::vector<std::int64_t>{2, 5});
    CHECK(e.line() == 6);
    const std::string message = e.what();
    CHECK(message.find("vertex 5") != std::string::npos);
    CHECK(message.find("vertex 2") != std::string::npos);
  }
  madd::Pslg huge = square.pslg;
  huge.points[3].x = 1e300;
  const auto range = error_of(huge, points);
  REQUIRE(range);
  CHECK(range->ids() == std::vector<std::int64_t>{4});
}

}  // TEST_SUITE("validate")
