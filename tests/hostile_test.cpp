// Hostile geometry (docs/hostile.md): extreme coordinates, near-degenerate
// shapes, many holes, huge inputs, impossible requests. Each case either gives
// a decomposition that passes verify_decomposition (every new angle >= Phi0)
// or a clear madd::Error of the kind asserted here.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "madd/atomic_write.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/mesh.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "madd/triangulation.hpp"
#include "decomposition_check.hpp"
#include "kernel/resource_limits.hpp"
#include "mesh/discretise.hpp"
#include "quality/area_bound.hpp"

namespace {

using madd::Point;
using madd::Pslg;

Pslg polygon(const std::vector<std::vector<Point>>& rings, const std::vector<Point>& holes = {}) {
  Pslg p;
  p.first_index = 0;
  for (const auto& ring : rings) {
    const auto base = static_cast<std::uint32_t>(p.points.size());
    const auto n = static_cast<std::uint32_t>(ring.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      p.points.push_back(ring[i]);
      p.segments.push_back({base + i, base + (i + 1) % n, 0});
    }
  }
  p.holes = holes;
  return p;
}

std::vector<Point> rectangle(double x0, double y0, double x1, double y1, bool clockwise = false) {
  if (clockwise) return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Decomposes and checks the full contract: verified, N subdomains, min angle.
void expect_valid(const Pslg& domain, std::uint32_t n, double min_angle = 60.0) {
  madd::test::checked_decomposition(domain, n, min_angle);
}

madd::InvalidInputError expect_invalid(const Pslg& domain) {
  try {
    madd::validate(domain);
  } catch (const madd::InvalidInputError& e) {
    return e;
  }
  FAIL("validate accepted the domain");
  return madd::InvalidInputError(madd::InputProblem::other, "");
}

}  // namespace

TEST_SUITE("hostile") {

TEST_CASE("coordinates near 1e-300 and 1e300 are rejected with a clear error, by validate and by decompose") {
  for (const double scale : {1e-300, 1e300}) {
    const Pslg p = polygon({rectangle(1 * scale, 1 * scale, 2 * scale, 2 * scale)});
    const madd::InvalidInputError e = expect_invalid(p);
    CHECK(e.problem() == madd::InputProblem::other);
    CHECK(std::string(e.what()).find("outside the supported range") != std::string::npos);
    CHECK_THROWS_AS(madd::decompose(p, {}), madd::InvalidInputError);
  }
}

TEST_CASE("the supported extremes 1e-39 and 1e69 decompose") {
  for (const double scale : {1e-39, 1e69}) {
    const Pslg p = polygon({rectangle(1 * scale, 1 * scale, 3 * scale, 2 * scale)});
    expect_valid(p, 4);
  }
}

TEST_CASE("all points near (1e9, 1e9), 1e-3 apart") {
  // A 0.1 x 0.06 rectangle whose boundary vertices are 1e-3 apart: relative
  // spacing 1e-12 of the coordinates.
  std::vector<Point> ring;
  const double x0 = 1e9, y0 = 1e9;
  for (int i = 0; i < 100; ++i) ring.push_back({x0 + i * 1e-3, y0});
  for (int i = 0; i < 60; ++i) ring.push_back({x0 + 0.1, y0 + i * 1e-3});
  for (int i = 0; i < 100; ++i) ring.push_back({x0 + 0.1 - i * 1e-3, y0 + 0.06});
  for (int i = 0; i < 60; ++i) ring.push_back({x0, y0 + 0.06 - i * 1e-3});
  expect_valid(polygon({ring}), 8);
}

// Issue 13: a fuzz run found this needle, 1e11 long and 0.02 wide near
// (1e9, 1e9). Triangulation and decomposition were right; both self-checks
// compared floating-point area sums with a fixed relative 1e-9 and failed
// (exit 70). Now both areas are exact sums (docs/hostile.md).
Pslg issue13_needle() {
  return polygon({{{1040000000.0, 100000000030.0},
                   {1000000000.02, 1000000000.0},
                   {1000000000.01, 1000000000.004},
                   {1000000000.006, 1000000000.004},
                   {1000000000.006, 1000000000.008},
                   {1000000000.0, 1000000000.008}}});
}

TEST_CASE("issue 13: a needle 1e11 long and 0.02 wide near (1e9, 1e9) triangulates and decomposes") {
  const Pslg p = issue13_needle();
  madd::validate(p);
  const madd::Triangulation tri = madd::triangulate(p);
  const madd::Verification v = madd::verify_triangulation(tri, &p);
  INFO((v.ok() ? std::string() : v.problems.front()));
  CHECK(v.ok());
  for (const std::uint32_t n : {2u, 3u, 8u, 64u}) expect_valid(p, n);
  expect_valid(p, 8, 89.0);
}

TEST_CASE("sloping sides far from the origin: a unit triangle near (1e9, 1e9) and (1e11, 1e11), a sliver near 1e10") {
  // A vertex interpolated on a sloping side is rounded off it by up to
  // ~1e-7 near 1e9 (1e-5 near 1e11): far more than the former fixed
  // tolerance of 1e-9 sqrt(area), and the slivers it cuts off or adds are
  // more than a relative 1e-9 of a unit area.
  for (const double o : {1e9, 1e11}) {
    const Pslg p = polygon({{{o, o}, {o + 1, o + 0.3}, {o + 0.4, o + 1}}});
    for (const std::uint32_t n : {2u, 8u}) expect_valid(p, n);
  }
  const double o = 1e10, c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const double length = 1000, width = 1e-3;  // aspect ratio 1e6, at 30 degrees
  const Pslg sliver = polygon({{{o, o},
                                {o + length * c, o + length * s},
                                {o + length * c - width * s, o + length * s + width * c},
                                {o - width * s, o + width * c}}});
  for (const std::uint32_t n : {2u, 8u}) expect_valid(sliver, n);
}

TEST_CASE("a hole within 1e-12 of the outer boundary without touching it") {
  const Pslg p = polygon({rectangle(0, 0, 1, 1), rectangle(0.25, 1e-12, 0.75, 0.5, true)}, {{0.5, 0.25}});
  madd::validate(p);
  expect_valid(p, 4);
}

TEST_CASE("two holes within 1e-12 of each other") {
  const Pslg p =
      polygon({rectangle(0, 0, 4, 2), rectangle(1, 0.5, 2, 1.5, true), rectangle(2 + 1e-12, 0.5, 3, 1.5, true)},
              {{1.5, 1}, {2.5, 1}});
  madd::validate(p);
  expect_valid(p, 4);
}

TEST_CASE("a very thin sliver (aspect ratio 1e6)") {
  expect_valid(polygon({rectangle(0, 0, 1, 1e-6)}), 2);
  expect_valid(polygon({rectangle(0, 0, 1, 1e-6)}), 8);
}

TEST_CASE("a long thin spike on a square") {
  const Pslg p = polygon({{{0, 0}, {1, 0}, {1, 1}, {0.5005, 1}, {0.5, 1000}, {0.4995, 1}, {0, 1}}});
  expect_valid(p, 4);
}

TEST_CASE("a nearly collinear run of 5000 vertices") {
  // The bottom edge of a 10 x 1 rectangle wiggles by 1e-9 over 5000 vertices.
  std::vector<Point> ring;
  for (int i = 0; i <= 5000; ++i) ring.push_back({i * 10.0 / 5000, (i % 2 == 1) ? 1e-9 : 0.0});
  ring.push_back({10, 1});
  ring.push_back({0, 1});
  expect_valid(polygon({ring}), 8);
}

TEST_CASE("a hole touching the outer boundary at a vertex") {
  // The hole's vertex (2, 0) is also a vertex of the outer ring: validate
  // accepts this (the domain stays connected), and so must decompose.
  Pslg p = polygon({{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}});
  p.points.push_back({2.5, 1});
  p.points.push_back({1.5, 1});
  p.segments.push_back({1, 5, 0});
  p.segments.push_back({5, 6, 0});
  p.segments.push_back({6, 1, 0});
  p.holes.push_back({2, 0.5});
  madd::validate(p);
  for (const std::uint32_t n : {2u, 4u, 8u}) expect_valid(p, n);
}

TEST_CASE("four hundred tiny holes") {
  std::vector<std::vector<Point>> rings{rectangle(0, 0, 1, 1)};
  std::vector<Point> holes;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const double x = (i + 0.5) / 20, y = (j + 0.5) / 20;
      rings.push_back(rectangle(x - 1e-3, y - 1e-3, x + 1e-3, y + 1e-3, true));
      holes.push_back({x, y});
    }
  }
  expect_valid(polygon(rings, holes), 16);
}

