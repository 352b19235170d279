// Tests of a coastline as a domain (include/madd/coast.hpp): projection,
// clipping to a box, cleaning, the kept water body and piece.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "gis/clip_box.hpp"
#include "gis/ring_cleaning.hpp"
#include "kernel/rings.hpp"
#include "madd/coast.hpp"
#include "madd/error.hpp"
#include "madd/pslg.hpp"

namespace {

madd::GisRing ring(std::vector<madd::Point> points, std::uint32_t source = 0) { return {std::move(points), source}; }

madd::GisRing square(double x0, double y0, double x1, double y1) {
  return ring({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

// A projected set (no projection: exact arithmetic in the tests) of one polygon.
madd::PolygonSet one_polygon(madd::GisRing outer, std::vector<madd::GisRing> holes = {}) {
  madd::PolygonSet set;
  set.coordinates = madd::Coordinates::projected;
  set.polygons.push_back({std::move(outer), std::move(holes), 1, 0, 0});
  return set;
}

double segment_length_with(const madd::Pslg& d, int marker) {
  double total = 0.0;
  for (const madd::Segment& s : d.segments)
    if (s.marker == marker) total += madd::distance(d.points[s.a], d.points[s.b]);
  return total;
}

// Every segment lies on one side of the box (the open ones) or off it.
bool open_segments_on_box(const madd::Pslg& d, const madd::ClipBox& b) {
  for (const madd::Segment& s : d.segments) {
    if (s.marker != 2) continue;
    const madd::Point p = d.points[s.a], q = d.points[s.b];
    const bool on = (p.x == b.x0 && q.x == b.x0) || (p.x == b.x1 && q.x == b.x1) || (p.y == b.y0 && q.y == b.y0) ||
                    (p.y == b.y1 && q.y == b.y1);
    if (!on) return false;
  }
  return true;
}

// Sutherland and Hodgman's clipping of one ring to a box: an independent
// reading of the clipped area (its degenerate edges along the box add none).
std::vector<madd::Point> clip_ring_sh(std::vector<madd::Point> ring, const madd::ClipBox& b) {
  const auto clip_half = [](const std::vector<madd::Point>& in, auto inside, auto cut) {
    std::vector<madd::Point> out;
    for (std::size_t k = 0; k < in.size(); ++k) {
      const madd::Point p = in[k], q = in[(k + 1) % in.size()];
      if (inside(p)) out.push_back(p);
      if (inside(p) != inside(q)) out.push_back(cut(p, q));
    }
    return out;
  };
  const auto at_x = [](madd::Point p, madd::Point q, double x) {
    return madd::Point{x, p.y + (x - p.x) * (q.y - p.y) / (q.x - p.x)};
  };
  const auto at_y = [](madd::Point p, madd::Point q, double y) {
    return madd::Point{p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y), y};
  };
  ring = clip_half(
      ring, [&](madd::Point p) { return p.x >= b.x0; }, [&](madd::Point p, madd::Point q) { return at_x(p, q, b.x0); });
  ring = clip_half(
      ring, [&](madd::Point p) { return p.x <= b.x1; }, [&](madd::Point p, madd::Point q) { return at_x(p, q, b.x1); });
  ring = clip_half(
      ring, [&](madd::Point p) { return p.y >= b.y0; }, [&](madd::Point p, madd::Point q) { return at_y(p, q, b.y0); });
  ring = clip_half(
      ring, [&](madd::Point p) { return p.y <= b.y1; }, [&](madd::Point p, madd::Point q) { return at_y(p, q, b.y1); });
  return ring;
}

double area(const std::vector<madd::Point>& ring) {
  return madd::detail::ring_signed_area(madd::detail::RingView(ring));
}

// A star-shaped ring about c: n vertices at radii in [r0, r1].
std::vector<madd::Point> star(std::mt19937& rng, madd::Point c, double r0, double r1, int n, bool clockwise) {
  std::uniform_real_distribution<double> radius(r0, r1);
  std::vector<madd::Point> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n, r = radius(rng);
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  if (clockwise) std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_SUITE("coast") {

TEST_CASE("projection: equirectangular about the centre, metres along meridians, exact enough both ways") {
  const madd::Projection p{true, -69.75, 43.7};
  const madd::Point centre = p.to_metres({-69.75, 43.7});
  CHECK(centre.x == 0.0);
  CHECK(centre.y == 0.0);
  const double metres_per_degree = madd::Projection::earth_radius_m * M_PI / 180.0;
  CHECK(p.to_metres({-69.75, 44.7}).y == doctest::Approx(metres_per_degree).epsilon(1e-15));
  CHECK(p.to_metres({-68.75, 43.7}).x ==
        doctest::Approx(metres_per_degree * std::cos(43.7 * M_PI / 180)).epsilon(1e-15));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lon(-70.2, -69.3), lat(43.3, 44.0);
  for (int k = 0; k < 1000; ++k) {
    const madd::Point q{lon(rng), lat(rng)};
    const madd::Point back = p.to_lonlat(p.to_metres(q));
    CHECK(std::abs(back.x - q.x) < 1e-12);
    CHECK(std::abs(back.y - q.y) < 1e-12);
  }
  const madd::Projection identity;
  CHECK(identity.to_metres({3, 4}) == madd::Point{3, 4});
  CHECK(identity.to_lonlat({3, 4}) == madd::Point{3, 4});
}

TEST_CASE("clip: the box's sides that bound water become open boundary, the coast stays land") {
  // Water in [0, 10]^2 with an island [4, 6]^2; the box cuts the island through.
  const madd::PolygonSet set = one_polygon(square(0, 0, 10, 10), {square(4, 4, 6, 6)});
  madd::CoastOptions options;
  options.clip = madd::ClipBox{2, -5, 8, 5};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(d.report.area_m2 == doctest::Approx(6 * 5 - 2 * 1));
  CHECK(madd::domain_area(d.domain) == doctest::Approx(28));
  CHECK(open_segments_on_box(d.domain, *options.clip));
  // Open: the west and east sides (5 each) and the north side less the island's 2.
  CHECK(segment_length_with(d.domain, 2) == doctest::Approx(5 + 5 + 6 - 2));
  // Land: the coast along y = 0 (6) and the island's three sides inside the box (1 + 2 + 1).
  CHECK(segment_length_with(d.domain, 1) == doctest::Approx(6 + 4));
  CHECK(d.domain.holes.empty());  // the island is now a notch of the outer boundary
  CHECK(d.report.open_segments + d.report.land_segments == d.domain.segments.size());
}

TEST_CASE("clip: a box wholly in the water is all open boundary; a box on land has no water") {
  const madd::PolygonSet set = one_polygon(square(0, 0, 10, 10), {square(4, 4, 6, 6)});
  madd::CoastOptions options;
  options.clip = madd::ClipBox{1, 1, 3, 2};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(2));
  CHECK(d.report.land_segments == 0);
  CHECK(segment_length_with(d.domain, 2) == doctest::Approx(6));
  options.clip = madd::ClipBox{4.5, 4.5, 5.5, 5.5};  // inside the island
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::InvalidInputError);
  options.clip = madd::ClipBox{20, 20, 30, 30};  // off the polygon
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::InvalidInputError);
  options.clip = madd::ClipBox{3, 3, 1, 4};
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::OptionError);
}

TEST_CASE("clip: a box side through vertices and along an edge is moved off them") {
  // The box's west side x = 5 runs through two coast vertices and along the edge between them.
  const madd::PolygonSet set = one_polygon(ring({{0, 0}, {5, 0}, {5, 1}, {5, 2}, {10, 2}, {10, 10}, {0, 10}}));
  madd::CoastOptions options;
  options.clip = madd::ClipBox{5, 1, 10, 5};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(5 * 3).epsilon(1e-12));
  const madd::ClipBox moved = madd::detail::box_off_vertices(
      std::vector<madd::detail::MarkedPolygon>{{{{{5, 0}, {5, 2}, {10, 2}}, {1, 1, 1}, {{}, {}, {}}}, {}}},
      *options.clip);
  CHECK(moved.x0 < 5.0);
  CHECK(moved.x0 == std::nextafter(5.0, 0.0));
  CHECK(moved.x1 == std::nextafter(10.0, 20.0));
  CHECK(moved.y0 == 1.0);
}

