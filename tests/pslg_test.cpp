// Tests of the PSLG level of include/madd/pslg.hpp: validate_pslg (what
// triangulate takes) and summarize_pslg (what `madd check` prints).
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <tuple>
#include <random>
#include <string>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

using madd::InputProblem;
using madd::Point;

namespace {

std::optional<madd::InvalidInputError> pslg_error(const madd::Pslg& p, bool allow_intersections = false) {
  madd::ValidatePslgOptions options;
  options.allow_intersections = allow_intersections;
  try {
    madd::validate_pslg(p, {}, options);
  } catch (const madd::InvalidInputError& e) {
    return e;
  }
  return std::nullopt;
}

madd::Pslg square_with(std::vector<Point> extra, std::vector<madd::Segment> extra_segments) {
  madd::Pslg p;
  p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  p.points.insert(p.points.end(), extra.begin(), extra.end());
  p.segments.insert(p.segments.end(), extra_segments.begin(), extra_segments.end());
  return p;
}

double triangles_area(const madd::Triangulation& tri) {
  double a = 0;
  for (const auto& t : tri.triangles) a += madd::signed_area(tri.points[t[0]], tri.points[t[1]], tri.points[t[2]]);
  return a;
}

}  // namespace

TEST_SUITE("pslg") {

TEST_CASE("validate_pslg accepts what a domain may not hold: interior, dangling and touching segments, lone vertices") {
  // A T-junction at (1, 0.5) on the right side, a dangling segment into the
  // interior, an isolated vertex, an open polyline outside.
  const madd::Pslg p = square_with({{1, 0.5}, {0.5, 0.5}, {0.25, 0.75}, {2, 0}, {3, 1}}, {{4, 5, 0}, {7, 8, 0}});
  CHECK(!pslg_error(p));
  // As a domain, all but the polyline outside are interior constraints.
  try {
    madd::validate(p);
    FAIL("a domain with a segment outside it");
  } catch (const madd::InvalidInputError& e) {
    CHECK(e.problem() == InputProblem::open_boundary);
    CHECK(e.ids() == std::vector<std::int64_t>{8});  // vertex 8 (2, 0), a loose end of the polyline
  }
  const madd::Pslg inside = square_with({{1, 0.5}, {0.5, 0.5}, {0.25, 0.75}}, {{4, 5, 0}});
  CHECK_NOTHROW(madd::validate(inside));
  CHECK(madd::domain_area(inside) == 1.0);
}

TEST_CASE("validate_pslg refuses crossings and overlaps unless asked, naming both segments in the file's base") {
  madd::Pslg cross = square_with({}, {{0, 2, 0}, {1, 3, 0}});
  cross.first_index = 0;
  auto e = pslg_error(cross);
  REQUIRE(e);
  CHECK(e->problem() == InputProblem::segments_intersect);
  CHECK(e->ids() == std::vector<std::int64_t>{5, 4});
  CHECK(std::string(e->what()).find("crosses") != std::string::npos);
  CHECK(!pslg_error(cross, true));

  const madd::Pslg overlap = square_with({{0.25, 0}, {2, 0}}, {{4, 5, 0}});  // along the bottom side and beyond
  e = pslg_error(overlap);
  REQUIRE(e);
  CHECK(e->problem() == InputProblem::segments_intersect);
  CHECK(std::string(e->what()).find("overlaps") != std::string::npos);
  CHECK(!pslg_error(overlap, true));

  const madd::Pslg twice = square_with({}, {{1, 0, 0}});  // the bottom side drawn again, reversed
  e = pslg_error(twice);
  REQUIRE(e);
  CHECK(e->ids() == std::vector<std::int64_t>{5, 1});
}

TEST_CASE(
    "validate_pslg still refuses duplicates, zero length, holes on segments or with nothing to stop them, bad ranges") {
  CHECK(pslg_error(square_with({{1, 1}}, {}))->problem() == InputProblem::duplicate_vertex);
  CHECK(pslg_error(square_with({}, {{2, 2, 0}}))->problem() == InputProblem::zero_length_segment);
  madd::Pslg on = square_with({}, {});
  on.holes = {{0.5, 0}};
  CHECK(pslg_error(on)->problem() == InputProblem::hole_on_segment);
  madd::Pslg points_only;
  points_only.points = {{0, 0}, {1, 0}, {0, 1}};
  CHECK(!pslg_error(points_only));
  points_only.holes = {{0.2, 0.2}};
  CHECK(pslg_error(points_only)->problem() == InputProblem::empty_domain);
  madd::Pslg far = square_with({}, {});
  far.regions = {{{0.5, 1e-300}, 1.0, -1.0}};
  CHECK(pslg_error(far)->problem() == InputProblem::other);
  far.regions[0].at.y = 0.5;
  CHECK(!pslg_error(far));
}

TEST_CASE("every domain is a PSLG: the bundled domains pass validate_pslg, their summary is all boundary") {
  for (const char* name : {"key.poly", "pipe.poly", "archipelago.poly", "spiral.poly"}) {
    CAPTURE(name);
    const madd::PolyFile f = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/" + name);
    madd::validate(f.pslg, f.source);
    madd::validate_pslg(f.pslg, f.source);
    const madd::PslgSummary s = madd::summarize_pslg(f.pslg);
    CHECK(s.boundary_segments == f.pslg.segments.size());
    CHECK(s.interior_segments + s.outside_segments + s.isolated_vertices + s.dangling_ends +
              s.vertices_inside_segments ==
          0);
    CHECK(s.parts == 1);
    CHECK(s.area == doctest::Approx(madd::domain_area(f.pslg)).epsilon(1e-12));
  }
}

// data/pslg/estuary.poly holds one of each kind of constraint; the counts
// follow from its construction in data/generate.py, estuary().
TEST_CASE("summarize_pslg counts each kind of constraint of data/pslg/estuary.poly") {
  const madd::PolyFile f = madd::read_poly_file(std::string(MADD_DATA_DIR) + "/pslg/estuary.poly");
  madd::validate_pslg(f.pslg, f.source);
  const madd::PslgSummary s = madd::summarize_pslg(f.pslg);
  CHECK(s.boundary_segments == 6 + 4);          // the shore and the hole
  CHECK(s.interior_segments == 3 + 2 + 3 + 1);  // loop, lane, levee with spur, groyne
  CHECK(s.outside_segments == 0);
  CHECK(s.isolated_vertices == 4);  // three survey points in the water, one in the hole
  CHECK(s.isolated_inside == 3);
  CHECK(s.vertices_inside_segments == 2);        // the groyne's end on the levee, a point on the lane
  CHECK(s.dangling_ends == 5);                   // lane end, levee ends, spur end, groyne start
  CHECK(s.parts == 2);                           // the water and the loop's region
  CHECK(s.area == doctest::Approx(74.0 - 1.0));  // the bay less the hole
}

TEST_CASE("summarize_pslg on random lone points and segments agrees with brute force and with the triangulation") {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(0.1, 0.9);
  for (int round = 0; round < 20; ++round) {
    // A square, and random segments taken from the Delaunay triangulation of
    // random points (so none cross), the other points left alone.
    std::vector<Point> pts;
    for (int k = 0; k < 40; ++k) pts.push_back({u(rng), u(rng)});
    const madd::Triangulation d = madd::delaunay(pts);
    madd::Pslg p = square_with(pts, {});
    std::vector<int> degree(p.points.size(), 0);
    for (std::uint32_t t = 0; t < d.triangle_count(); ++t) {
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = d.triangles[t][(i + 1) % 3], b = d.triangles[t][(i + 2) % 3];
        if (a < b && rng() % 4 == 0) {
          p.segments.push_back({a + 4, b + 4, 0});
          ++degree[a + 4], ++degree[b + 4];
        }
      }
    }
    REQUIRE(!pslg_error(p));
    const madd::PslgSummary s = madd::summarize_pslg(p);
    std::size_t lone = 0, ends = 0;
    for (std::size_t v = 4; v < p.points.size(); ++v) lone += degree[v] == 0, ends += degree[v] == 1;
    CHECK(s.isolated_vertices == lone);
    CHECK(s.isolated_inside == lone);  // all inside the square
    CHECK(s.dangling_ends == ends);
    CHECK(s.boundary_segments == 4);
    CHECK(s.interior_segments == p.segments.size() - 4);
    CHECK(s.area == doctest::Approx(1.0));
    const madd::Triangulation tri = madd::triangulate(p);
    CHECK(triangles_area(tri) == doctest::Approx(s.area));
  }
}