TEST_CASE("a 100,000-segment circle validates and splits in two") {
  std::vector<Point> ring;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    ring.push_back({std::cos(t), std::sin(t)});
  }
  const Pslg p = polygon({ring});
  madd::validate(p);
  expect_valid(p, 2);
}

TEST_CASE("a 1,000,000-segment domain validates and splits in two") {
  // A wavy star r(t) = 1 + 0.1 sin 7t: every split's refinement, triangulation
  // and bisection runs on a million boundary points.
  std::vector<Point> ring;
  const int n = 1000000;
  ring.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    const double r = 1.0 + 0.1 * std::sin(7.0 * t);
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  const Pslg p = polygon({ring});
  madd::validate(p);
  expect_valid(p, 2);
}

TEST_CASE("Phi0 = 89 still decomposes a triangle; Phi0 = 89.99 fails naming the subdomain, its area and Phi0") {
  // Bent medial-axis separators meet two non-parallel sides at nearly 90
  // degrees, so even Phi0 = 89 works on an equilateral triangle.
  const Pslg tri = polygon({{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}}});
  expect_valid(tri, 4, 89.0);
  madd::DecomposeOptions options;
  options.subdomains = 64;
  options.separator_angle_deg = 89.99;
  options.threads = 1;
  try {
    (void)madd::decompose(tri, options);
    FAIL("decompose succeeded at Phi0 = 89.99");
  } catch (const madd::DecompositionError& e) {
    CHECK(e.subdomain() >= 0);
    CHECK(e.area() > 0.0);
    CHECK(e.area() < std::sqrt(3.0) / 4);
    CHECK(e.separator_angle_deg() == 89.99);
    const std::string what = e.what();
    CHECK(what.find("89.99") != std::string::npos);
    CHECK(what.find("subdomain " + std::to_string(e.subdomain())) != std::string::npos);
  }
}

