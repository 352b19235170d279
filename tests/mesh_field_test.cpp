// madd::mesh with the size field (docs/mesh.md, "Size field"), end to end on
// a basin with a channel of known width (as data/channel.poly): mesh()
// verifies itself against the same field; here the mesh is checked from the
// outside against the raw rules, by brute force.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "madd/bathymetry.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/decomposition.hpp"
#include "mesh/narrow_gaps.hpp"
#include "mesh/refine.hpp"
#include "mesh/work.hpp"
#include "quality/area_bound.hpp"
#include "sizing/edge_length.hpp"

namespace {

// A 10 x 10 basin whose south side runs through `south` (from (0, 0) to
// (10, 0)), meshed as one subdomain at A = 0.04 (sides of about 0.3): the
// estimate against the count.
double estimate_over_count(const std::vector<madd::Point>& south) {
  madd::Pslg d;
  d.points = south;
  d.points.insert(d.points.end(), {{10, 10}, {0, 10}});
  const auto n = static_cast<std::uint32_t>(d.points.size());
  for (std::uint32_t i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n, 1});
  madd::MeshOptions o;
  o.decomposition.subdomains = 1;
  o.size.min_triangle_angle_deg = 30;
  o.size.max_triangle_area = 0.04;
  const madd::MeshRun run = madd::mesh_with_report(d, o);
  return run.report.expected_triangles.at(0) / static_cast<double>(run.mesh.triangles.size());
}

// data/channel.poly: a 10 x 10 basin, a channel of width 0.25 from x = 10 to
// 18 at y = 5; the west side (x = 0) is open sea (marker 2), the rest coast (1).
madd::Pslg channel_domain() {
  madd::Pslg d;
  d.points = {{0, 0}, {10, 0}, {10, 4.875}, {18, 4.875}, {18, 5.125}, {10, 5.125}, {10, 10}, {0, 10}};
  for (std::uint32_t i = 0; i < 8; ++i) d.segments.push_back({i, (i + 1) % 8, i == 7 ? 2 : 1});
  return d;
}

double distance_to_segment(madd::Point p, madd::Point a, madd::Point b) {
  const double vx = b.x - a.x, vy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * vx + (p.y - a.y) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * vx), p.y - (a.y + t * vy));
}

madd::MeshOptions field_options(std::uint32_t threads) {
  madd::MeshOptions o;
  o.decomposition.subdomains = 4;
  o.decomposition.threads = threads;
  o.size.min_triangle_angle_deg = 30;
  o.size.min_edge_length = 0.02;
  o.size.max_edge_length = 1.0;
  o.size.distance_rate = 0.15;
  o.size.cells_across = 3;
  o.size.size_gradation = 0.2;
  o.size.coast_markers = {1};
  return o;
}

}  // namespace

