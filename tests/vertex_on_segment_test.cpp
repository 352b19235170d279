// Vertices lying exactly inside segments they do not end (docs/formats.md,
// "The domain"): on every side of the outer ring, on a hole's ring, on an
// interior segment between two regions, on a dangling segment, several on
// one segment (pieces with such a vertex at both ends), next to a segment's
// end, at both ends of a separator, beside a segment ending inside the same
// segment, and beside a truly isolated vertex. Each domain is validated and summarised as `madd check`
// does, decomposed at several N and Phi0, written as one .poly per subdomain
// (--split) and meshed; the vertex must stay on its segment throughout.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "madd/pslg.hpp"
#include "vertex_on_segment.hpp"

namespace {

using madd::Pslg;

// A w x h rectangle from the origin, counter-clockwise, side k with marker k + 1.
Pslg rectangle(double w, double h) {
  Pslg p;
  p.points = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  p.segments = {{0, 1, 1}, {1, 2, 2}, {2, 3, 3}, {3, 0, 4}};
  p.has_segment_markers = true;
  return p;
}

std::uint32_t add_point(Pslg& p, madd::Point q) {
  p.points.push_back(q);
  return static_cast<std::uint32_t>(p.points.size() - 1);
}

struct Case {
  const char* name;
  Pslg domain;
  double area = 0.0;
  std::size_t isolated = 0;  // vertices on no segment, and inside none
};

std::vector<Case> cases() {
  std::vector<Case> out;
  Pslg sides = rectangle(4, 2);  // one on each side: the ray casting that located them saw some outside
  for (const madd::Point q : {madd::Point{2, 0}, {4, 1}, {2.5, 2}, {0, 0.75}}) add_point(sides, q);
  out.push_back({"one on each side of the outer ring", sides, 8});

  Pslg hole = rectangle(4, 4);
  for (const madd::Point q : {madd::Point{1, 1}, {3, 1}, {3, 3}, {1, 3}}) add_point(hole, q);
  hole.segments.insert(hole.segments.end(), {{4, 5, 5}, {5, 6, 5}, {6, 7, 5}, {7, 4, 5}});
  hole.holes = {{2, 2}};
  add_point(hole, {2, 1});
  add_point(hole, {1, 2.5});
  out.push_back({"on a hole's ring", hole, 12});

  Pslg regions = rectangle(4, 2);  // an interior segment between two regions
  regions.points.insert(regions.points.end(), {{2, 0}, {2, 2}});
  regions.segments = {{0, 4, 1}, {4, 1, 1}, {1, 2, 2}, {2, 5, 3}, {5, 3, 3}, {3, 0, 4}, {4, 5, 8}};
  regions.regions = {{{1, 1}, 10.0, 0.05}, {{3, 1}, 20.0, -1.0}};
  add_point(regions, {2, 1});
  out.push_back({"on an interior segment between two regions", regions, 8});

  Pslg dangling = rectangle(4, 2);
  dangling.points.insert(dangling.points.end(), {{0, 1}, {2, 1}});
  dangling.segments = {{0, 1, 1}, {1, 2, 2}, {2, 3, 3}, {3, 4, 4}, {4, 0, 4}, {4, 5, 9}};
  add_point(dangling, {1, 1});
  out.push_back({"on a dangling segment from the boundary", dangling, 8});

  Pslg several = rectangle(4, 2);  // out of order along the segment; pieces with one at both ends
  for (const double x : {3.0, 1.0, 2.0, 0x1p-10, 4.0 - 0x1p-10}) add_point(several, {x, 0});
  out.push_back({"several on one segment, two of them next to its ends", several, 8});

  Pslg slope;  // a right triangle: the vertices on its hypotenuse are exactly on it
  slope.points = {{0, 0}, {4, 0}, {4, 3}, {3.0 * 0.25 * 4, 3.0 * 0.25 * 3}, {2, 1.5}};
  slope.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  out.push_back({"two on a sloping segment, no markers", slope, 6});

  Pslg touch = rectangle(4, 2);  // a segment ending inside side 1, a vertex on both
  touch.points.insert(touch.points.end(), {{1, 0}, {1.5, 1}});
  touch.segments.push_back({5, 4, 6});
  add_point(touch, {3, 0});
  add_point(touch, {1.25, 0.5});
  out.push_back({"beside a segment ending inside the same segment", touch, 8});

  Pslg both_ends = rectangle(2, 1);  // where the separator halving it ends, on both sides
  add_point(both_ends, {1, 0});
  add_point(both_ends, {1, 1});
  out.push_back({"at both ends of the separator that halves the domain", both_ends, 2});

  Pslg isolated = rectangle(4, 2);
  add_point(isolated, {2, 0});
  add_point(isolated, {2.2, 1.1});
  out.push_back({"beside a truly isolated vertex", isolated, 8, 1});
  return out;
}

// The --split files: each piece a valid domain of its own with the
// subdomain's area, where every vertex on a segment is now a segment's end.
void check_pieces(const madd::Decomposition& d) {
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k) {
    CAPTURE(k);
    const Pslg piece = madd::parse_poly(madd::format_subdomain_poly(d, k)).pslg;
    CHECK_NOTHROW(madd::validate(piece));
    CHECK(madd::test::vertices_on_segments(piece).empty());
    CHECK(madd::summarize_pslg(piece).isolated_vertices == d.subdomains[k].interior_points.size());
    CHECK(madd::domain_area(piece) == doctest::Approx(d.subdomains[k].area).epsilon(1e-12));
  }
}

}  // namespace

TEST_SUITE("vertex on segment") {

TEST_CASE("a vertex inside a segment it does not end splits it: check, decompose, split and mesh keep it there") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const std::size_t on_segments = madd::test::vertices_on_segments(c.domain).size();
    REQUIRE(on_segments >= 1);
    REQUIRE_NOTHROW(madd::validate(c.domain));
    const madd::PslgSummary summary = madd::summarize_pslg(c.domain);
    CHECK(summary.isolated_vertices == c.isolated);
    CHECK(summary.vertices_inside_segments == on_segments);
    CHECK(summary.area == doctest::Approx(c.area).epsilon(1e-15));
    CHECK(madd::domain_area(c.domain) == doctest::Approx(c.area).epsilon(1e-15));
    for (const double phi : {45.0, 60.0, 70.0})
      for (const std::uint32_t n : {1u, 2u, 3u, 5u, 8u}) {
        const madd::Decomposition d = madd::test::checked_on_segments(c.domain, n, phi);
        if (phi == 60.0) check_pieces(d);
      }
    for (const std::uint32_t n : {1u, 2u, 4u}) madd::test::meshed_on_segments(c.domain, n);
  }
}

TEST_CASE("a separator may end at a vertex on a segment: the halving one of a 2 x 1 rectangle ends at two") {
  Pslg p = rectangle(2, 1);
  const std::uint32_t bottom = add_point(p, {1, 0}), top = add_point(p, {1, 1});
  const madd::Decomposition d = madd::test::checked_on_segments(p, 2, 60.0);
  bool joined = false;
  for (std::uint32_t g = 0; g < d.segments.size(); ++g) {
    const madd::Segment& s = d.segments[g];
    joined = joined || (d.is_separator(g) && std::min(s.a, s.b) == bottom && std::max(s.a, s.b) == top);
  }
  CHECK(joined);  // else this case no longer exercises a separator ending there
}

}  // TEST_SUITE("vertex on segment")
