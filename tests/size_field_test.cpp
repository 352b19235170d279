// The size field (src/sizing/): the --sizes samples read linearly or by the
// nearest sample, and the field's rules checked as properties against
// independent brute force: the distance term never above hmin + G d with the
// exact d anywhere, the feature size on a channel of known width, the
// gradient bound of the gradation in every triangle and between visible
// points, the coast markers, islands, determinism and the option errors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"
#include "sizing/nearest_sample.hpp"
#include "sizing/sample_interpolant.hpp"
#include "sizing/size_field.hpp"

using madd::MeshSizeOptions;
using madd::Point;
using madd::Pslg;
using madd::ValuedPoint;
using madd::detail::SizeField;

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Adds the closed ring `ring` to p with marker `marker` (or per-edge markers).
void add_ring(Pslg& p, const std::vector<Point>& ring, std::vector<int> markers) {
  const auto first = static_cast<std::uint32_t>(p.points.size());
  const auto n = static_cast<std::uint32_t>(ring.size());
  if (markers.size() == 1) markers.assign(n, markers[0]);
  for (std::uint32_t i = 0; i < n; ++i) {
    p.points.push_back(ring[i]);
    p.segments.push_back({first + i, first + (i + 1) % n, markers[i]});
  }
  p.has_segment_markers = true;
}

Pslg square(double side) {
  Pslg p;
  add_ring(p, {{0, 0}, {side, 0}, {side, side}, {0, side}}, {1});
  madd::validate(p);
  return p;
}

// A sea (ring `outer`) with one island (ring `island` around `hole`), all
// coast (marker 1).
Pslg sea_around(const std::vector<Point>& outer, const std::vector<Point>& island, Point hole) {
  Pslg sea;
  add_ring(sea, outer, {1});
  add_ring(sea, island, {1});
  sea.holes = {hole};
  madd::validate(sea);
  return sea;
}

// A 12 x 8 sea with a 2 x 2 island.
Pslg small_sea() { return sea_around({{0, 0}, {12, 0}, {12, 8}, {0, 8}}, {{4, 3}, {6, 3}, {6, 5}, {4, 5}}, {5, 4}); }

double segment_distance(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double t = std::clamp(madd::dot(p - a, ab) / madd::dot(ab, ab), 0.0, 1.0);
  return madd::distance(p, a + t * ab);
}

// The exact distance to the coast (the segments whose marker is in
// `markers`, all when empty), by a scan.
double coast_distance(const Pslg& p, Point x, const std::vector<int>& markers = {}) {
  double d = infinity;
  for (const madd::Segment& s : p.segments)
    if (markers.empty() || std::find(markers.begin(), markers.end(), s.marker) != markers.end())
      d = std::min(d, segment_distance(x, p.points[s.a], p.points[s.b]));
  return d;
}

// Whether x is in the domain: crossing parity over every segment (no
// interior segments in these fixtures).
bool in_domain(const Pslg& p, Point x) {
  bool odd = false;
  for (const madd::Segment& s : p.segments) {
    const Point a = p.points[s.a], b = p.points[s.b];
    if ((a.y > x.y) != (b.y > x.y) && a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y) > x.x) odd = !odd;
  }
  return odd;
}

// Random points of the domain in its bounding box [lo, hi].
std::vector<Point> random_inside(const Pslg& p, Point lo, Point hi, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y);
  std::vector<Point> out;
  while (static_cast<int>(out.size()) < count) {
    const Point x{ux(rng), uy(rng)};
    if (in_domain(p, x)) out.push_back(x);
  }
  return out;
}

MeshSizeOptions distance_field(double hmin, double rate, double hmax) {
  MeshSizeOptions s;
  s.min_edge_length = hmin;
  s.distance_rate = rate;
  s.max_edge_length = hmax;
  return s;
}

