// libFuzzer target: the .poly reader plus validation. Any exception other than
// madd::Error, any crash or sanitizer report is a bug.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const madd::PolyFile file = madd::parse_poly(text, "fuzz.poly");
    madd::validate(file.pslg, file.source);
    // A valid domain must survive a write/read round trip unchanged.
    const std::string written = madd::format_poly(file.pslg);
    if (madd::parse_poly(written, "roundtrip.poly").pslg != file.pslg) std::abort();
    (void)madd::domain_area(file.pslg);
  } catch (const madd::Error&) {
  }
  return 0;
}