TEST_CASE("decompose() takes interior segments and isolated vertices, and keeps each inside one subdomain") {
  madd::Pslg lone = square_with({{0.5, 0.5}}, {});
  madd::Pslg interior = square_with({}, {{0, 2, 0}});
  // The lone point is the square's centre, where every medial separator of
  // the square passes: the split falls back to pinning it (split/refine.hpp).
  for (const madd::Pslg& pslg : {lone, interior}) {
    for (const std::uint32_t n : {2u, 3u}) {
      madd::DecomposeOptions options;
      options.subdomains = n;
      const madd::Decomposition d = madd::decompose(pslg, options);
      CHECK(madd::verify_decomposition(d, pslg, n).ok());
      // The one point in one subdomain; the diagonal in pieces inside them, its whole length.
      std::size_t points = 0;
      double length = 0.0;
      for (const madd::Subdomain& s : d.subdomains) {
        points += s.interior_points.size();
        for (const std::uint32_t g : s.interior_segments)
          length += madd::distance(d.points[d.segments[g].a], d.points[d.segments[g].b]);
      }
      CHECK(points == pslg.points.size() - 4);
      CHECK(length == doctest::Approx(pslg.segments.size() > 4 ? std::sqrt(2.0) : 0.0));
    }
  }
}

}  // TEST_SUITE("pslg")
