// Benchmark of delaunay() and triangulate() on the workloads of the
// triangulator's targets: uniform random points (1e4, 1e5, 1e6), a regular
// 100,000-gon, and a random star polygon of 100,000 vertices with 9 holes of
// 64 vertices (generated in memory like peers/gen_poly.py star).
//   madd_bench triangulate [WORKLOAD...] [--runs K]
// Each workload runs in a forked child so that its peak memory is its own.
// The peak is the growth of the resident set (VmHWM) over the run, input
// included; see warm_up() for what is left out.
#include <malloc.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench.hpp"
#include "madd/triangulation.hpp"

namespace {

using madd::Point;

// CPU seconds of this process: on a shared, loaded machine wall time alone
// misleads, so both are printed.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

long long current_rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
  }
  return -1;
}

std::vector<Point> ring(std::size_t n, Point c, double r, double phase, bool cw) {
  std::vector<Point> pts(n);
  const double s = cw ? -1.0 : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = phase + s * 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    pts[i] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  return pts;
}

void add_ring(madd::Pslg& pslg, const std::vector<Point>& pts, int marker) {
  const auto base = static_cast<std::uint32_t>(pslg.points.size());
  const auto n = static_cast<std::uint32_t>(pts.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    pslg.points.push_back(pts[i]);
    pslg.segments.push_back({base + i, base + (i + 1) % n, marker});
  }
}

// Star-shaped about the origin: smooth random Fourier radius plus radial noise
// of 0.3 mean edge lengths, and k disjoint circular holes of m vertices.
madd::Pslg star(std::size_t n, std::size_t k, std::size_t m, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double two_pi = 2 * std::numbers::pi;
  double amp[5], phase[5];
  for (int j = 0; j < 5; ++j) {
    amp[j] = 0.12 / (j + 2) * u(rng);
    phase[j] = two_pi * u(rng);
  }
  std::vector<Point> outer(n);
  double rmin = 1e300;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = two_pi * (static_cast<double>(i) + 0.1 + 0.8 * u(rng)) / static_cast<double>(n);
    double r = 1 + 0.3 * (two_pi / static_cast<double>(n)) * (u(rng) - 0.5);
    for (int j = 0; j < 5; ++j) r += amp[j] * std::cos((j + 2) * t + phase[j]);
    rmin = std::min(rmin, r);
    outer[i] = {r * std::cos(t), r * std::sin(t)};
  }
  madd::Pslg pslg;
  add_ring(pslg, outer, 1);
  const double rin = 0.95 * rmin * std::cos(two_pi / static_cast<double>(n));
  double rh = 0.45 * rin / std::sqrt(static_cast<double>(std::max<std::size_t>(k, 1)));
  std::vector<Point> centres;
  while (centres.size() < k) {
    centres.clear();
    for (int tries = 0; tries < 20000 && centres.size() < k; ++tries) {
      const double a = two_pi * u(rng), d = (rin - 1.1 * rh) * std::sqrt(u(rng));
      const Point c{d * std::cos(a), d * std::sin(a)};
      bool clear = true;
      for (const Point& q : centres) clear = clear && madd::distance(c, q) > 2.2 * rh;
      if (clear) centres.push_back(c);
    }
    if (centres.size() < k) rh *= 0.9;
  }
  for (std::size_t h = 0; h < k; ++h) {
    add_ring(pslg, ring(m, centres[h], rh, two_pi * u(rng), true), static_cast<int>(h + 2));
    pslg.holes.push_back(centres[h]);
  }
  return pslg;
}

struct Workload {
  std::string kind;  // "uniform", "circle" or "star"
  std::size_t n = 0;
};

