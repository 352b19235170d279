// The figures of a mesh (madd/mesh_metrics.hpp) against the mesh itself, and
// their report (format_mesh_report_json).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_metrics.hpp"
#include "madd/mesh_output.hpp"
#include "madd/poly_io.hpp"
#include "mesh_fixtures.hpp"

namespace {

// Each triangle's smallest angle, the plain way: the least of its three corners.
std::vector<double> smallest_angles(const madd::Mesh& m) {
  std::vector<double> out;
  for (const auto& t : m.triangles) {
    double s = 180;
    for (int i = 0; i < 3; ++i)
      s = std::min(s,
                   madd::degrees(madd::angle_at(m.points[t[i]], m.points[t[(i + 1) % 3]], m.points[t[(i + 2) % 3]])));
    out.push_back(s);
  }
  return out;
}

// The position of `key` as a member of the JSON text, or npos.
std::size_t member(const std::string& json, const std::string& key) {
  std::string start = "\n  \"";
  start += key;
  start += "\": ";
  return json.find(start);
}

}  // namespace

TEST_SUITE("mesh_metrics") {

TEST_CASE("mesh_metrics: the counts, extremes and balance of the mesh's triangles") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  const madd::MeshOptions o = madd::test::options_for(12, 33, madd::domain_area(domain) / 3000);
  const madd::Mesh mesh = madd::mesh(domain, o);
  const madd::MeshMetrics m = madd::mesh_metrics(mesh, o.size);
  REQUIRE(m.triangles == mesh.triangles.size());
  CHECK(m.vertices == mesh.points.size());
  CHECK(m.subdomains == 12);
  CHECK(m.min_angle_bound_deg == 33);
  CHECK(m.max_area_bound == o.size.max_triangle_area);

  std::vector<double> angles = smallest_angles(mesh);
  std::sort(angles.begin(), angles.end());
  CHECK(m.smallest_angle_deg == doctest::Approx(angles.front()).epsilon(1e-12));
  CHECK(m.median_smallest_angle_deg == doctest::Approx(angles[angles.size() / 2]).epsilon(1e-12));
  // Every triangle in one bin, each bin holding the triangles of its ten degrees.
  CHECK(std::accumulate(m.smallest_angle_histogram.begin(), m.smallest_angle_histogram.end(), std::uint64_t{0}) ==
        m.triangles);
  const auto in_bin = [&](int b) {
    return std::count_if(angles.begin(), angles.end(),
                         [&](double a) { return std::min(5, static_cast<int>(a / 10)) == b; });
  };
  for (int b = 0; b < 6; ++b)
    CHECK(m.smallest_angle_histogram[static_cast<std::size_t>(b)] == static_cast<std::uint64_t>(in_bin(b)));
  // verify_mesh accepts the mesh only when its shortfall counts exactly the triangles below the bound.
  CHECK(m.below_bound == mesh.shortfall.total());
  CHECK(m.shortfall == mesh.shortfall);
  CHECK(m.share_below_bound() ==
        doctest::Approx(static_cast<double>(m.below_bound) / static_cast<double>(m.triangles)));

  std::vector<std::uint64_t> per_subdomain(m.subdomains, 0);
  for (const std::uint32_t k : mesh.triangle_subdomain) ++per_subdomain[k];
  CHECK(m.largest_subdomain_triangles == *std::max_element(per_subdomain.begin(), per_subdomain.end()));
  CHECK(m.max_over_mean_triangles() >= 1.0);
  CHECK(m.max_over_mean_triangles() == doctest::Approx(static_cast<double>(m.largest_subdomain_triangles) *
                                                       m.subdomains / static_cast<double>(m.triangles)));
}

TEST_CASE("mesh_metrics: the same figures on 1, 2 and 3 threads") {
  // The angles are measured in chunks of 16,384 triangles: a mesh of several.
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/estuary.poly");
  const madd::MeshOptions o = madd::test::options_for(12, 33, madd::domain_area(domain) / 20000);
  const madd::Mesh mesh = madd::mesh(domain, o);
  REQUIRE(mesh.triangles.size() > 2 * 16384);
  const madd::MeshMetrics one = madd::mesh_metrics(mesh, o.size, 1);
  for (const unsigned threads : {2u, 3u}) CHECK(madd::mesh_metrics(mesh, o.size, threads) == one);
}