TEST_SUITE("mesh with a size field") {
TEST_CASE("every triangle within sqrt(3)/4 min(hmax, hmin + G d)^2, d the exact distance to the coast") {
  const madd::Pslg domain = channel_domain();
  const madd::MeshOptions o = field_options(2);
  const madd::Mesh m = madd::mesh(domain, o);
  REQUIRE(!m.triangles.empty());
  for (const auto& t : m.triangles) {
    const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    const madd::Point g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    double d = std::numeric_limits<double>::infinity();
    for (const madd::Segment& s : domain.segments)
      if (s.marker == 1) d = std::min(d, distance_to_segment(g, domain.points[s.a], domain.points[s.b]));
    const double h = std::min(o.size.max_edge_length, o.size.min_edge_length + o.size.distance_rate * d);
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    REQUIRE(area <= std::sqrt(3.0) / 4 * h * h * (1 + 1e-9));
  }
}

// The fewest triangles a vertical line through the channel (x in 10..18,
// y in 4.875..5.125) crosses, over cross-sections every 0.25.
int fewest_across_channel(const madd::Mesh& m) {
  int fewest = std::numeric_limits<int>::max();
  // Off round numbers, so that no cross-section runs along a vertical edge (a
  // separator across the channel at x = 12 would leave it no triangle).
  for (double x = 10.2371; x < 17.9; x += 0.25) {
    int across = 0;
    for (const auto& t : m.triangles) {
      const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
      const double lo = std::min({a.x, b.x, c.x}), hi = std::max({a.x, b.x, c.x});
      const double cy = (a.y + b.y + c.y) / 3;
      if (lo < x && x < hi && cy > 4.875 && cy < 5.125) ++across;
    }
    fewest = std::min(fewest, across);
  }
  return fewest;
}

TEST_CASE("the channel is meshed at least R triangles across every cross-section") {
  // The feature size alone: without the distance term (whose hmin + G d is
  // already fine inside a narrow channel) only --cells-across holds the
  // channel's size, so this fails if the feature-size term is lost.
  madd::MeshOptions o = field_options(2);
  o.size.distance_rate = 0;
  o.size.min_edge_length = 0.01;
  const int with_term = fewest_across_channel(madd::mesh(channel_domain(), o));
  CHECK(with_term >= o.size.cells_across);
  o.size.cells_across = 0;
  const int without_term = fewest_across_channel(madd::mesh(channel_domain(), o));
  CHECK(without_term < 3);
}

TEST_CASE("reading most bounds from a neighbour's query makes the same mesh as querying every triangle") {
  // A graded field is G-Lipschitz along paths in the domain, so the mesher
  // decides most triangles from the last query of the same fan
  // (Refiner::bound_of); that must change no decision.
  const madd::Pslg domain = channel_domain();
  const madd::MeshOptions o = field_options(1);
  const madd::detail::AreaBound bound(o.size, &domain);
  REQUIRE(bound.edge_slope() == 0.2);
  madd::detail::RefineSettings settings;
  settings.size = &bound;
  const std::vector<bool> splittable(domain.segments.size(), true);
  const madd::detail::SubdomainMesh read = madd::detail::refine_subdomain(domain, splittable, settings);
  settings.bounds_from_neighbours = false;
  const madd::detail::SubdomainMesh queried = madd::detail::refine_subdomain(domain, splittable, settings);
  REQUIRE(read.triangles.size() > 5000);
  CHECK(read.points == queried.points);
  CHECK(read.triangles == queried.triangles);
}

TEST_CASE("the least bound (no query below it) is at most the bound everywhere, and 0 when unknown") {
  const madd::Pslg domain = channel_domain();
  madd::MeshOptions o = field_options(1);
  const madd::detail::AreaBound field(o.size, &domain);
  CHECK(field.least() == doctest::Approx(std::sqrt(3.0) / 4 * 0.02 * 0.02).epsilon(1e-9));
  std::size_t at_least = 0, probes = 0;
  for (double x = 0.01; x < 18; x += 0.173)
    for (double y = 0.01; y < 10; y += 0.0617) {
      if (x > 10 && (y < 4.875 || y > 5.125)) continue;
      ++probes;
      at_least += field.area_at({x, y}) >= field.least();
    }
  CHECK(probes > 5000);
  CHECK(at_least == probes);
  // Without hmin (a gradation of hmax alone) or with an area function: no floor known.
  o.size.min_edge_length = 0;
  o.size.distance_rate = 0;
  o.size.cells_across = 0;
  CHECK(madd::detail::AreaBound(o.size, &domain).least() == 0.0);
  o = field_options(1);
  o.size.triangle_area_function = [](double, double) { return 1e-9; };
  CHECK(madd::detail::AreaBound(o.size, &domain).least() == 0.0);
}

TEST_CASE("separator pieces under a graded field: no triangle bad by its size can encroach one") {
  // A triangle whose circumcentre encroaches a piece of length L has
  // circumradius <= L / sqrt(2) and area <= 3 sqrt(3) / 8 L^2; it is bad by
  // size only if that is above the bound at its centroid, which lies within
  // L / sqrt(2) + L / 2 of the piece's midpoint. So L <= sqrt(8 / (3 sqrt(3)))
  // sqrt(A(c)) for every such c keeps the decoupling (docs/mesh.md); the
  // pieces were sized from A on the piece itself, where the field is up to
  // G x 1.21 L larger.
  const madd::Pslg domain = channel_domain();
  madd::MeshOptions o = field_options(2);
  o.decomposition.subdomains = 16;
  const madd::Decomposition d = madd::discretise(madd::decompose(domain, o.decomposition), domain, o.size);
  const madd::detail::AreaBound bound(o.size, &domain);
  std::size_t pieces = 0, probes = 0, encroachable = 0;
  for (std::uint32_t j = 0; j < d.segments.size(); ++j) {
    if (!d.is_separator(j)) continue;
    ++pieces;
    const madd::Point a = d.points[d.segments[j].a], b = d.points[d.segments[j].b];
    const double length = madd::distance(a, b);
    const madd::Point m = madd::midpoint(a, b), along = (1.0 / length) * (b - a), across{-along.y, along.x};
    for (int i = -4; i <= 4; ++i)
      for (int k = -4; k <= 4; ++k) {
        const madd::Point c = m + (0.3 * i * length) * along + (0.3 * k * length) * across;
        if (madd::distance(c, m) > 1.21 * length || c.x <= 0 || c.y <= 0 || c.y >= 10 ||
            (c.x >= 10 && (c.y <= 4.875 || c.y >= 5.125)) || c.x >= 18)
          continue;
        ++probes;
        encroachable += length > 1.2408 * std::sqrt(bound.area_at(c));
      }
  }
  MESSAGE(pieces, " separator pieces, ", probes, " centroids");
  REQUIRE(pieces > 50);
  CHECK(encroachable == 0);
}

TEST_CASE("the work integral's weights are the same on one thread and on two (chunks concatenated in order)") {
  // A sea of 30 x 30 islands: the domain's triangulation has several
  // chunks' worth of triangles (mesh/work.cpp), and far fewer pieces than the
  // integral's cap of 2^21, past which one thread runs it.
  madd::Pslg sea;
  const auto ring = [&](std::vector<madd::Point> corners) {
    const auto first = static_cast<std::uint32_t>(sea.points.size());
    for (std::uint32_t k = 0; k < corners.size(); ++k) {
      sea.points.push_back(corners[k]);
      sea.segments.push_back({first + k, first + (k + 1) % static_cast<std::uint32_t>(corners.size()), 1});
    }
  };
  ring({{0, 0}, {31, 0}, {31, 31}, {0, 31}});
  for (int i = 1; i <= 30; ++i)
    for (int j = 1; j <= 30; ++j) {
      const double x = i + 0.1 * std::sin(i * j), y = j + 0.1 * std::cos(i + j);
      ring({{x - 0.2, y - 0.2}, {x + 0.2, y - 0.2}, {x + 0.2, y + 0.2}, {x - 0.2, y + 0.2}});
      sea.holes.push_back({x, y});
    }
  madd::MeshOptions o = field_options(1);
  o.size.min_edge_length = 0.1;
  o.size.max_edge_length = 1.0;
  o.size.cells_across = 0;
  o.size.coast_markers = {};
  const madd::detail::AreaBound bound(o.size, &sea);
  const madd::detail::DomainWork work(sea, bound);
  REQUIRE(work.triangulation.triangles.size() > 2 * 2048);
  madd::DecomposeOptions one = o.decomposition, two = o.decomposition;
  one.threads = 1;
  two.threads = 2;
  madd::detail::weigh_by_work(one, work);
  madd::detail::weigh_by_work(two, work);
  REQUIRE(one.weight_samples.size() > 100);
  CHECK(one.weight_samples == two.weight_samples);
}

TEST_CASE("the same mesh on one thread and on three") {
  const madd::Mesh one = madd::mesh(channel_domain(), field_options(1));
  const madd::Mesh three = madd::mesh(channel_domain(), field_options(3));
  CHECK(one.points == three.points);
  CHECK(one.triangles == three.triangles);
}
}