// Whether the open segment xy crosses or touches a segment of p.
bool blocked(const Pslg& p, Point x, Point y) {
  for (const madd::Segment& s : p.segments) {
    const Point a = p.points[s.a], b = p.points[s.b];
    const double o1 = madd::orient2d(x, y, a), o2 = madd::orient2d(x, y, b);
    const double o3 = madd::orient2d(a, b, x), o4 = madd::orient2d(a, b, y);
    if (o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  }
  return false;
}

// The gradient of the linear interpolant of f over triangle t of the background.
double triangle_gradient(const madd::detail::SizeBackground& bg, std::size_t t) {
  const auto& v = bg.triangles[t];
  const Point p0 = bg.points[v[0]], p1 = bg.points[v[1]], p2 = bg.points[v[2]];
  const double a1 = bg.edge[v[1]] - bg.edge[v[0]], a2 = bg.edge[v[2]] - bg.edge[v[0]];
  const Point e1 = p1 - p0, e2 = p2 - p0;
  const double det = madd::cross(e1, e2);
  return std::hypot((a1 * e2.y - a2 * e1.y) / det, (a2 * e1.x - a1 * e2.x) / det);
}

// A 20 x 12 sea with one island, and a field with every term, for the
// reading's own properties (threads, hints).
Pslg sea_with_island() {
  return sea_around({{0, 0}, {20, 0}, {20, 12}, {0, 12}}, {{5, 5}, {7, 4}, {8, 6}, {6, 7.5}}, {6.5, 5.5});
}

MeshSizeOptions every_term() {
  MeshSizeOptions size = distance_field(0.04, 0.15, 1.5);
  size.cells_across = 3.0;
  size.size_gradation = 0.2;
  return size;
}

}  // namespace

TEST_SUITE("size field") {

TEST_CASE("samples: the linear reading reproduces a linear function inside the hull") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto f = [](Point p) { return 2.0 + 0.5 * p.x - 0.25 * p.y; };
  std::vector<ValuedPoint> samples;
  for (int i = 0; i < 400; ++i) {
    const Point p{unit(rng) * 4.0, unit(rng) * 4.0};
    samples.push_back({p, f(p)});
  }
  samples.push_back({samples[7].at, 1e6});  // a duplicate: ignored, the first is kept
  const madd::detail::SampleInterpolant linear(samples, MeshSizeOptions::SampleInterpolation::linear);
  const madd::detail::NearestSample nearest(samples);
  for (int q = 0; q < 3000; ++q) {
    const Point p{unit(rng) * 6.0 - 1.0, unit(rng) * 6.0 - 1.0};
    const double got = linear.area_at(p);
    // In the samples' hull (within it by a margin, to stay clear of its
    // edges): the linear function; outside, the nearest sample's value.
    const bool deep = p.x > 0.3 && p.x < 3.7 && p.y > 0.3 && p.y < 3.7;
    if (deep) CHECK(got == doctest::Approx(f(p)).epsilon(1e-12));
    if (p.x < 0.0 || p.x > 4.0 || p.y < 0.0 || p.y > 4.0) CHECK(got == samples[nearest.nearest(p)].value);
  }
  CHECK(linear.area_at(samples[7].at) == doctest::Approx(f(samples[7].at)));
}

TEST_CASE("samples: the nearest reading is the old rule, and no-bound samples bound nothing") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ValuedPoint> samples;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) samples.push_back({{i * 0.5, j * 0.5}, 1.0 + unit(rng)});
  samples[210].value = 0.0;  // no bound
  samples[211].value = std::numeric_limits<double>::quiet_NaN();
  const madd::detail::SampleInterpolant near(samples, MeshSizeOptions::SampleInterpolation::nearest);
  const madd::detail::NearestSample scan(samples);
  for (int q = 0; q < 2000; ++q) {
    const Point p{unit(rng) * 12.0 - 1.0, unit(rng) * 12.0 - 1.0};
    const double v = samples[scan.nearest(p)].value;
    CHECK(near.area_at(p) == (v > 0.0 ? v : infinity));
  }
  // Linear: +infinity wherever a no-bound corner has weight, and never
  // below the smallest bounded corner value anywhere.
  const madd::detail::SampleInterpolant linear(samples, MeshSizeOptions::SampleInterpolation::linear);
  CHECK(linear.area_at(samples[210].at) == infinity);
  CHECK(linear.area_at({samples[210].at.x + 0.1, samples[210].at.y + 0.05}) == infinity);
  for (int q = 0; q < 2000; ++q) {
    const Point p{unit(rng) * 9.5, unit(rng) * 9.5};
    CHECK(linear.area_at(p) >= 1.0);
  }
  // No samples, or fewer than three: the nearest one (or no bound).
  const madd::detail::SampleInterpolant none({}, MeshSizeOptions::SampleInterpolation::linear);
  CHECK(none.area_at({0, 0}) == infinity);
  const std::vector<ValuedPoint> two{{{0, 0}, 1.0}, {{1, 0}, 2.0}};
  const madd::detail::SampleInterpolant pair(two, MeshSizeOptions::SampleInterpolation::linear);
  CHECK(pair.area_at({0.9, 5.0}) == 2.0);
}