// "uniform-N", "circle-N" (regular N-gon) or "star-N" (N vertices, 9 holes of
// 64); N may be written 1e5. Exits with a message on anything else.
Workload parse_workload(const std::string& name) {
  const std::size_t dash = name.find('-');
  Workload w{name.substr(0, dash), 0};
  if (dash != std::string::npos) w.n = static_cast<std::size_t>(std::atof(name.c_str() + dash + 1));
  const bool known = (w.kind == "uniform" && w.n > 0) || ((w.kind == "circle" || w.kind == "star") && w.n >= 3);
  if (!known) {
    std::fprintf(stderr, "unknown workload %s (uniform-N, circle-N, star-N)\n", name.c_str());
    std::exit(2);
  }
  return w;
}

madd::Pslg generate(const Workload& w) {
  madd::Pslg pslg;
  if (w.kind == "uniform") {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    pslg.points.resize(w.n);
    for (auto& p : pslg.points) p = {u(rng), u(rng)};
  } else if (w.kind == "circle") {
    add_ring(pslg, ring(w.n, {0, 0}, 1.0, 0.0, false), 1);
  } else {
    pslg = star(w.n, 9, 64, 1);
  }
  // Exact-size storage, so the input counts once in the peak memory figure.
  pslg.points.shrink_to_fit();
  pslg.segments.shrink_to_fit();
  return pslg;
}

madd::Triangulation run_workload(const madd::Pslg& pslg) {
  return pslg.segments.empty() ? madd::delaunay(pslg.points) : madd::triangulate(pslg);
}

// Faults in the code a run touches (about 0.4 MB of text, ours and the
// libraries': a fixed cost, which would read as 40 bytes/point at 10^4) by a
// run of the same kind on a few hundred points, then hands the heap it used
// back to the system, so that it cannot lower the figure that follows.
void warm_up(const Workload& w) {
  (void)run_workload(generate({w.kind, 200}));
  malloc_trim(0);
}

// Runs one workload `runs` times; prints the median wall and CPU times, the
// triangle count and the peak memory growth (input included) per input point,
// measured from after a warm-up; the figure with the first touch of the code
// (from a cold start) follows in parentheses.
int run_one(const std::string& name, int runs) {
  const Workload w = parse_workload(name);
  const long long rss_cold = current_rss_bytes();
  warm_up(w);
  const long long rss0 = current_rss_bytes();
  const madd::Pslg pslg = generate(w);
  std::vector<double> times, cpu;
  std::size_t triangles = 0;
  for (int r = 0; r < runs; ++r) {
    const double t0 = madd::bench::now_seconds(), c0 = cpu_seconds();
    const madd::Triangulation tri = run_workload(pslg);
    times.push_back(madd::bench::now_seconds() - t0);
    cpu.push_back(cpu_seconds() - c0);
    triangles = tri.triangle_count();
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu.begin(), cpu.end());
  const double n = static_cast<double>(pslg.points.size());
  const long long peak = madd::bench::peak_rss_bytes();
  const double bytes = static_cast<double>(peak - rss0) / n;
  const double cold_bytes = static_cast<double>(peak - rss_cold) / n;
  std::printf("%-12s %8zu pts %8zu tris  wall median %9.3f ms (min %.3f)  cpu median %9.3f ms  %d runs  "
              "peak %5.1f bytes/point (%.1f cold)\n",
              name.c_str(), pslg.points.size(), triangles, 1e3 * times[times.size() / 2], 1e3 * times.front(),
              1e3 * cpu[cpu.size() / 2], runs, bytes, cold_bytes);
  return 0;
}

int run_triangulate(int argc, char** argv) {
  std::vector<std::string> names;
  int runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      names.push_back(argv[i]);
    }
  }
  if (names.empty()) names = {"uniform-1e4", "uniform-1e5", "uniform-1e6", "circle-1e5", "star-1e5"};
  std::fflush(stdout);
  for (const std::string& name : names) {
    const pid_t pid = fork();
    if (pid == 0) {
      const int rc = run_one(name, name == "uniform-1e6" ? std::min(runs, 3) : runs);
      std::fflush(stdout);
      _exit(rc);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
  }
  return 0;
}

const madd::bench::Registration reg("triangulate", run_triangulate);

}  // namespace