TEST_CASE("N far beyond the domain's features") {
  // At Phi0 = 60 no limit on N was found: a 1 x 0.05 triangle splits into
  // 4096 and a square into 10^5 (docs/hostile.md). Where the angle bound
  // makes splitting impossible (a 1 x 0.001 triangle at Phi0 = 89.9) the
  // error comes at once and nothing partial is returned.
  expect_valid(polygon({{{0, 0}, {1, 0}, {0.5, 0.05}}}), 1024);
  madd::DecomposeOptions options;
  options.subdomains = 1024;
  options.separator_angle_deg = 89.9;
  options.threads = 1;
  try {
    (void)madd::decompose(polygon({{{0, 0}, {1, 0}, {0.5, 0.001}}}), options);
    FAIL("no error");
  } catch (const madd::DecompositionError& e) {
    // It says that nothing could be split, how far it got and why.
    const std::string what = e.what();
    CHECK_MESSAGE(what.find("no subdomain can be split") != std::string::npos, what);
    CHECK_MESSAGE(what.find("reached 1 of 1024 subdomains") != std::string::npos, what);
    CHECK(e.subdomain() == 0);
  }
}

TEST_CASE("a subdomain that cannot be split gives its share to the others, and is tried again") {
  // A unit square with a spike 2 long and 0.01 wide on its right side. At
  // Phi0 = 89.9 some faces have no valid separator; the decomposition still
  // reaches N, every new angle >= Phi0, and it is the same for any thread count.
  const Pslg spike = polygon({{{0, 0}, {1, 0}, {1, 0.495}, {3, 0.5}, {1, 0.505}, {1, 1}, {0, 1}}});
  for (const std::uint32_t n : {8u, 64u}) {
    CAPTURE(n);
    madd::DecomposeOptions options;
    options.subdomains = n;
    options.separator_angle_deg = 89.9;
    options.threads = 1;
    const madd::Decomposition one = madd::decompose(spike, options);
    const madd::Verification check = madd::verify_decomposition(one, spike, n);
    CHECK_MESSAGE(check.ok(), (check.ok() ? std::string() : check.problems.front()));
    CHECK(madd::metrics(one).angle_min >= 89.9 - 1e-9);
    options.threads = 3;
    CHECK(madd::decompose(spike, options) == one);
  }
}