TEST_CASE("distance: a square basin's field never exceeds hmin + G d, d exact") {
  const Pslg basin = square(10.0);
  const MeshSizeOptions size = distance_field(0.05, 0.15, 1.0);
  const SizeField field(basin, size);
  REQUIRE(!field.empty());
  const auto& bg = field.background();
  // At the background's points, and at random points (brute force).
  double worst = 0.0, sum = 0.0;
  std::vector<Point> probes = random_inside(basin, {0, 0}, {10, 10}, 20000, 11);
  for (std::size_t t = 0; t < bg.triangles.size(); ++t)
    if (bg.inside[t] != 0) {
      const auto& v = bg.triangles[t];
      probes.push_back(madd::triangle_centroid(bg.points[v[0]], bg.points[v[1]], bg.points[v[2]]));
    }
  for (const Point x : probes) {
    const double raw =
        std::min(size.max_edge_length, size.min_edge_length + size.distance_rate * coast_distance(basin, x));
    const double h = field.edge_at(x);
    CAPTURE(x.x);
    CAPTURE(x.y);
    REQUIRE(h <= raw);
    REQUIRE(h > 0.0);
    worst = std::max(worst, h / raw);
    sum += h / raw;
  }
  // Exact, in fact: the distance term is read with the exact distance.
  CHECK(sum / static_cast<double>(probes.size()) > 0.999);
  MESSAGE("square basin: ", bg.points.size(), " background points, mean h / raw ",
          sum / static_cast<double>(probes.size()));
}

TEST_CASE("distance: on every bundled domain, never above hmin + G d, in both readings of the term") {
  // Holes, interior segments, spirals, combs, a thin annulus: the domain's
  // own triangulation (madd::triangulate) gives the points and the boundary
  // edges, independently of the field's code.
  for (const char* name :
       {"archipelago", "comb", "estuary", "key", "l_shape", "near_collinear", "pipe", "spiral", "thin_annulus"}) {
    CAPTURE(name);
    const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name + ".poly");
    const madd::Triangulation tri = madd::triangulate(domain);
    std::vector<std::pair<Point, Point>> boundary;
    for (std::size_t t = 0; t < tri.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i)
        if (tri.neighbours[t][i] == madd::no_index)
          boundary.push_back({tri.points[tri.triangles[t][(i + 1) % 3]], tri.points[tri.triangles[t][(i + 2) % 3]]});
    double x0 = infinity, x1 = -infinity, y0 = infinity, y1 = -infinity;
    for (const Point p : domain.points)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const double hmin = std::max(x1 - x0, y1 - y0) / 400.0;
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const double gradation : {0.25, 0.1}) {  // the exact term, then the lowered linear one
      MeshSizeOptions size = distance_field(hmin, 0.2, 40.0 * hmin);
      size.cells_across = 3.0;
      size.size_gradation = gradation;
      const SizeField field(domain, size);
      CHECK(field.report().floored_points == 0);
      for (int q = 0; q < 3000; ++q) {
        const auto& v = tri.triangles[rng() % tri.triangles.size()];
        double a = unit(rng), b = unit(rng);
        if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
        const Point o = tri.points[v[0]];
        const Point x = o + a * (tri.points[v[1]] - o) + b * (tri.points[v[2]] - o);
        double d = infinity;
        for (const auto& [p, r] : boundary) d = std::min(d, segment_distance(x, p, r));
        const double h = field.edge_at(x);
        CAPTURE(x.x);
        CAPTURE(x.y);
        REQUIRE(h <= std::min(40.0 * hmin, hmin + 0.2 * d));
        REQUIRE(h > 0.0);
      }
    }
  }
}

