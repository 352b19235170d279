// madd_bench scaling [--n N] [--threads T] [--time-limit S] [SEGMENTS...]
// Scaling of decompose() with the input size: a star-shaped polygon with
// holes, generated in memory, of 10^3, 10^4, 10^5 and 10^6 segments by
// default, at N = 1024. Each size runs in its own forked process so the peak
// resident memory printed is that case's alone. Prints wall and CPU seconds
// (CPU of all threads, from getrusage) of validate + decompose.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <vector>

#include "bench.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"

namespace {

// About `segments` segments: half on the outer star r(t) = 1 + 0.25 sin(7t),
// half on k x k circular holes inside its inner radius.
madd::Pslg star_with_holes(std::size_t segments) {
  madd::Pslg p;
  p.first_index = 0;
  auto ring = [&p](const std::vector<madd::Point>& points) {
    const auto base = static_cast<std::uint32_t>(p.points.size());
    const auto n = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      p.points.push_back(points[i]);
      p.segments.push_back({base + i, base + (i + 1) % n, 1});
    }
  };
  const std::size_t outer = segments / 2;
  std::vector<madd::Point> points;
  for (std::size_t i = 0; i < outer; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(outer);
    const double r = 1 + 0.25 * std::sin(7 * t);
    points.push_back({r * std::cos(t), r * std::sin(t)});
  }
  ring(points);
  const int k = std::max(2, static_cast<int>(std::lround(std::pow(static_cast<double>(segments), 0.3))));
  const std::size_t per_hole = std::max<std::size_t>(8, (segments - outer) / static_cast<std::size_t>(k * k));
  const double cell = 1.0 / k;  // holes in [-0.5, 0.5]^2, inside the inner radius 0.75
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      const madd::Point c{-0.5 + (a + 0.5) * cell, -0.5 + (b + 0.5) * cell};
      points.clear();
      for (std::size_t i = 0; i < per_hole; ++i) {  // clockwise
        const double t = -2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(per_hole);
        points.push_back({c.x + 0.25 * cell * std::cos(t), c.y + 0.25 * cell * std::sin(t)});
      }
      ring(points);
      p.holes.push_back(c);
    }
  }
  return p;
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// The child: one size, one line.
int run_case(std::size_t segments, const madd::DecomposeOptions& options) {
  const madd::Pslg domain = star_with_holes(segments);
  const long long generated_rss = madd::bench::peak_rss_bytes();
  const double start = madd::bench::now_seconds();
  const double cpu_start = cpu_seconds();
  try {
    madd::validate(domain);
    const madd::Decomposition d = madd::decompose(domain, options);
    std::printf("%10zu %8zu %6u %10.3f %10.3f %10.1f %10.1f %9zu\n", domain.segments.size(), domain.holes.size(),
                options.subdomains, madd::bench::now_seconds() - start, cpu_seconds() - cpu_start,
                static_cast<double>(generated_rss) / 1048576.0,
                static_cast<double>(madd::bench::peak_rss_bytes()) / 1048576.0, d.subdomains.size());
  } catch (const madd::Error& e) {
    std::printf("%10zu %8zu %6u  failed after %.1f s: %s\n", domain.segments.size(), domain.holes.size(),
                options.subdomains, madd::bench::now_seconds() - start, e.what());
  }
  std::fflush(stdout);
  return 0;
}

int run(int argc, char** argv) {
  madd::DecomposeOptions options;
  options.subdomains = 1024;
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--n") == 0 && i + 1 < argc) {
      options.subdomains = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      options.threads = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (std::strcmp(argv[i], "--time-limit") == 0 && i + 1 < argc) {
      options.time_limit_seconds = std::atof(argv[++i]);
    } else {
      sizes.push_back(static_cast<std::size_t>(std::atof(argv[i])));
    }
  }
  if (sizes.empty()) sizes = {1000, 10000, 100000, 1000000};
  std::printf("%10s %8s %6s %10s %10s %10s %10s %9s\n", "segments", "holes", "N", "wall_s", "cpu_s", "input_MB",
              "peak_MB", "subdoms");
  std::fflush(stdout);
  for (const std::size_t size : sizes) {
    const pid_t child = fork();
    if (child < 0) return 1;
    if (child == 0) _exit(run_case(size, options));
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status)) std::printf("%10zu  crashed (status %d)\n", size, status);
  }
  return 0;
}

const madd::bench::Registration registration("scaling", run);

}  // namespace
