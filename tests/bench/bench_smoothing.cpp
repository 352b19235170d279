// `madd_bench smoothing FILE.poly SEEDS N...`: separator smoothing (Sec. 5.1)
// off (--smoothing 0: no edge-weight coefficients, no step 2) and on (1 and 3
// iterations), each figure averaged over seeds 1..SEEDS (one decomposition
// is one sample of a chaotic recursion: single runs are noisy).
#include <cstdio>
#include <cstdlib>

#include "../smoothing_measure.hpp"
#include "bench.hpp"
#include "madd/poly_io.hpp"

namespace {

struct Sums {
  double shortest = 0, short_count = 0, short_sep = 0, on_existing = 0, ends = 0, median = 0, min_angle = 180, c3 = 0,
         ms = 0;
};

Sums measure(const madd::Pslg& domain, std::uint32_t n, int iterations, int seeds) {
  Sums s;
  for (int seed = 1; seed <= seeds; ++seed) {
    madd::DecomposeOptions o;
    o.subdomains = n;
    o.smoothing_iterations = iterations;
    o.seed = static_cast<std::uint64_t>(seed);
    const double t0 = madd::bench::now_seconds();
    const madd::Decomposition d = madd::decompose(domain, o);
    s.ms += 1e3 * (madd::bench::now_seconds() - t0) / seeds;
    const auto f = madd::test::smoothing_figures(d, domain.points.size());
    s.shortest += f.shortest_norm / seeds;
    s.short_count += static_cast<double>(f.short_count) / seeds;
    s.short_sep += static_cast<double>(f.short_separators) / seeds;
    s.on_existing += f.on_existing / seeds;
    s.ends += static_cast<double>(f.ends) / seeds;
    s.median += f.median_angle / seeds;
    s.min_angle = std::min(s.min_angle, f.min_angle);
    s.c3 += madd::metrics(d).max_area_over_mean / seeds;
  }
  return s;
}

int run(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: madd_bench smoothing FILE.poly SEEDS N...\n");
    return 2;
  }
  const madd::Pslg domain = madd::read_domain(argv[1]);
  const int seeds = std::max(1, std::atoi(argv[2]));
  std::printf("| N | smoothing | shortest new seg / sqrt(mean area) | new segs < 5%% (separators) | ends on existing | "
              "median angle | min angle (worst) | C3 area max/mean | ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 3; i < argc; ++i) {
    const auto n = static_cast<std::uint32_t>(std::strtoul(argv[i], nullptr, 10));
    for (int iterations : {0, 1, 3}) {
      const Sums s = measure(domain, n, iterations, seeds);
      std::printf("| %u | %d | %.4f | %.1f (%.1f) | %.3f (%.0f ends) | %.2f | %.2f | %.4f | %.0f |\n", n, iterations,
                  s.shortest, s.short_count, s.short_sep, s.on_existing, s.ends, s.median, s.min_angle, s.c3, s.ms);
    }
  }
  return 0;
}

const madd::bench::Registration reg("smoothing", run);

}  // namespace