TEST_CASE("clip: the bodies' area is Sutherland-Hodgman's, ring by ring, on random seas with islands") {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> corner(-12, 12), size(2, 20);
  for (int trial = 0; trial < 200; ++trial) {
    madd::detail::MarkedPolygon sea;
    const std::vector<madd::Point> outer = star(rng, {0, 0}, 6, 10, 40, false);
    for (madd::Point p : outer) sea.outer.push(p, 1, {0, 0, 0});
    std::vector<std::vector<madd::Point>> islands;
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * M_PI * k / 3;
      islands.push_back(star(rng, {3 * std::cos(a), 3 * std::sin(a)}, 0.5, 1.2, 9, true));
      madd::detail::MarkedRing hole;
      for (madd::Point p : islands.back()) hole.push(p, 1, {0, 1, 0});
      sea.holes.push_back(hole);
    }
    const double x0 = corner(rng), y0 = corner(rng);
    const madd::ClipBox box{x0, y0, x0 + size(rng), y0 + size(rng)};
    double expected = area(clip_ring_sh(outer, box));
    for (const auto& island : islands) expected += area(clip_ring_sh(island, box));
    const std::vector<madd::detail::MarkedPolygon> sea_only{sea};
    const madd::ClipBox off = madd::detail::box_off_vertices(sea_only, box);
    double got = 0.0;
    for (const auto& body : madd::detail::clip_to_box(sea_only, off, 2)) {
      got += madd::detail::signed_area_of(body.outer);
      CHECK(madd::detail::signed_area_of(body.outer) > 0.0);
      for (const auto& hole : body.holes) got += madd::detail::signed_area_of(hole);
    }
    CAPTURE(trial);
    CHECK(got == doctest::Approx(expected).epsilon(1e-9).scale(1.0));
  }
}

