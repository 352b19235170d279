// Separator smoothing (paper Sec. 5.1): with it, more separator ends land on
// existing ends, and validity and C1 hold either way.
#include <doctest/doctest.h>

#include <string>

#include "madd/decomposition.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "smoothing_measure.hpp"

namespace {

madd::test::SmoothingFigures run(const madd::Pslg& domain, std::uint32_t n, int iterations, unsigned threads = 1) {
  madd::DecomposeOptions o;
  o.subdomains = n;
  o.smoothing_iterations = iterations;
  o.threads = threads;
  const madd::Decomposition d = madd::decompose(domain, o);
  const madd::Verification v = madd::verify_decomposition(d, domain, n);
  for (const auto& p : v.problems) INFO(p);
  CHECK(v.ok());
  const auto f = madd::test::smoothing_figures(d, domain.points.size());
  CHECK(f.min_angle >= o.separator_angle_deg);
  return f;
}

}  // namespace

TEST_SUITE("smoothing") {

TEST_CASE("smoothing puts at least as many separator ends on existing ends") {
  for (const char* name : {"pipe.poly", "key.poly"}) {
    CAPTURE(name);
    const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name);
    const auto off = run(domain, 64, 0);
    const auto on = run(domain, 64, 1);
    INFO("off " << off.on_existing << " (" << off.ends << " ends), on " << on.on_existing << " (" << on.ends << ")");
    CHECK(on.on_existing >= off.on_existing);
    CHECK(on.ends > 0);
  }
}

TEST_CASE("smoothed decompositions stay valid, with C1, for several N and iterations") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/pipe.poly");
  for (std::uint32_t n : {2u, 7u, 33u, 200u}) {
    for (int iterations : {1, 3}) {
      CAPTURE(n);
      CAPTURE(iterations);
      run(domain, n, iterations);
    }
  }
}

TEST_CASE("smoothing is deterministic across thread counts") {
  const madd::Pslg domain = madd::read_domain(std::string(MADD_DATA_DIR) + "/key.poly");
  madd::DecomposeOptions o;
  o.subdomains = 100;
  o.smoothing_iterations = 2;
  o.threads = 1;
  const madd::Decomposition one = madd::decompose(domain, o);
  o.threads = 2;
  CHECK(one == madd::decompose(domain, o));
}

}  // TEST_SUITE("smoothing")