TEST_CASE("distance: islands are coast, and the field is deterministic") {
  Pslg sea;
  add_ring(sea, {{0, 0}, {20, 0}, {20, 12}, {0, 12}}, {1});
  add_ring(sea, {{5, 5}, {7, 4}, {8, 6}, {6, 7.5}}, {1});
  add_ring(sea, {{13, 3}, {15, 3}, {15, 9}, {14, 9.5}, {13, 9}}, {1});
  sea.holes = {{6.5, 5.5}, {14, 6}};
  madd::validate(sea);
  const MeshSizeOptions size = distance_field(0.04, 0.2, 1.5);
  const SizeField field(sea, size);
  for (const Point x : random_inside(sea, {0, 0}, {20, 12}, 20000, 13)) {
    const double raw =
        std::min(size.max_edge_length, size.min_edge_length + size.distance_rate * coast_distance(sea, x));
    REQUIRE(field.edge_at(x) <= raw);
  }
  // Next to an island, far from the outer ring, the field is fine.
  CHECK(field.edge_at({9.0, 5.0}) <= 0.04 + 0.2 * 1.35);  // 1.34 from the first island, 5 from the outer ring
  const SizeField again(sea, size);
  CHECK(again.background().points == field.background().points);
  CHECK(again.background().triangles == field.background().triangles);
  CHECK(again.background().edge == field.background().edge);
}

TEST_CASE("the field built on several threads is the one built on one") {
  // Enough background triangles for several chunks of the coast candidates'
  // lists (2048 triangles a chunk), with the exact distance term and gradation.
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/archipelago.poly");
  MeshSizeOptions size = distance_field(0.05, 0.15, 5.0);  // the bay is 118 x 81
  size.cells_across = 3;
  size.size_gradation = 0.2;
  const SizeField one(domain, size, 1);
  REQUIRE(one.report().inside_triangles > 3 * 2048);
  REQUIRE(one.report().exact_triangles > 0);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const SizeField many(domain, size, threads);
    CHECK(many.report().coast_candidates == one.report().coast_candidates);
    CHECK(many.report().exact_triangles == one.report().exact_triangles);
    CHECK(many.background().triangles == one.background().triangles);
    CHECK(many.background().edge == one.background().edge);
    // The exact term reads each triangle's own list: the same value everywhere.
    std::size_t differ = 0;
    for (const Point x : random_inside(domain, {-12, -22}, {107, 60}, 20000, 5))
      differ += many.edge_at(x) != one.edge_at(x);
    CHECK(differ == 0);
  }
}

