// Benchmark: format, parse and validate a large valid domain built in memory.
//   madd_bench validate [outer_vertices=999000] [holes=10] [hole_vertices=100]
// The default is a 999,000-gon with 10 holes of 100 segments: 1,000,000 segments.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <numbers>

#include "bench.hpp"
#include "madd/poly_io.hpp"

namespace {

void add_circle(madd::Pslg& p, madd::Point c, double r, std::uint32_t n, bool clockwise) {
  const auto base = static_cast<std::uint32_t>(p.points.size());
  for (std::uint32_t k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n * (clockwise ? -1.0 : 1.0);
    p.points.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    p.segments.push_back({base + k, base + (k + 1) % n, 1});
  }
}

int run_validate(int argc, char** argv) {
  const auto outer = static_cast<std::uint32_t>(argc > 1 ? std::atol(argv[1]) : 999000);
  const auto holes = static_cast<std::uint32_t>(argc > 2 ? std::atol(argv[2]) : 10);
  const auto hole_n = static_cast<std::uint32_t>(argc > 3 ? std::atol(argv[3]) : 100);
  madd::Pslg p;
  p.has_segment_markers = true;
  add_circle(p, {0, 0}, 1000.0, outer, false);
  for (std::uint32_t h = 0; h < holes; ++h) {
    const double a = 2.0 * std::numbers::pi * h / std::max<std::uint32_t>(holes, 1);
    const madd::Point c{500.0 * std::cos(a), 500.0 * std::sin(a)};
    add_circle(p, c, 50.0, hole_n, true);
    p.holes.push_back(c);
  }
  // CPU seconds too: on a shared machine wall time overstates the cost.
  const auto cpu = [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
  const double t0 = madd::bench::now_seconds(), c0 = cpu();
  const std::string text = madd::format_poly(p, "bench_validate");
  const double t1 = madd::bench::now_seconds(), c1 = cpu();
  const madd::PolyFile file = madd::parse_poly(text, "bench.poly");
  const double t2 = madd::bench::now_seconds(), c2 = cpu();
  madd::validate(file.pslg, file.source);
  const double t3 = madd::bench::now_seconds(), c3 = cpu();
  const double area = madd::domain_area(file.pslg);
  const double t4 = madd::bench::now_seconds(), c4 = cpu();
  std::printf("segments %zu  holes %zu  text %.1f MB\n", file.pslg.segments.size(), file.pslg.holes.size(),
              static_cast<double>(text.size()) / 1e6);
  std::printf("wall: format %.3f s  parse %.3f s  validate %.3f s  domain_area %.3f s\n", t1 - t0, t2 - t1, t3 - t2,
              t4 - t3);
  std::printf("cpu:  format %.3f s  parse %.3f s  validate %.3f s  domain_area %.3f s\n", c1 - c0, c2 - c1, c3 - c2,
              c4 - c3);
  std::printf("area %.6f  peak RSS %.1f MB\n", area, static_cast<double>(madd::bench::peak_rss_bytes()) / 1e6);
  return file.pslg == p ? 0 : 1;
}

const madd::bench::Registration reg("validate", run_validate);

}  // namespace