TEST_SUITE("balance by the work the field makes") {
TEST_CASE("every piece of boundary and separator the decoupling makes is counted, on domains outside the fit") {
  // docs/mesh.md, "Balance by work": under a varying bound each piece adds
  // a - b l^2 / A triangles to the interior's integral, its constants fitted
  // on nine real coastlines. The bundled estuary (islands, a river) and pipe
  // (nine holes) were not in the fit: under the built-in field at N = 16
  // each subdomain's estimate is within 6% of its count (the coast's layer
  // alone, separators adding none, missed the estuary's by 11% and the
  // pipe's total by 5%).
  for (const std::string name : {"estuary.poly", "pipe.poly"}) {
    CAPTURE(name);
    const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name);
    double x0 = domain.points[0].x, x1 = x0, y0 = domain.points[0].y, y1 = y0;
    for (const madd::Point p : domain.points)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const double extent = std::max(x1 - x0, y1 - y0);
    madd::MeshOptions o;
    o.decomposition.subdomains = 16;
    o.decomposition.threads = 2;
    o.size.min_triangle_angle_deg = 30;
    o.size.min_edge_length = extent / 400;
    o.size.max_edge_length = extent / 20;
    o.size.distance_rate = 0.15;
    o.size.cells_across = 3;
    o.size.size_gradation = 0.2;
    const madd::MeshRun run = madd::mesh_with_report(domain, o);
    const madd::Mesh& m = run.mesh;
    REQUIRE(run.report.expected_triangles.size() == m.subdomain_count());
    double predicted = 0, error = 0;
    for (std::uint32_t k = 0; k < m.subdomain_count(); ++k) {
      const double actual = m.subdomain_first_triangle[k + 1] - m.subdomain_first_triangle[k];
      CAPTURE(k);
      CHECK(std::abs(run.report.expected_triangles[k] / actual - 1.0) < 0.06);
      predicted += run.report.expected_triangles[k];
      error += std::abs(run.report.expected_triangles[k] / actual - 1.0);
    }
    CHECK(error / m.subdomain_count() < 0.025);
    CHECK(std::abs(predicted / static_cast<double>(m.triangles.size()) - 1.0) < 0.02);
  }
}

TEST_CASE("the predicted triangles of the whole mesh and of each subdomain are near the actual counts") {
  // docs/mesh.md, "Balance by work": the integral of 1 / (kappa A) over each
  // subdomain, and each piece of boundary and separator. Within 3% in all and
  // 10% per subdomain here (the real coastlines' totals: within 3%).
  madd::MeshOptions o = field_options(2);
  o.decomposition.subdomains = 8;
  const madd::MeshRun run = madd::mesh_with_report(channel_domain(), o);
  const madd::Mesh& m = run.mesh;
  REQUIRE(run.report.expected_triangles.size() == m.subdomain_count());
  double predicted = 0;
  for (std::uint32_t k = 0; k < m.subdomain_count(); ++k) {
    const double actual = m.subdomain_first_triangle[k + 1] - m.subdomain_first_triangle[k];
    CAPTURE(k);
    CHECK(run.report.expected_triangles[k] > 0.9 * actual);
    CHECK(run.report.expected_triangles[k] < 1.1 * actual);
    predicted += run.report.expected_triangles[k];
  }
  CHECK(predicted > 0.97 * static_cast<double>(m.triangles.size()));
  CHECK(predicted < 1.03 * static_cast<double>(m.triangles.size()));
}
}