TEST_CASE("distance: graded below its rate, the lowered linear term still never exceeds hmin + G d") {
  // The gradation (0.1) is below the distance rate (0.3): the distance term
  // is graded with the rest, through its point values lowered by the
  // safety bound (src/sizing/distance_bound.hpp).
  Pslg sea;
  add_ring(sea, {{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {1});
  add_ring(sea, {{3, 2}, {5, 2.5}, {4, 4}}, {1});
  sea.holes = {{4, 2.8}};
  madd::validate(sea);
  MeshSizeOptions size = distance_field(0.03, 0.3, 1.0);
  size.size_gradation = 0.1;
  const SizeField field(sea, size);
  double sum = 0.0;
  const std::vector<Point> probes = random_inside(sea, {0, 0}, {10, 6}, 20000, 23);
  for (const Point x : probes) {
    const double raw = std::min(1.0, 0.03 + 0.3 * coast_distance(sea, x));
    const double h = field.edge_at(x);
    REQUIRE(h <= raw);
    REQUIRE(h > 0.0);
    sum += h / std::min(1.0, 0.03 + 0.1 * coast_distance(sea, x));
  }
  // Within the gradation's own cone (hmin + 0.1 d) on average, not far below.
  MESSAGE("graded distance: mean h / (hmin + 0.1 d) ", sum / static_cast<double>(probes.size()));
  CHECK(sum / static_cast<double>(probes.size()) > 0.7);
  CHECK(field.report().floored_points == 0);
}

TEST_CASE("coast points read the water's field: hmin on every ring, not the land's linear part") {
  // A point on the coast is on an inside and an outside triangle of the
  // background; the outside one carries only the linear part (hmax here).
  // The decoupling samples its segments there: reading hmax at a separator's
  // end on the coast made its first piece 45 x too long for the triangles
  // beside it, and refinement then stopped at it.
  const Pslg sea = small_sea();
  MeshSizeOptions size = distance_field(0.02, 0.15, 1.5);
  size.size_gradation = 0.2;
  const SizeField field(sea, size);
  std::size_t probes = 0, above = 0;
  for (const madd::Segment& s : sea.segments)
    for (int k = 0; k <= 64; ++k) {
      const Point p = madd::lerp(sea.points[s.a], sea.points[s.b], k / 64.0);
      ++probes;
      above += field.edge_at(p) > 0.02;
    }
  CHECK(probes == 8 * 65);
  CHECK(above == 0);
  // A rounding off the coast onto the land, on the island and beyond the
  // hull: within the exact term of the water's edge.
  for (const Point p : {Point{4.0 + 1e-15, 4.0}, Point{5.0, 5.0 - 1e-15}, Point{3.0, -1e-15}, Point{12.0 + 1e-14, 7.0},
                        Point{7.0, 8.0 + 1e-14}})
    above += field.edge_at(p) > 0.02 * (1.0 + 1e-9);
  CHECK(above == 0);
  // The background's own points on the coast too (its quadtree points are
  // on no ring; its coast vertices are the rings').
  const auto& bg = field.background();
  std::size_t on_coast = 0;
  for (std::size_t v = 0; v < bg.points.size(); ++v)
    if (coast_distance(sea, bg.points[v]) == 0.0) ++on_coast, above += field.edge_at(bg.points[v]) > 0.02;
  CHECK(on_coast >= 8);
  CHECK(above == 0);
}

TEST_CASE("gradation: with the exact distance term, visible pairs within the rate") {
  const Pslg sea = small_sea();
  MeshSizeOptions size = distance_field(0.02, 0.15, 1.5);
  size.triangle_area_function = [](double x, double y) { return std::hypot(x - 9.0, y - 2.0) < 1.5 ? 1e-3 : 1.0; };
  size.size_gradation = 0.2;
  const SizeField field(sea, size);
  CHECK(field.report().exact_triangles == field.report().inside_triangles);
  const std::vector<Point> probes = random_inside(sea, {0, 0}, {12, 8}, 6000, 29);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i + 1 < probes.size(); i += 2) {
    const Point x = probes[i], y = probes[i + 1];
    CHECK(field.edge_at(x) <= 0.02 + 0.15 * coast_distance(sea, x));
    if (blocked(sea, x, y)) continue;
    ++pairs;
    CHECK(field.edge_at(x) <= field.edge_at(y) + 0.2 * madd::distance(x, y) * (1.0 + 1e-9) + 1e-12);
  }
  CHECK(pairs > 1500);
  // Short steps too, where a jump between triangles would show.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const Point x : probes) {
    const Point y{x.x + 0.01 * unit(rng), x.y + 0.01 * unit(rng)};
    if (!in_domain(sea, y) || blocked(sea, x, y)) continue;
    CHECK(field.edge_at(x) <= field.edge_at(y) + 0.2 * madd::distance(x, y) * (1.0 + 1e-9) + 1e-12);
  }
  CHECK(field.edge_at({9.0, 2.0}) <= madd::detail::edge_of_area(1e-3) * 1.5);
}

