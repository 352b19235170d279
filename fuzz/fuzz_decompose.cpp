// libFuzzer target: .poly text -> parse -> validate -> decompose, then the
// independent verifier. Only small domains (<= 200 segments) at small N, with
// a time limit inside the library (DecomposeOptions::time_limit_seconds), so one input
// stays fast. The limit is checked between splits and refinement rounds; one
// split refines the boundary at a spacing of sqrt(area) / 12, up to 2e4
// working points for a small face: a needle-like domain (perimeter >>
// sqrt(area)) always reaches that cap, which is slow under ASan
// (docs/hostile.md), so such inputs are skipped. Only madd::Error may escape the library (DecompositionError and
// LimitError are expected outcomes); a result that fails verify_decomposition
// is a bug and aborts.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/poly_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The last byte chooses N in 2..8 and Phi0 in {60, 45, 30, 70} (all 28
  // pairs occur among the bytes 0..27); it stays part of the text (usually a
  // newline or a digit), so plain .poly seeds work unchanged. A newline picks
  // N = 5 and Phi0 = 45, as it did when Phi0 was chosen from the first three.
  const std::uint8_t knob = data[size - 1];
  madd::DecomposeOptions options;
  options.subdomains = 2u + knob % 7u;
  constexpr double angles[] = {60.0, 45.0, 30.0, 70.0};
  options.separator_angle_deg = angles[(knob / 7u) % 4u];
  options.threads = 1;
  options.time_limit_seconds = 2.0;
  try {
    const madd::PolyFile file = madd::parse_poly(text, "fuzz.poly");
    if (file.pslg.segments.size() > 200) return 0;
    madd::validate(file.pslg, file.source);
    double perimeter = 0.0;
    for (const madd::Segment& seg : file.pslg.segments)
      perimeter += std::hypot(file.pslg.points[seg.b].x - file.pslg.points[seg.a].x,
                              file.pslg.points[seg.b].y - file.pslg.points[seg.a].y);
    if (!(perimeter <= 1000.0 * std::sqrt(madd::domain_area(file.pslg)))) return 0;
    const madd::Decomposition d = madd::decompose(file.pslg, options);
    const madd::Verification check = madd::verify_decomposition(d, file.pslg, options.subdomains);
    if (!check.ok()) {
      std::fprintf(stderr, "verify_decomposition (N=%u, Phi0=%g): %s\n", options.subdomains,
                   options.separator_angle_deg, check.problems.front().c_str());
      std::abort();
    }
  } catch (const madd::Error&) {}
  return 0;
}