TEST_CASE("cleaning: islands touching each other and the coast at a point stay, each a hole of its own") {
  // Islands A and B share vertex (2, 2); C touches the coast at (5, 10), a vertex of the coast.
  const madd::PolygonSet set =
      one_polygon(ring({{0, 0}, {10, 0}, {10, 10}, {5, 10}, {0, 10}}),
                  {ring({{1, 1}, {1, 2}, {2, 2}, {2, 1}}, 1), ring({{2, 2}, {2, 3}, {3, 3}, {3, 2}}, 2),
                   ring({{5, 10}, {6, 9}, {4, 9}}, 3)});
  const madd::CoastDomain d = madd::coast_domain(set);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(100 - 1 - 1 - 1));
  CHECK(d.domain.holes.size() == 3);
  CHECK(d.report.pinches == 2);
  CHECK(d.report.pockets_dropped == 0);
  CHECK(d.report.crossings_resolved == 0);
}

TEST_CASE("cleaning: a barrier island touching the coast at two points cuts off its lagoon, which is dropped") {
  // The island's ends (2, 10) and (8, 10) lie inside the coast's edge (0, 10)-(10, 10).
  const madd::PolygonSet set = one_polygon(square(0, 0, 10, 10), {ring({{2, 10}, {5, 9}, {8, 10}, {5, 8}}, 1)});
  const madd::CoastDomain d = madd::coast_domain(set);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(100 - 6));  // island 3, lagoon 3
  CHECK(d.report.pockets_dropped == 1);
  CHECK(d.domain.holes.empty());  // the island is on the outer boundary now
}

TEST_CASE("cleaning: duplicates, near duplicates and spikes go; rings given either way round; specks removed") {
  madd::PolygonSet set = one_polygon(
      // clockwise outer, a duplicate vertex, a spike out to (12, 5), a near duplicate of (0, 10)
      ring({{0, 0}, {0, 10}, {1e-12, 10}, {10, 10}, {10, 5}, {12, 5}, {10, 5}, {10, 0}, {10, 0}}),
      // a counter-clockwise island, and a speck of an island
      {ring({{4, 4}, {6, 4}, {6, 6}, {4, 6}}, 1), ring({{8, 8}, {8.01, 8}, {8.01, 8.01}}, 2)});
  madd::CoastOptions options;
  options.min_island_area = 0.01;
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(96));
  CHECK(d.report.vertices_merged == 3);  // (1e-12, 10); (10, 0) twice: the duplicate, then the spike's return
  CHECK(d.report.spikes_removed == 1);
  CHECK(d.report.small_islands_removed == 1);
  CHECK(d.domain.holes.size() == 1);
  CHECK(d.domain.points.size() == 5 + 4);  // (10, 5) stays: straight on, not back
}