TEST_CASE("resource limits throw LimitError with a clear message") {
  std::vector<Point> ring;
  for (int i = 0; i < 400; ++i) {
    const double t = 2 * std::numbers::pi * i / 400;
    ring.push_back({std::cos(t), std::sin(t)});
  }
  const Pslg p = polygon({ring});
  madd::DecomposeOptions options;
  options.subdomains = 64;
  options.threads = 1;
  options.time_limit_seconds = 1e-9;
  try {
    (void)madd::decompose(p, options);
    FAIL("no LimitError");
  } catch (const madd::LimitError& e) {
    CHECK(std::string(e.what()).find("time limit") != std::string::npos);
  }
  options.time_limit_seconds = 0;
  options.max_memory_bytes = 1;
  try {
    (void)madd::decompose(p, options);
    FAIL("no LimitError");
  } catch (const madd::LimitError& e) {
    CHECK(std::string(e.what()).find("memory limit") != std::string::npos);
  }
  options.max_memory_bytes = std::size_t{1} << 40;  // generous limits change nothing
  options.time_limit_seconds = 1e6;
  madd::DecomposeOptions unlimited = options;
  unlimited.max_memory_bytes = 0;
  unlimited.time_limit_seconds = 0;
  CHECK(madd::decompose(p, options) == madd::decompose(p, unlimited));
}

TEST_CASE("a size bound far below the domain's scale stops at the memory and time limits, before refinement") {
  // --size-fn 1e-30 on data/channel.poly grew to 24 GB in the decoupling
  // (millions of split points a separator, no limit checked there) and was
  // killed. A unit square asking for sides of 1e-7: 8.5 million points a
  // segment.
  const Pslg p = polygon({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  madd::DecomposeOptions dopt;
  dopt.subdomains = 2;
  const madd::Decomposition d = madd::decompose(p, dopt);
  madd::MeshOptions o;
  o.decomposition.threads = 1;
  o.size.triangle_area_function = [](double, double) { return 1e-14; };
  o.decomposition.max_memory_bytes = madd::detail::resident_bytes() + (std::size_t{128} << 20);
  try {
    (void)madd::mesh_decomposition(d, p, o);
    FAIL("no LimitError");
  } catch (const madd::LimitError& e) {
    CHECK(std::string(e.what()).find("memory limit") != std::string::npos);
  }
  // The decoupling itself checks the limits it is given (refinement, after
  // it, would have stopped the run too, but only once every point was made).
  const madd::detail::AreaBound field(o.size);
  const madd::detail::ResourceGuard expired({.time_limit_seconds = 1e-9});
  CHECK_THROWS_AS(madd::detail::discretise(d, field, false, &expired), madd::LimitError);
}

TEST_CASE("an unwritable output fails with OutputError and leaves no file") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("madd-hostile-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "is_a_directory");
  madd::write_file_atomically((dir / "plain").string(), "x");
  // The parent is a regular file; the target is an existing directory.
  CHECK_THROWS_AS(madd::write_file_atomically((dir / "plain" / "out.poly").string(), "data"), madd::OutputError);
  CHECK_THROWS_AS(madd::write_file_atomically((dir / "is_a_directory").string(), "data"), madd::OutputError);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 2);  // "plain" and "is_a_directory" only: no temporary file left
  CHECK(fs::is_empty(dir / "is_a_directory"));
  fs::remove_all(dir);
}

TEST_CASE("after interrupt_output_writes nothing is written and no temporary file stays") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("madd-interrupt-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The interrupt flag is process-wide and permanent, so test it in a child.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    const bool in_flight = madd::interrupt_output_writes();
    int code = in_flight ? 1 : 0;
    try {
      madd::write_file_atomically((dir / "out.poly").string(), "data");
      code = 2;
    } catch (const madd::OutputError&) {}
    _exit(code);
  }
  int status = 0;
  waitpid(child, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // TEST_SUITE("hostile")