TEST_SUITE("balance by the work the field makes") {
TEST_CASE("a face's pieces are cut as the decoupling cuts them: short near a feature, each counted") {
  // A 10 x 10 face whose east side is a separator (marker 0), at sides of
  // about 0.15, with and without an islet 0.05 from that separator. The
  // decoupling cuts the separator to half its distance from the islet
  // there, graded out from it, and each short piece stands its row of
  // triangles: the islet costs far more than its own perimeter would if
  // counted by length alone (0.5 of it at sides of 0.15: a few triangles).
  const auto face = [](bool islet) {
    madd::Pslg f;
    f.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    f.segments = {{0, 1, 1}, {1, 2, 0}, {2, 3, 1}, {3, 0, 1}};
    if (islet) {
      f.points.insert(f.points.end(), {{9.9, 4.9}, {9.9, 5.1}, {9.95, 5.1}, {9.95, 4.9}});
      for (std::uint32_t i = 0; i < 4; ++i) f.segments.push_back({4 + i, 4 + (i + 1) % 4, 2});
      f.holes = {{9.925, 5.0}};
    }
    return f;
  };
  madd::MeshSizeOptions size;
  size.triangle_area_function = [](double, double) { return 0.01; };
  const madd::detail::AreaBound bound(size);
  const double plain = madd::detail::face_pieces_layer(face(false), bound);
  const double with_islet = madd::detail::face_pieces_layer(face(true), bound);
  CHECK(std::isfinite(plain));
  CHECK(with_islet - plain > 12.0);
  MESSAGE("face pieces' layer: plain ", plain, ", with the islet ", with_islet);

  // And the estimate, which reads it, against the mesh of that face alone.
  madd::MeshOptions o;
  o.decomposition.subdomains = 1;
  o.size = size;
  o.size.min_triangle_angle_deg = 30;
  const madd::Pslg domain = face(true);
  const madd::MeshRun run = madd::mesh_with_report(domain, o);
  const madd::detail::DomainWork work(domain, bound);
  const double estimate = madd::detail::expected_triangles_of_face(domain, work);
  CHECK(estimate > 0.95 * static_cast<double>(run.mesh.triangles.size()));
  CHECK(estimate < 1.05 * static_cast<double>(run.mesh.triangles.size()));
}

TEST_CASE("narrow gap: a channel far narrower than the bound costs what refinement makes of it, a wedge does not") {
  // A 10 x 10 basin and a channel 0.01 wide and 8 long; the bound (a size
  // function, so the estimate integrates) asks for triangles of side ~0.3
  // everywhere. Refinement fills the channel at about gap_edge_fraction x
  // its width whatever the bound; the estimate must count that.
  madd::Pslg d;
  const double w = 0.01;
  d.points = {{0, 0}, {10, 0}, {10, 5 - w / 2}, {18, 5 - w / 2}, {18, 5 + w / 2}, {10, 5 + w / 2}, {10, 10}, {0, 10}};
  for (std::uint32_t i = 0; i < 8; ++i) d.segments.push_back({i, (i + 1) % 8, 1});
  const madd::detail::NarrowGaps gaps(d);
  const double bound = 0.04;
  const double in_gap = madd::detail::area_of_edge(madd::detail::gap_edge_fraction * w);
  CHECK(gaps.area_at({12, 5}, bound) == doctest::Approx(in_gap).epsilon(1e-6));
  CHECK(gaps.area_at({12, 5 + w / 4}, bound) == doctest::Approx(in_gap).epsilon(1e-6));
  CHECK(gaps.area_at({5, 5}, bound) == bound);             // the basin: wider than the bound's triangles
  CHECK(gaps.area_at({12, 5}, in_gap / 2) == in_gap / 2);  // a finer bound binds first
  // The wedge between the basin's south side and the channel's: they meet
  // at (10, 4.995) at 90 degrees, and near that corner the chord from one
  // side ends on the other. Not a gap.
  CHECK(gaps.area_at({9.999, 4.994}, bound) == bound);

  // Under a size function (the estimate integrates) and under one bound
  // everywhere (the estimate counts the interior by area and adds the gaps).
  for (const bool uniform : {false, true}) {
    CAPTURE(uniform);
    madd::MeshOptions o;
    o.decomposition.subdomains = 2;
    o.decomposition.threads = 2;
    o.size.min_triangle_angle_deg = 30;
    if (uniform) o.size.max_triangle_area = 0.04;
    else o.size.triangle_area_function = [](double x, double) { return 0.04 * (1.0 + 0.01 * x); };
    const madd::MeshRun run = madd::mesh_with_report(d, o);
    const madd::Mesh& m = run.mesh;
    // The channel's triangles alone, counted from the outside, against the
    // estimate's share for it: the integral over the channel of 1 / (kappa A)
    // with A the gap's area.
    std::size_t channel = 0;
    for (const auto& t : m.triangles) {
      const double cx = (m.points[t[0]].x + m.points[t[1]].x + m.points[t[2]].x) / 3;
      channel += cx > 10;
    }
    double predicted = 0;
    for (const double t : run.report.expected_triangles) predicted += t;
    const auto total = static_cast<double>(m.triangles.size());
    // The channel is a fifth of the mesh (the bound alone gives it a few
    // triangles): an estimate blind to it is 20% short.
    CHECK(static_cast<double>(channel) > 0.2 * total);
    CHECK(predicted > 0.9 * total);
    CHECK(predicted < 1.1 * total);
  }
}

TEST_CASE("a narrow gap's excess is spread along it, never one point a separator cannot split") {
  // The Seto Inland Sea's needle (docs/mesh.md, "Balance by work"; its
  // vertices 1807-1809, moved to the origin): a triangle 1.8 long, 0.0026
  // wide at its base, its domain triangulation that one sliver; under one
  // bound of side ~0.37 the gap's excess over the area term is thousands of
  // triangles. Placed at the sliver's centroid as one sample it made the
  // subdomain holding it 1.44 x the mean at N = 256.
  madd::Pslg d;
  d.points = {{0, 0}, {1.750882, 0.01112}, {-0.074564, 0.002224}};
  for (std::uint32_t i = 0; i < 3; ++i) d.segments.push_back({i, (i + 1) % 3, 1});
  madd::MeshSizeOptions size;
  size.min_triangle_angle_deg = 30;
  size.max_triangle_area = 0.06;
  const madd::detail::AreaBound bound(size, &d);
  REQUIRE(bound.uniform());
  const madd::detail::DomainWork work(d, bound);
  REQUIRE(work.triangulation.triangles.size() == 1);
  double total = 0, largest = 0, lo_x = 2, hi_x = -1;
  for (const madd::ValuedPoint& p : work.excess) {
    CHECK(p.value > 0);
    // Strictly inside the sliver (counter-clockwise).
    for (std::uint32_t i = 0; i < 3; ++i) CHECK(madd::orient2d(d.points[i], d.points[(i + 1) % 3], p.at) > 0);
    total += p.value;
    largest = std::max(largest, p.value);
    lo_x = std::min(lo_x, p.at.x);
    hi_x = std::max(hi_x, p.at.x);
  }
  // Hundreds of triangles or more, along most of the sliver, no sample a
  // tenth of them.
  CHECK(total > 1000);
  CHECK(largest < 0.1 * total);
  CHECK(lo_x < 0.3);
  CHECK(hi_x > 1.4);
  // And the whole is what refinement makes of the needle (within 25%).
  madd::MeshOptions o;
  o.decomposition.subdomains = 1;
  o.size = size;
  const madd::MeshRun run = madd::mesh_with_report(d, o);
  const auto actual = static_cast<double>(run.mesh.triangles.size());
  CHECK(run.report.expected_triangles[0] > 0.75 * actual);
  CHECK(run.report.expected_triangles[0] < 1.25 * actual);
}

TEST_CASE("under one bound, no merged work sample weighs more than a sixteenth of a mean subdomain") {
  // A 50 x 50 basin with the needle above on its east side: its excess is
  // 4% of the work, 2.7 mean subdomains at N = 64, inside two cells of the
  // samples' 64 x 64 grid.
  madd::Pslg d;
  d.points = {{0, 0}, {50, 0}, {50, 25}, {51.750882, 25.01112}, {50, 25.0026}, {50, 50}, {0, 50}};
  for (std::uint32_t i = 0; i < 7; ++i) d.segments.push_back({i, (i + 1) % 7, 1});
  madd::MeshSizeOptions size;
  size.min_triangle_angle_deg = 30;
  size.max_triangle_area = 0.06;
  const madd::detail::AreaBound bound(size, &d);
  const madd::detail::DomainWork work(d, bound);
  double excess = 0;
  for (const madd::ValuedPoint& p : work.excess) excess += p.value;
  const double triangles = 2500 / (0.645 * 0.06);
  REQUIRE(excess > 0.02 * triangles);
  madd::DecomposeOptions o;
  o.subdomains = 64;
  madd::detail::weigh_by_work(o, work);
  REQUIRE(o.weight_samples.size() > 0);
  // The weights are in units of area (kappa A a triangle) beside the area itself.
  double total = 2500 + 0.0026 * 1.75 / 2, largest = 0;
  for (const madd::ValuedPoint& p : o.weight_samples) {
    total += p.value;
    largest = std::max(largest, p.value);
  }
  CHECK(largest <= total / (16 * 64) * (1 + 1e-9));
}

TEST_CASE("pinch: two islands all but touching at a corner cost a cluster the estimate counts") {
  // A 10 x 10 basin with two square islands whose corners are 0.0005 apart
  // at (5, 5), diagonally (the banks open at 90 degrees: no narrow gap sees
  // them), meshed at sides of about 0.6: refinement grades from the pinch
  // outwards, a quarter of the mesh, which the area and the boundary layer
  // miss (the estimate without the pinch term: 0.75 of the count).
  madd::Pslg d;
  const double e = 0.00025;
  d.points = {{0, 0},         {10, 0},    {10, 10},       {0, 10},      // the basin
              {3, 3},         {3, 5 - e}, {5 - e, 5 - e}, {5 - e, 3},   // island south-west, clockwise
              {5 + e, 5 + e}, {5 + e, 7}, {7, 7},         {7, 5 + e}};  // island north-east, clockwise
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({4 + i, 4 + (i + 1) % 4, 2});
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({8 + i, 8 + (i + 1) % 4, 3});
  d.holes = {{4, 4}, {6, 6}};
  const madd::detail::NarrowGaps gaps(d);
  CHECK(gaps.area_at({5 - 2 * e, 5}, 0.16) == 0.16);  // no chord across: not a gap
  madd::MeshOptions o;
  o.decomposition.subdomains = 1;
  o.size.min_triangle_angle_deg = 30;
  o.size.max_triangle_area = 0.16;
  const madd::MeshRun run = madd::mesh_with_report(d, o);
  const madd::Mesh& m = run.mesh;
  // The triangles within 0.6 of the pinch, counted from the outside, against
  // what their area would hold at the bound's mean triangle: the cluster.
  std::size_t near = 0;
  double near_area = 0;
  for (const auto& t : m.triangles) {
    const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    const madd::Point g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    if (std::hypot(g.x - 5, g.y - 5) > 0.6) continue;
    ++near;
    near_area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
  }
  const double cluster = static_cast<double>(near) - near_area / (0.645 * 0.16);
  CHECK(cluster > 200);
  // The estimate counts it: within 5% of the whole mesh, of which the
  // cluster alone is more than a fifth.
  const auto total = static_cast<double>(m.triangles.size());
  CHECK(cluster > 0.2 * total);
  const double predicted = run.report.expected_triangles.at(0);
  CHECK(predicted > 0.95 * total);
  CHECK(predicted < 1.05 * total);

  // Under a varying bound (the estimate integrates it) the cluster is
  // there all the same, and counted (without the pinch term: 0.8 of the count).
  madd::MeshOptions graded = o;
  graded.size.max_triangle_area = 0;
  graded.size.triangle_area_function = [](double x, double) { return 0.16 * (1.0 + 0.02 * x); };
  const madd::MeshRun graded_run = madd::mesh_with_report(d, graded);
  const auto graded_total = static_cast<double>(graded_run.mesh.triangles.size());
  CHECK(graded_run.report.expected_triangles.at(0) > 0.95 * graded_total);
  CHECK(graded_run.report.expected_triangles.at(0) < 1.05 * graded_total);
}

TEST_CASE("pinch: its cluster is shared out around the vertex, as refinement makes it") {
  // A spike rises from the basin's south side to within 0.0005 of a square
  // island's flat south side: one pinch vertex, the spike's tip, whose gap
  // is to a segment. Refinement grades out from the tip on both sides of
  // the vertical through it; a separator from the tip (where the domain is
  // narrowest, the medial axis puts one) divides the cluster. The estimate's
  // samples must be divided alike: once they were one sample towards one
  // triangle at the tip, all on one side.
  madd::Pslg d;
  const double e = 0.0005;
  d.points = {{0, 0}, {4.8, 0}, {5, 5 - e}, {5.2, 0}, {10, 0}, {10, 10}, {0, 10},  // basin with the spike
              {4, 5}, {4, 7},   {6, 7},     {6, 5}};                               // island, clockwise
  for (std::uint32_t i = 0; i < 7; ++i) d.segments.push_back({i, (i + 1) % 7, 1});
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({7 + i, 7 + (i + 1) % 4, 2});
  d.holes = {{5, 6}};
  const madd::Point tip = d.points[2];
  const auto near_tip = [&](madd::Point p) { return std::hypot(p.x - tip.x, p.y - tip.y) < 0.6; };
  for (const bool graded : {false, true}) {
    CAPTURE(graded);
    madd::MeshSizeOptions size;
    size.min_triangle_angle_deg = 30;
    if (graded) size.triangle_area_function = [](double x, double) { return 0.16 * (1.0 + 0.02 * x); };
    else size.max_triangle_area = 0.16;
    const madd::detail::AreaBound bound(size, &d);
    const madd::detail::DomainWork work(d, bound);
    double west = 0, east = 0;
    for (const madd::ValuedPoint& p : work.excess) {
      // In the water: neither in the island nor in the spike.
      CHECK_FALSE((p.at.x > 4 && p.at.x < 6 && p.at.y > 5 && p.at.y < 7));
      CHECK_FALSE((madd::orient2d(d.points[1], d.points[3], p.at) > 0 &&
                   madd::orient2d(d.points[3], d.points[2], p.at) > 0 &&
                   madd::orient2d(d.points[2], d.points[1], p.at) > 0));
      if (!near_tip(p.at)) continue;
      (p.at.x < tip.x ? west : east) += p.value;
    }
    // The cluster is worth counting (some doublings of 0.0005 up to ~0.6).
    REQUIRE(west + east > 50);
    CHECK(west > 0.3 * (west + east));
    CHECK(east > 0.3 * (west + east));
  }
  // ... as the mesh has it: the triangles near the tip beyond what their
  // area holds at the bound's mean triangle, on each side.
  madd::MeshOptions o;
  o.decomposition.subdomains = 1;
  o.size.min_triangle_angle_deg = 30;
  o.size.max_triangle_area = 0.16;
  const madd::Mesh m = madd::mesh(d, o);
  double side_count[2] = {0, 0}, side_area[2] = {0, 0};
  for (const auto& t : m.triangles) {
    const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
    const madd::Point g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    if (!near_tip(g)) continue;
    const int k = g.x < tip.x ? 0 : 1;
    side_count[k] += 1;
    side_area[k] += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
  }
  const double west = side_count[0] - side_area[0] / (0.645 * 0.16);
  const double east = side_count[1] - side_area[1] / (0.645 * 0.16);
  REQUIRE(west + east > 50);
  CHECK(west > 0.3 * (west + east));
  CHECK(east > 0.3 * (west + east));
}

TEST_CASE("pinch: a few of them tip a subdomain unless the decomposition weighs the work") {
  // A 60 x 60 basin meshed at sides of about 0.3 (140,000 triangles): its
  // boundary layer and the pinches together are under the 2% of the work
  // where the decomposition keeps the areas; but four pairs of small islands
  // pinch together near its south-west corner (corners 0.0005 apart, as on a
  // rasterised shore), some 1,400 triangles in one place, more than half a
  // subdomain's share at N = 64: by area the subdomain holding them had
  // 1.38 x the mean, 1.09 when the decomposition weighs the work.
  madd::Pslg d;
  d.points = {{0, 0}, {60, 0}, {60, 60}, {0, 60}};
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  const double e = 0.00025, s = 0.5;
  const auto island = [&](double x0, double y0, double x1, double y1) {  // clockwise
    const auto first = static_cast<std::uint32_t>(d.points.size());
    d.points.insert(d.points.end(), {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}});
    for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({first + i, first + (i + 1) % 4, 2});
    d.holes.push_back({(x0 + x1) / 2, (y0 + y1) / 2});
  };
  for (const double cx : {5.0, 6.5})  // the pinches, at (cx, cy)
    for (const double cy : {5.0, 6.5}) {
      island(cx - s, cy - s, cx - e, cy - e);
      island(cx + e, cy + e, cx + s, cy + s);
    }
  madd::MeshOptions o;
  const std::uint32_t n = 64;
  o.decomposition.subdomains = n;
  o.decomposition.threads = 2;
  o.size.min_triangle_angle_deg = 30;
  o.size.max_triangle_area = 0.04;
  const madd::Mesh m = madd::mesh(d, o);
  double largest = 0;
  for (std::uint32_t k = 0; k < n; ++k)
    largest = std::max(largest, static_cast<double>(m.subdomain_first_triangle[k + 1] - m.subdomain_first_triangle[k]));
  CHECK(largest / (static_cast<double>(m.triangles.size()) / n) < 1.2);
}