TEST_CASE("bodies: the largest is kept, or the one holding water_at; water_at on land is an option error") {
  madd::PolygonSet set = one_polygon(square(0, 0, 10, 10));
  set.polygons.push_back({square(20, 0, 23, 3), {}, 1, 1, 0});
  madd::CoastDomain d = madd::coast_domain(set);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(100));
  CHECK(d.report.bodies == 2);
  CHECK(d.report.bodies_dropped == 1);
  madd::CoastOptions options;
  options.water_at = madd::Point{21, 1};
  d = madd::coast_domain(set, options);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(9));
  options.water_at = madd::Point{15, 1};
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::OptionError);
  options.water_at.reset();
  options.min_island_area = 200;
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::InvalidInputError);
}

TEST_CASE("crossing islands are split where they meet and read as Triangle reads them") {
  // Two islands overlapping in [4, 5] x [4, 5]: their union is land.
  const madd::PolygonSet set = one_polygon(
      square(0, 0, 10, 10), {ring({{3, 3}, {3, 5}, {5, 5}, {5, 3}}, 1), ring({{4, 4}, {4, 6}, {6, 6}, {6, 4}}, 2)});
  const madd::CoastDomain d = madd::coast_domain(set);
  CHECK(d.report.crossings_resolved >= 2);
  CHECK(madd::domain_area(d.domain) == doctest::Approx(100 - 7));
}

TEST_CASE("clip: an island's vertex on a box side leaves the rest of the box water") {
  // The island's vertex (4, 10) is on the north side; the side is moved an ulp
  // outwards, and both island edges cross it within an ulp of each other. Their
  // rounded crossings tie; read as a tie the island's chain closed on itself
  // and the box was lost ("no water inside the clip box"). They are ordered
  // exactly by their edges.
  const madd::PolygonSet set =
      one_polygon(ring({{-5, -5}, {20, -5}, {20, 20}, {-5, 20}}), {ring({{4, 10}, {6, 12}, {5, 14}}, 1)});
  madd::CoastOptions options;
  options.clip = madd::ClipBox{0, 0, 10, 10};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(d.report.area_m2 == doctest::Approx(100).epsilon(1e-12));
  CHECK(d.report.land_segments == 0);
  CHECK(segment_length_with(d.domain, 2) == doctest::Approx(40).epsilon(1e-12));
}

TEST_CASE("clip: a water wedge pointing out of the box from its corner is no water") {
  // The triangle's vertex (0.1, 0) is the box's north-west corner and its
  // wedge of water points away from the box: inside the box (moved an ulp
  // off the vertex) is a sliver of ulps. Crossings interpolated from the far
  // end of an edge come out an ulp of 1.2 off and in the wrong order, and
  // the whole box would be water: they are interpolated from the near end.
  const madd::PolygonSet set = one_polygon(ring({{1.2, 1.5}, {0.6, 0.2}, {0.1, 0}}));
  madd::CoastOptions options;
  options.clip = madd::ClipBox{0.1, -0.1, 0.2, 0};
  CHECK_THROWS_AS(madd::coast_domain(set, options), madd::InvalidInputError);
  // Pointing out of the north-east corner: Liang and Barsky's rounded
  // parameters tie there and pick the side the edge does not cross; the
  // side is decided exactly.
  options.clip = madd::ClipBox{-1, -1, 0, 0};
  CHECK_THROWS_AS(madd::coast_domain(one_polygon(ring({{0, 0}, {10, 14}, {5, 15}})), options), madd::InvalidInputError);
}

