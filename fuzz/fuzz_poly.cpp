// libFuzzer target: the .poly reader plus both validations (a domain, any
// PSLG) and the PSLG summary. Any exception other than madd::Error, any crash
// or sanitizer report is a bug.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  madd::PolyFile file;
  try {
    file = madd::parse_poly(text, "fuzz.poly");
  } catch (const madd::Error&) {
    return 0;
  }
  bool pslg = false;
  try {
    madd::validate_pslg(file.pslg, file.source);
    pslg = true;
    const madd::PslgSummary summary = madd::summarize_pslg(file.pslg);
    if (summary.interior_segments + summary.boundary_segments + summary.outside_segments != file.pslg.segments.size())
      std::abort();
    if (summary.isolated_inside > summary.isolated_vertices) std::abort();
  } catch (const madd::Error&) {}
  try {
    madd::validate(file.pslg, file.source);
    if (!pslg) std::abort();  // every domain is a PSLG
    // A valid domain must survive a write/read round trip unchanged.
    const std::string written = madd::format_poly(file.pslg);
    if (madd::parse_poly(written, "roundtrip.poly").pslg != file.pslg) std::abort();
    (void)madd::domain_area(file.pslg);
  } catch (const madd::Error&) {}
  return 0;
}