TEST_CASE("mesh_metrics: the median and the bins of random triangles, many of them alike, by brute force") {
  // The median is selected from the angles of one fine bin (1/1024 degree):
  // random triangles and, as many, near-copies of one right isosceles
  // triangle whose smallest angles differ by less than a bin (some exactly
  // alike), so that the median falls among them; odd and even counts, 1, 2
  // and 3 threads.
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (const std::size_t count :
       {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{30001}, std::size_t{30002}}) {
    madd::Mesh mesh;
    mesh.min_triangle_angle_deg = 20;
    for (std::size_t t = 0; t < count; ++t) {
      const auto first = static_cast<std::uint32_t>(mesh.points.size());
      if (t % 2 == 0) {
        const double lift = 1e-6 * static_cast<double>(random() % 1000);
        mesh.points.insert(mesh.points.end(), {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0 + lift}});
      } else {
        for (int i = 0; i < 3; ++i) mesh.points.push_back({coordinate(random), coordinate(random)});
      }
      // Counter-clockwise or not does not matter to an angle.
      mesh.triangles.push_back({first, first + 1, first + 2});
    }
    mesh.subdomain_first_triangle = {0, static_cast<std::uint32_t>(count)};
    std::vector<double> angles = smallest_angles(mesh);
    std::sort(angles.begin(), angles.end());
    for (const unsigned threads : {1u, 2u, 3u}) {
      CAPTURE(count);
      CAPTURE(threads);
      const madd::MeshMetrics m = madd::mesh_metrics(mesh, {}, threads);
      CHECK(m.median_smallest_angle_deg == doctest::Approx(angles[count / 2]).epsilon(1e-12));
      CHECK(m.smallest_angle_deg == doctest::Approx(angles.front()).epsilon(1e-12));
      const auto below =
          static_cast<std::uint64_t>(std::lower_bound(angles.begin(), angles.end(), 20.0 - 1e-6) - angles.begin());
      CHECK(m.below_bound == below);
    }
  }
}

TEST_CASE("mesh_metrics of an empty mesh: no triangle, no ratio") {
  const madd::MeshMetrics m = madd::mesh_metrics(madd::Mesh{});
  CHECK(m.triangles == 0);
  CHECK(m.share_below_bound() == 0.0);
  CHECK(m.max_over_mean_triangles() == 0.0);
}

TEST_CASE("format_mesh_report_json: every figure once, then the run's in order; an unknown median is left out") {
  const madd::Pslg domain = madd::read_domain(MADD_DATA_DIR "/key.poly");
  const madd::MeshOptions o = madd::test::options_for(4, 30, 0);
  const madd::MeshRun made = madd::mesh_with_report(domain, o);
  const madd::MeshReport& report = made.report;
  madd::MeshMetrics m = madd::mesh_metrics(made.mesh, o.size);
  std::vector<madd::RunFigure> run = madd::run_figures(report);
  run.push_back({"seconds", 1.5});
  const std::string json = madd::format_mesh_report_json(m, run);
  REQUIRE(json.front() == '{');
  CHECK(json.substr(json.size() - 3) == "\n}\n");
  const char* keys[] = {"subdomains",
                        "triangles",
                        "vertices",
                        "min_angle_bound_deg",
                        "max_area_bound",
                        "smallest_angle_deg",
                        "median_smallest_angle_deg",
                        "below_bound",
                        "share_below_bound",
                        "below_bound_input_angle",
                        "below_bound_separator",
                        "below_bound_precision",
                        "below_bound_limit",
                        "smallest_angle_histogram_10deg",
                        "max_over_mean_triangles",
                        "threads",
                        "thread_imbalance",
                        "thread_seconds",
                        "phase_seconds",
                        "predicted_triangles",
                        "subdomain_predicted_triangles",
                        "seconds"};
  std::size_t previous = 0;
  for (const char* key : keys) {
    CAPTURE(key);
    const std::size_t at = member(json, key);
    REQUIRE(at != std::string::npos);
    CHECK(at > previous);
    CHECK(member(json.substr(at + 1), key) == std::string::npos);  // once
    previous = at;
  }
  CHECK(json.find("\"triangles\": " + std::to_string(made.mesh.triangles.size()) + ",") != std::string::npos);
  CHECK(json.find("\"threads\": " + std::to_string(report.thread_seconds.size()) + ",") != std::string::npos);
  CHECK(json.find("\"seconds\": 1.5\n}") != std::string::npos);
  for (const madd::PhaseTime& p : report.phases) CHECK(json.find("\"" + p.name + "\": ") != std::string::npos);
  // Every number with all its digits: the smallest angle reads back exactly.
  const std::size_t angle = member(json, "smallest_angle_deg") + std::string("\n  \"smallest_angle_deg\": ").size();
  CHECK(std::stod(json.substr(angle)) == m.smallest_angle_deg);

  m.median_smallest_angle_deg = std::numeric_limits<double>::quiet_NaN();
  const std::string parts =
      madd::format_mesh_report_json(m, {{"ranks", 3.0}, {"mesh_seconds", std::vector<double>{1, 2, 3}}});
  CHECK(member(parts, "median_smallest_angle_deg") == std::string::npos);
  CHECK(parts.find("\"mesh_seconds\": [1, 2, 3]\n}") != std::string::npos);
  CHECK(member(parts, "ranks") > member(parts, "max_over_mean_triangles"));
}

}  // TEST_SUITE("mesh_metrics")