TEST_CASE("clip: a ring crossing itself is still closed along the box") {
  // The chains' entries and exits do not pair up: joining one ran into a
  // chain already used and closed the ring with a diagonal "open" segment.
  const madd::PolygonSet set = one_polygon(ring({{4, 0}, {5, 2}, {0, 0}, {5, 0}, {10, 2}, {10, 10}, {0, 10}}));
  madd::CoastOptions options;
  options.clip = madd::ClipBox{5, 1, 11, 5};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  const madd::ClipBox moved{std::nextafter(5.0, 0.0), 1, 11, 5};  // off the vertices at x = 5
  CHECK(open_segments_on_box(d.domain, moved));
  CHECK(d.report.open_segments == 3);
  // The box right of x = 5 above the coast edge (5, 0)-(10, 2), which leaves it at (7.5, 1).
  CHECK(d.report.area_m2 == doctest::Approx(5 * 4 - 2.5 * 1 / 2.0).epsilon(1e-12));
}

TEST_CASE("parity: an island on the coast's edge is land, not a pocket of water") {
  // The island's edge (5, 0)-(2, 0) lies on the coast's: the two become one
  // segment, and a parity flipped across segments from the hull read the
  // island as water (a pocket dropped; with overlaps from clipping, one face
  // both water and land, and an internal error). The parity is the rings'
  // winding at a point of each face.
  const madd::PolygonSet set = one_polygon(square(0, 0, 10, 10), {ring({{2, 0}, {2, 3}, {5, 3}, {5, 0}}, 1)});
  const madd::CoastDomain d = madd::coast_domain(set);
  CHECK(d.report.area_m2 == doctest::Approx(91));
  CHECK(d.report.pockets_dropped == 0);
  CHECK(d.domain.holes.empty());
}

TEST_CASE("cleaning: a figure-of-eight island whose loops cancel is land, not collapsed") {
  // Signed area 0, but it bounds two triangles of 4 (as Triangle reads it).
  const madd::PolygonSet set = one_polygon(square(0, 0, 10, 10), {ring({{2, 2}, {6, 6}, {6, 2}, {2, 6}}, 1)});
  const madd::CoastDomain d = madd::coast_domain(set);
  CHECK(d.report.rings_collapsed == 0);
  CHECK(d.report.area_m2 == doctest::Approx(100 - 8));
  CHECK(d.domain.holes.size() == 2);
}

TEST_CASE("cleaning: a ring flat in degrees is flat, whatever the projection rounds it to") {
  // (-69.25, 43.75), (-70, 43) and (-66.25, 46.75) lie on one line in degrees
  // (after the spike at (-66.75, 43.5) goes), not in the projection's
  // rounded metres: cleaned after projecting, the ring was a needle whose
  // shoelace area had the wrong sign (an internal error). Spikes and
  // duplicates are cleaned in the file's coordinates first.
  madd::PolygonSet set =
      one_polygon(ring({{-69.25, 43.75}, {-69.25, 43.75}, {-70, 43}, {-66.75, 43.5}, {-70, 43}, {-66.25, 46.75}}));
  set.coordinates = madd::Coordinates::lonlat;
  CHECK_THROWS_AS(madd::coast_domain(set), madd::InvalidInputError);
}

TEST_CASE("area check: a sliver's area is all cancellation, within the shoelace's rounding") {
  // A sliver of about 1e-3 m^2 along 1200 km (the world in degrees cut to the
  // far south): the domain's shoelace sum is off by 1% and a relative
  // tolerance called it an internal error. The loops are checked exactly
  // against the water's triangles, the area within a bound on the rounding.
  madd::PolygonSet set;
  set.polygons.push_back(
      {ring({{-180, -90}, {-174.35294117647058, 90}, {180, -19.411764705882348}}),
       {ring({{-38.823529411764696, -90}, {-180, -90}, {-161.64705882352942, 90}, {180, 90}, {180, 90}, {180, -90}},
             1)},
       3,
       0,
       0});
  madd::CoastOptions options;
  options.clip = madd::ClipBox{-40.235294117647044, -90, 180, -84.352941176470594};
  const madd::CoastDomain d = madd::coast_domain(set, options);
  CHECK(d.report.area_m2 == madd::domain_area(d.domain));
  CHECK(d.report.area_m2 < 0.01);
}

}  // TEST_SUITE
