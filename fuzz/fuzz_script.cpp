// libFuzzer target: the script language, sandboxed. File commands are
// disabled, a unit square is preloaded so `dec` can run, and the options are
// bounded so that one input stays fast. Any exception other than madd::Error,
// any crash or sanitizer report is a bug; so is a decomposition that fails
// verify_decomposition.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/metrics.hpp"
#include "madd/script.hpp"

namespace {

madd::Pslg unit_square() {
  madd::Pslg square;
  square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  square.has_segment_markers = true;
  return square;
}

void refuse_costly(const madd::DecomposeOptions& o) {
  if (o.boundary_refinement > 8 || o.smoothing_iterations > 4 || o.threads != 1)
    throw madd::OptionError("options", "outside the fuzzing sandbox (r <= 8, s <= 4, j = 1)");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  madd::ScriptContext context;
  context.allow_files = false;
  context.max_subdomains = 8;
  context.check_options = refuse_costly;
  context.options.threads = 1;
  context.domain = unit_square();
  try {
    madd::run_script(text, "fuzz.txt", context);
  } catch (const madd::ParseError& e) {
    if (e.path() != "fuzz.txt" || e.line() < 1) std::abort();  // every script error names its line
  } catch (const madd::Error&) {}
  if (context.decomposition) {
    const madd::Decomposition& d = *context.decomposition;
    const auto n = static_cast<std::uint32_t>(d.subdomains.size());
    const bool area_graded = context.options.subdomain_area_function || !context.options.subdomain_area_samples.empty();
    const std::uint32_t expected = area_graded && n <= context.requested_subdomains ? n : context.requested_subdomains;
    if (!madd::verify_decomposition(d, *context.domain, expected).ok()) std::abort();
  }
  return 0;
}