TEST_CASE("small features: a coast of short segments, or a small bump on a straight one, is counted") {
  // Refinement grades down to the input's small features (Ruppert's local
  // feature size). A zigzag of teeth 0.02 wide (segments 0.028 long, a tenth
  // of the bound's edge) made 5,513 triangles where the boundary layer by
  // length alone expected 4,088 (0.74); four bumps 0.005 wide on a straight
  // side made 4,569 against 4,072 (0.89); a plain side 3,908 against 4,072
  // (1.04).
  std::vector<madd::Point> zigzag;
  for (int i = 0; i <= 500; ++i) zigzag.push_back({i * 0.02, i % 2 == 0 ? 0.0 : 0.02});
  const double teeth = estimate_over_count(zigzag);
  CHECK(teeth > 0.95);
  CHECK(teeth < 1.05);
  std::vector<madd::Point> bumps{{0, 0}};
  const double w = 0.005;
  for (int k = 1; k <= 4; ++k)
    bumps.insert(bumps.end(), {{2.0 * k - w / 2, 0}, {2.0 * k, w / 2}, {2.0 * k + w / 2, 0}});
  bumps.push_back({10, 0});
  const double bump = estimate_over_count(bumps);
  CHECK(bump > 0.95);
  CHECK(bump < 1.05);
  const double plain = estimate_over_count({{0, 0}, {10, 0}});
  CHECK(plain > 0.98);
  CHECK(plain < 1.02);
}