TEST_CASE("gradation: every inside triangle and every visible pair within the rate, never raised") {
  const Pslg sea = small_sea();
  // A steep distance term, and an area function with a tiny spot: both need limiting.
  MeshSizeOptions size = distance_field(0.02, 0.6, 1.5);
  // (The background samples the function at its points: the spot is wider than its cells there.)
  size.triangle_area_function = [](double x, double y) { return std::hypot(x - 9.0, y - 2.0) < 1.5 ? 1e-3 : 1.0; };
  MeshSizeOptions raw_size = size;
  size.size_gradation = 0.2;
  const SizeField raw(sea, raw_size), field(sea, size);
  const auto& bg = field.background();
  double steepest = 0.0;
  for (std::size_t t = 0; t < bg.triangles.size(); ++t)
    if (bg.inside[t] != 0) steepest = std::max(steepest, triangle_gradient(bg, t));
  CHECK(steepest <= 0.2 * (1.0 + 1e-9));
  CHECK(steepest > 0.15);  // the limiter binds somewhere: the test tests something
  const std::vector<Point> probes = random_inside(sea, {0, 0}, {12, 8}, 4000, 17);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i + 1 < probes.size(); i += 2) {
    const Point x = probes[i], y = probes[i + 1];
    const double hx = field.edge_at(x), hy = field.edge_at(y);
    CHECK(hx <= raw.edge_at(x) * (1.0 + 1e-12));  // only lowered
    if (blocked(sea, x, y)) continue;
    ++pairs;
    CHECK(hx <= hy + 0.2 * madd::distance(x, y) * (1.0 + 1e-9) + 1e-12);
  }
  CHECK(pairs > 1000);
  // The spot is in the background, and graded around it.
  const double spot = madd::detail::edge_of_area(1e-3);
  CHECK(field.edge_at({9.0, 2.0}) <= spot * 1.5);
  CHECK(field.edge_at({9.0, 6.0}) <= field.edge_at({9.0, 2.0}) + 0.2 * 4.0 * (1.0 + 1e-9));
  CHECK(raw.edge_at({9.0, 6.0}) > field.edge_at({9.0, 2.0}) + 0.2 * 4.0);
}

TEST_CASE("coast markers: a side that is not coast pulls nothing fine") {
  Pslg box;
  add_ring(box, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {2, 1, 1, 1});  // the bottom side: marker 2, the open sea
  madd::validate(box);
  MeshSizeOptions size = distance_field(0.05, 0.15, 1.0);
  const SizeField all(box, size);
  size.coast_markers = {1};
  const SizeField coast(box, size);
  CHECK(all.edge_at({5.0, 0.1}) < 0.1);
  CHECK(coast.edge_at({5.0, 0.1}) > 0.6);  // hmin + G 4.9 = 0.785 from the other sides
  for (const Point x : random_inside(box, {0, 0}, {10, 10}, 5000, 19)) {
    const double raw = std::min(1.0, 0.05 + 0.15 * coast_distance(box, x, {1}));
    REQUIRE(coast.edge_at(x) <= raw);
  }
}

TEST_CASE("feature size: a channel of width W gets h <= W / R along it") {
  // A basin and a channel of width 1 running east from it, closed at its end.
  const double w = 1.0, r = 3.0;
  Pslg basin;
  add_ring(basin, {{0, 0}, {20, 0}, {20, 9}, {40, 9}, {40, 9 + w}, {20, 9 + w}, {20, 20}, {0, 20}}, {1});
  madd::validate(basin);
  MeshSizeOptions size;
  size.min_edge_length = 0.02;
  size.max_edge_length = 3.0;
  size.cells_across = r;
  const SizeField field(basin, size);
  // Along the axis and across the channel, from its mouth to its closed end.
  for (double x = 20.0; x <= 40.0; x += 0.05)
    for (const double y : {9.0 + 0.5 * w, 9.0 + 0.1 * w, 9.0 + 0.9 * w}) {
      CAPTURE(x);
      CAPTURE(y);
      CHECK(field.edge_at({x, y}) <= w / r * (1.0 + 1e-9));
    }
  // Not pulled down in the basin away from the channel: the width there is
  // the basin's (20 across: 2 * 10 / 3 > hmax).
  CHECK(field.edge_at({6.0, 5.0}) == doctest::Approx(3.0));
  CHECK(field.edge_at({10.0, 14.0}) > 2.0);
}

