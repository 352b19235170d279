// libFuzzer target: .poly text -> parse -> validate -> triangulate, then the
// independent verifier. Only madd::Error may escape the library; a result
// that fails verify_triangulation is a bug and aborts.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "madd/triangulation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const madd::PolyFile file = madd::parse_poly(text, "fuzz.poly");
    madd::validate(file.pslg, file.source);
    const madd::Triangulation tri = madd::triangulate(file.pslg);
    const madd::Verification check = madd::verify_triangulation(tri, &file.pslg);
    if (!check.ok()) {
      std::fprintf(stderr, "verify_triangulation: %s\n", check.problems.front().c_str());
      std::abort();
    }
    if (madd::triangulate(file.pslg) != tri) std::abort();  // deterministic
  } catch (const madd::Error&) {
  }
  return 0;
}