TEST_CASE("small features: the excess is the same on one thread and on two (chunks joined in order)") {
  // A basin whose south side zigzags in 2,000 teeth: its triangulation has
  // more triangles than one chunk of the pass (2,048).
  madd::Pslg d;
  for (int i = 0; i <= 4000; ++i) d.points.push_back({i * 0.0025, i % 2 == 0 ? 0.0 : 0.0025});
  d.points.insert(d.points.end(), {{10, 10}, {0, 10}});
  const auto n = static_cast<std::uint32_t>(d.points.size());
  for (std::uint32_t i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n, 1});
  madd::MeshSizeOptions size;
  size.max_triangle_area = 0.04;
  const madd::detail::AreaBound bound(size, &d);
  const madd::detail::DomainWork one(d, bound, 1), two(d, bound, 2);
  REQUIRE(one.triangulation.triangles.size() > 2048);
  REQUIRE(one.excess.size() > 1000);
  REQUIRE(one.excess.size() == two.excess.size());
  for (std::size_t i = 0; i < one.excess.size(); ++i) {
    CHECK(one.excess[i].at == two.excess[i].at);
    CHECK(one.excess[i].value == two.excess[i].value);
  }
}

TEST_CASE("small features: a vertex on a segment not its own has no feature size of 0") {
  // The fuzz finding of issue 26 (vertex 5 on segment 1, a valid domain:
  // refinement splits the segment there). Its distance to a feature not
  // incident to it is 0, which as a feature size made a hole of work at it:
  // 2,046 triangles expected, 1,719 made, the largest of 4 subdomains 1.23 x
  // the mean.
  madd::Pslg d;
  d.points = {{0, 0}, {1.2, 0}, {1, 1}, {0, 1}, {1, 0}};
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  madd::MeshOptions o;
  o.decomposition.subdomains = 4;
  o.size.min_triangle_angle_deg = 30;
  o.size.max_triangle_area = 0.001;
  const madd::MeshRun run = madd::mesh_with_report(d, o);
  double predicted = 0;
  for (const double t : run.report.expected_triangles) predicted += t;
  const auto made = static_cast<double>(run.mesh.triangles.size());
  CHECK(predicted > 0.95 * made);
  CHECK(predicted < 1.05 * made);
}