TEST_CASE("edge_at: the same from several threads at once as from one") {
  const Pslg sea = sea_with_island();
  const SizeField field(sea, every_term());
  const std::vector<Point> probes = random_inside(sea, {0, 0}, {20, 12}, 20000, 37);
  std::vector<double> alone(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i) alone[i] = field.edge_at(probes[i]);
  std::vector<std::vector<double>> together(4, std::vector<double>(probes.size()));
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < together.size(); ++k)
    threads.emplace_back([&, k] {
      for (std::size_t i = 0; i < probes.size(); ++i) {
        const std::size_t j = (i * 7919 + k * 1237) % probes.size();  // each thread in its own order
        together[k][j] = field.edge_at(probes[j]);
      }
    });
  for (std::thread& t : threads) t.join();
  for (const auto& run : together) CHECK(run == alone);
  // A copy reads the same (the locator keeps no view of the background).
  const SizeField copy = field;
  for (std::size_t i = 0; i < probes.size(); i += 97) CHECK(copy.edge_at(probes[i]) == alone[i]);
}

// A walk hint (one caller's last location) only shortens the walk: the
// field reads the same with or without it, in any order, also at points on
// the background's edges and corners, where two or more triangles hold the
// point and the lowest-numbered one is read (brute force over them all).
TEST_CASE("edge_at: the same with a walk hint as without, on edges and corners too") {
  const Pslg sea = sea_with_island();
  const SizeField field(sea, every_term());
  const madd::detail::SizeBackground& bg = field.background();
  std::vector<Point> probes = random_inside(sea, {0, 0}, {20, 12}, 5000, 41);
  std::size_t on_edges = 0;
  for (std::size_t t = 0; t < bg.triangles.size(); t += 3) {
    const auto& v = bg.triangles[t];
    probes.push_back(bg.points[v[0]]);
    const Point m = madd::midpoint(bg.points[v[1]], bg.points[v[2]]);
    if (madd::orient2d(bg.points[v[1]], bg.points[v[2]], m) == 0.0) probes.push_back(m), ++on_edges;
  }
  CHECK(on_edges > 100);  // the quadtree's edges are axis-parallel: their midpoints are on them
  std::vector<double> alone(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i) alone[i] = field.edge_at(probes[i]);
  std::mt19937 rng(5);
  for (int order = 0; order < 3; ++order) {
    madd::detail::WalkHint hint;
    std::vector<std::size_t> idx(probes.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    if (order > 0) std::shuffle(idx.begin(), idx.end(), rng);
    std::size_t differ = 0;
    for (const std::size_t i : idx) differ += field.edge_at(probes[i], &hint) != alone[i];
    CHECK(differ == 0);
  }
  // The locator itself: the lowest-numbered triangle whose closure holds p.
  const madd::detail::TriangleView view{bg.points, bg.triangles, bg.neighbours};
  const madd::detail::TriangleLocator locator(view);
  madd::detail::WalkHint hint;
  std::size_t wrong = 0;
  for (const Point p : probes) {
    std::uint32_t lowest = madd::no_index;
    for (std::uint32_t t = 0; t < bg.triangles.size() && lowest == madd::no_index; ++t) {
      const auto& v = bg.triangles[t];
      bool in = true;
      for (int i = 0; i < 3; ++i) in = in && madd::orient2d(bg.points[v[i]], bg.points[v[(i + 1) % 3]], p) >= 0;
      if (in) lowest = t;
    }
    const madd::detail::Location at = locator.locate(view, p, &hint);
    wrong += !at.inside || at.triangle != lowest;
  }
  CHECK(wrong == 0);
}

TEST_CASE("options: bad field options are OptionErrors naming the field") {
  const Pslg basin = square(1.0);
  const auto field_of = [&](const MeshSizeOptions& s) {
    try {
      SizeField f(basin, s);
    } catch (const madd::OptionError& e) {
      return e.option() + ": " + e.what();
    }
    return std::string();
  };
  MeshSizeOptions s = distance_field(0.01, 0.1, 0.5);
  CHECK(field_of(s).empty());
  s.distance_rate = -1.0;
  CHECK(field_of(s).rfind("distance_rate", 0) == 0);
  s.distance_rate = std::numeric_limits<double>::quiet_NaN();
  CHECK(field_of(s).rfind("distance_rate", 0) == 0);
  s = distance_field(0.6, 0.1, 0.5);
  CHECK(field_of(s).rfind("min_edge_length", 0) == 0);
  s = distance_field(0.0, 0.1, 0.5);
  CHECK(field_of(s).rfind("distance_rate", 0) == 0);
  s = MeshSizeOptions{};
  s.cells_across = 3.0;
  CHECK(field_of(s).rfind("cells_across", 0) == 0);
  s.min_edge_length = 0.01;
  CHECK(field_of(s).empty());
  s.size_gradation = infinity;
  CHECK(field_of(s).rfind("size_gradation", 0) == 0);
  s = distance_field(0.01, 0.1, 0.5);
  s.coast_markers = {1, 7};
  const std::string message = field_of(s);
  CHECK(message.find("coast_markers") == 0);
  CHECK(message.find("7") != std::string::npos);
  CHECK(message.find("markers are 1") != std::string::npos);
}

TEST_CASE("edge_of_area and area_of_edge are inverse, and say no bound for none") {
  for (const double h : {1e-6, 0.3, 1.0, 250.0})
    CHECK(madd::detail::edge_of_area(madd::detail::area_of_edge(h)) == doctest::Approx(h).epsilon(1e-14));
  CHECK(madd::detail::area_of_edge(1.0) == doctest::Approx(std::sqrt(3.0) / 4.0));
  CHECK(madd::detail::edge_of_area(0.0) == infinity);
  CHECK(madd::detail::edge_of_area(std::numeric_limits<double>::quiet_NaN()) == infinity);
  CHECK(SizeField().edge_at({0, 0}) == infinity);
}

}  // TEST_SUITE

