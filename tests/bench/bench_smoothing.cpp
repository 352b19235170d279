// `madd_bench smoothing FILE.poly N...`: separator smoothing (Sec. 5.1) off
// (--smoothing 0: no edge-weight coefficients, no step 2) and on (1 iteration).
#include <cstdio>
#include <cstdlib>

#include "../smoothing_measure.hpp"
#include "bench.hpp"
#include "madd/poly_io.hpp"

namespace {

int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: madd_bench smoothing FILE.poly N...\n");
    return 2;
  }
  const madd::Pslg domain = madd::read_domain(argv[1]);
  std::printf("| N | smoothing | shortest new seg / sqrt(mean area) | new segs < 5%% | ends on existing | median angle | min angle | C3 max/mean | ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 2; i < argc; ++i) {
    for (int iterations : {0, 1, 3}) {
      madd::Options o;
      o.subdomains = static_cast<std::uint32_t>(std::strtoul(argv[i], nullptr, 10));
      o.smoothing_iterations = iterations;
      const double t0 = madd::bench::now_seconds();
      const madd::Decomposition d = madd::decompose(domain, o);
      const double ms = 1e3 * (madd::bench::now_seconds() - t0);
      const auto f = madd::test::smoothing_figures(d, domain.points.size());
      std::printf("| %u | %d | %.4f | %u | %.3f (%u ends) | %.2f | %.2f | %.4f | %.0f |\n", o.subdomains, iterations,
                  f.shortest_norm, f.short_count, f.on_existing, f.ends, f.median_angle, f.min_angle,
                  madd::metrics(d).max_area_over_mean, ms);
    }
  }
  return 0;
}

const madd::bench::Registration reg("smoothing", run);

} // namespace
