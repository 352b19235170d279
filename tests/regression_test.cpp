// Regressions found by fuzzing (fuzz/fuzz_*.cpp), each named after what broke;
// the input that found it is kept under fuzz/corpus/<target>/.
#include <doctest/doctest.h>

#include <string>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"
#include "decomposition_check.hpp"

namespace {

std::string corpus(const char* target, const char* name) {
  return std::string(MADD_SOURCE_DIR) + "/fuzz/corpus/" + target + "/" + name;
}

}  // namespace

TEST_SUITE("regression") {

TEST_CASE("needle spike: a 48-segment disk with a 6.7e5-long spike splits in seconds, not forever, and validly") {
  // fuzz_decompose timeout (> 10 s under ASan): one split of this needle
  // refined the boundary at sqrt(area) / 12 up to the 4e5 working-point cap,
  // once per refinement round. The cap now also scales with the face's own
  // vertices (at least 2e4 points), and limits are checked between refinement
  // rounds. The result must still be valid.
  madd::test::checked_decomposition(madd::read_domain(corpus("fuzz_decompose", "needle_spike_disk")), 2, 45.0);
}

// fuzz_decompose timeout (11 s under ASan, 1 s in Release) after the fix
// above: a 24-gon with two spikes, 81 and 66,000 long, is not needle-like
// enough to be skipped (perimeter 730 sqrt(area)) yet refined to 1.4e5 points
// in its last refinement rounds. Now capped at 2e4 points per split (0.1 s).
TEST_CASE("star with two needles: the per-face point cap keeps each split small, and the result valid") {
  madd::test::checked_decomposition(madd::read_domain(corpus("fuzz_decompose", "star_two_needles")), 5, 45.0);
}

// Was a hang (fuzz_decompose timeout) inside a split: try_spacing ->
// triangulate -> insert_segments. The refined face boundary is valid, but one
// segment crossed all three triangles around a vertex lying just above it, so
// the cavity held an uncrossed edge twice on its upper path; the old fill
// linked those edges to recycled slots, corrupting the mesh, and the next
// find_exit rotation never closed. The split is valid, so a valid
// decomposition is required (no error is acceptable).
TEST_CASE("cdt find_exit hang: segment insertion during a split terminates") {
  madd::test::checked_decomposition(madd::read_domain(corpus("fuzz_decompose", "cdt_find_exit_hang")), 5, 45.0);
}

}  // TEST_SUITE("regression")
