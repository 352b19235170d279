// libFuzzer target: .poly text -> parse -> validate_pslg -> (resolve the
// crossings) -> triangulate, then the independent verifier. The options come
// from the input's first byte, so the corpus exercises every combination: bit
// 0 keeps the convex hull (-c), bit 1 resolves crossings (-r), bit 2 asks for
// the strict domain validation that decompose uses, bit 3 regional attributes
// (-A). Only madd::Error may
// escape the library; a result that fails verify_triangulation is a bug and
// aborts, and so does a domain that validate() accepts but validate_pslg()
// refuses (every domain is a PSLG).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "madd/poly_io.hpp"
#include "madd/triangulation.hpp"

namespace {

// A check that must pass by construction: an error there is a bug.
template <class Check>
void must(const char* what, Check&& check) {
  try {
    check();
  } catch (const madd::Error& e) {
    std::fprintf(stderr, "%s: %s\n", what, e.what());
    std::abort();
  }
}

// Bit for bit, so that NaN regional attributes (the reader takes any real)
// compare equal to themselves, which operator== would not.
bool identical(const madd::Triangulation& a, const madd::Triangulation& b) {
  return a.points == b.points && a.triangles == b.triangles && a.neighbours == b.neighbours &&
         a.segment_of == b.segment_of && a.attributes.size() == b.attributes.size() &&
         (a.attributes.empty() ||
          std::memcmp(a.attributes.data(), b.attributes.data(), a.attributes.size() * sizeof(double)) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::uint8_t mode = size > 0 && data[0] < 16 ? data[0] : 0;
  const std::size_t skip = size > 0 && data[0] < 16 ? 1 : 0;  // a text input (the seeds) runs with mode 0
  const std::string_view text(reinterpret_cast<const char*>(data) + skip, size - skip);
  madd::TriangulateOptions options;
  options.convex_hull = (mode & 1) != 0;
  options.region_attributes = (mode & 8) != 0;
  const bool resolve = (mode & 2) != 0;
  try {
    madd::PolyFile file = madd::parse_poly(text, "fuzz.poly");
    if ((mode & 4) != 0) {
      madd::validate(file.pslg, file.source);
      must("a domain refused as a PSLG", [&] { madd::validate_pslg(file.pslg); });
    } else {
      madd::ValidatePslgOptions validation;
      validation.allow_intersections = resolve;
      madd::validate_pslg(file.pslg, file.source, validation);
      if (resolve) {
        file.pslg = madd::resolve_intersections(file.pslg).pslg;
        must("resolved segments still intersect", [&] { madd::validate_pslg(file.pslg); });
      }
    }
    const madd::Triangulation tri = madd::triangulate(file.pslg, options);
    const madd::Verification check = madd::verify_triangulation(tri, &file.pslg, options);
    if (!check.ok()) {
      std::fprintf(stderr, "verify_triangulation: %s\n", check.problems.front().c_str());
      std::abort();
    }
    if (!identical(madd::triangulate(file.pslg, options), tri)) std::abort();  // deterministic
  } catch (const madd::Error& e) {
    (void)e;
  }
  return 0;
}