TEST_CASE("gradation: never below hmin, the smallest value of every term") {
  // Flattening a needle of the background, whose short edge alone is steeper
  // than the rate, lowered its third corner without end (on the Gulf of
  // Finland below 0: the field read sides of 1e-5 where hmin was 0.12, a run
  // that filled the machine's memory), and the distance term's safety bound
  // lowers point values below hmin where the background is coarse (on the
  // bundled archipelago at hmin = extent / 1000, to 0.53 hmin). Every term
  // is hmin or more, so the field is too.
  const Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/archipelago.poly");
  double x0 = infinity, x1 = -infinity, y0 = infinity, y1 = -infinity;
  for (const Point p : domain.points)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  for (const double divisor : {1000.0, 2000.0, 3300.0}) {
    for (const double gradation : {0.1, 0.25}) {
      const double hmin = std::max(x1 - x0, y1 - y0) / divisor;
      MeshSizeOptions size = distance_field(hmin, 0.3, 30.0 * hmin);
      size.cells_across = 3.0;
      size.size_gradation = gradation;
      const SizeField field(domain, size);
      CAPTURE(divisor);
      CAPTURE(gradation);
      // Read at the centroid of every inside triangle of the background.
      const auto& bg = field.background();
      double lowest = infinity;
      for (std::size_t t = 0; t < bg.triangles.size(); ++t) {
        if (bg.inside[t] == 0) continue;
        const auto& v = bg.triangles[t];
        lowest =
            std::min(lowest, field.edge_at(madd::triangle_centroid(bg.points[v[0]], bg.points[v[1]], bg.points[v[2]])));
      }
      CHECK(lowest >= hmin * (1.0 - 1e-9));
    }
  }
}