TEST_CASE("narrow gap: a needle of water under 3 degrees is a gap, a wider wedge is not") {
  // A basin with two spikes of water to the east: a needle 1.15 degrees wide
  // and a wedge of 33 degrees, each 10 long.
  madd::Pslg d;
  d.points = {{0, 0}, {10, 0}, {10, 4.9}, {20, 5}, {10, 5.1}, {10, 7}, {20, 10}, {10, 13}, {10, 20}, {0, 20}};
  for (std::uint32_t i = 0; i < 10; ++i) d.segments.push_back({i, (i + 1) % 10, 1});
  const madd::detail::NarrowGaps gaps(d);
  const double bound = 0.04;  // sides of 0.3
  // Halfway along the needle the water is 0.1 wide.
  CHECK(gaps.area_at({15, 5}, bound) < bound / 3);  // sides of about 1.6 x 0.1
  // Near the wedge's tip it is 0.06 wide, but refinement leaves the angle be.
  CHECK(gaps.area_at({19.9, 10}, bound) == bound);
}
}

TEST_CASE("depth rules: every triangle within the M2 wavelength's and the slope's edge at its centroid") {
  // A 40 km square sea whose depth grows linearly eastwards, 5 m to 25 m:
  // h_w = T sqrt(g d) / 80 runs from 1.25 to 2.75 km (below hmax 20 km; at
  // 40 cells the mesh was 100 triangles in 4 subdomains, too few for the
  // work estimate the decomposition balances), and
  // the slope's 2 pi d / (K |grad d|) with |grad d| = 1/2000 from 1.6 to 7.9
  // km at K 40. sqrt is concave and the slope term linear in d, so the
  // background's linear reading of either lies below it: the raw rule at
  // a triangle's centroid bounds it.
  madd::Pslg sea;
  sea.points = {{0, 0}, {40000, 0}, {40000, 40000}, {0, 40000}};
  for (std::uint32_t i = 0; i < 4; ++i) sea.segments.push_back({i, (i + 1) % 4, 1});
  const auto depth = [](double x, double) { return 5.0 + x / 2000.0; };
  for (const bool slope : {false, true}) {
    CAPTURE(slope);
    madd::MeshOptions o;
    o.decomposition.subdomains = 4;
    o.decomposition.threads = 2;
    o.size.min_edge_length = 500;
    o.size.max_edge_length = 20000;
    o.size.depth = depth;
    o.size.depth_gradient = [](double, double) { return madd::Point{1.0 / 2000.0, 0.0}; };
    (slope ? o.size.slope_cells : o.size.wavelength_cells) = slope ? 40 : 80;
    const madd::Mesh m = madd::mesh(sea, o);
    std::size_t near_bound = 0;
    for (const auto& t : m.triangles) {
      const madd::Point a = m.points[t[0]], b = m.points[t[1]], c = m.points[t[2]];
      const madd::Point g = madd::triangle_centroid(a, b, c);
      const double d = depth(g.x, g.y);
      const double h = slope ? madd::slope_edge(d, 1.0 / 2000.0, 40) : madd::wavelength_edge(d, 80);
      const double bound = std::sqrt(3.0) / 4.0 * h * h;
      REQUIRE(madd::triangle_area(a, b, c) <= bound * (1 + 1e-12));
      near_bound += madd::triangle_area(a, b, c) > 0.25 * bound ? 1 : 0;
    }
    MESSAGE(m.triangles.size(), " ", m.subdomain_first_triangle[1], " ", m.subdomain_first_triangle[2], " ",
            m.subdomain_first_triangle[3]);
    CHECK(near_bound > m.triangles.size() / 4);  // the rule is what sizes the mesh, not hmin
  }
  // Without a depth the rules are an option error.
  madd::MeshOptions bad;
  bad.size.wavelength_cells = 40;
  CHECK_THROWS_AS(madd::check_options(bad), madd::OptionError);
}
