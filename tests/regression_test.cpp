// Regressions found by fuzzing (fuzz/fuzz_*.cpp), each named after what broke;
// the input that found it is kept under fuzz/corpus/<target>/.
#include <doctest/doctest.h>

#include <string>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"

namespace {

std::string corpus(const char* target, const char* name) {
  return std::string(MADD_SOURCE_DIR) + "/fuzz/corpus/" + target + "/" + name;
}

} // namespace

TEST_SUITE("regression") {

TEST_CASE("needle spike: a 48-segment disk with a 6.7e5-long spike splits in seconds, not forever, and validly") {
  // fuzz_decompose timeout (> 10 s under ASan): one split of this needle
  // refined the boundary at sqrt(area) / 12 up to the 4e5 working-point cap,
  // once per refinement round. The cap now also scales with the face's own
  // vertices (at least 2e4 points), and limits are checked between refinement
  // rounds. The result must still be valid.
  const madd::Pslg domain = madd::read_domain(corpus("fuzz_decompose", "needle_spike_disk"));
  madd::Options options;
  options.subdomains = 2;
  options.min_angle_deg = 45.0;
  options.threads = 1;
  const madd::Decomposition d = madd::decompose(domain, options);
  const madd::Verification check = madd::verify_decomposition(d, domain, 2);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
}

// fuzz_decompose timeout (11 s under ASan, 1 s in Release) after the fix
// above: a 24-gon with two spikes, 81 and 66,000 long, is not needle-like
// enough to be skipped (perimeter 730 sqrt(area)) yet refined to 1.4e5 points
// in its last refinement rounds. Now capped at 2e4 points per split (0.1 s).
TEST_CASE("star with two needles: the per-face point cap keeps each split small, and the result valid") {
  const madd::Pslg domain = madd::read_domain(corpus("fuzz_decompose", "star_two_needles"));
  madd::Options options;
  options.subdomains = 5;
  options.min_angle_deg = 45.0;
  options.threads = 1;
  const madd::Decomposition d = madd::decompose(domain, options);
  const madd::Verification check = madd::verify_decomposition(d, domain, 5);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
}

// Was a hang (fuzz_decompose timeout) inside a split: try_spacing ->
// triangulate -> insert_segments. The refined face boundary is valid, but one
// segment crossed all three triangles around a vertex lying just above it, so
// the cavity held an uncrossed edge twice on its upper path; the old fill
// linked those edges to recycled slots, corrupting the mesh, and the next
// find_exit rotation never closed. The split is valid, so a valid
// decomposition is required (no error is acceptable).
TEST_CASE("cdt find_exit hang: segment insertion during a split terminates") {
  const madd::Pslg domain =
      madd::read_domain(std::string(MADD_SOURCE_DIR) + "/fuzz/corpus/fuzz_decompose/cdt_find_exit_hang");
  madd::Options options;
  options.subdomains = 5;
  options.min_angle_deg = 45.0;
  options.threads = 1;
  const madd::Decomposition d = madd::decompose(domain, options);
  CHECK(madd::verify_decomposition(d, domain, 5).ok());
}

} // TEST_SUITE
