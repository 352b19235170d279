// libFuzzer target: the fort.14 reader and its check. Any exception other
// than madd::Error, any crash, hang or sanitizer report is a bug.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/error.hpp"
#include "madd/model_output.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  madd::Fort14 grid;
  try {
    grid = madd::parse_fort14(text, "fuzz.14");
  } catch (const madd::Error&) {
    return 0;
  }
  // What was read is within the file: ids within the nodes, one depth a node.
  if (grid.depths.size() != grid.points.size()) std::abort();
  for (const auto& e : grid.elements)
    for (const std::uint32_t v : e)
      if (v >= grid.points.size()) std::abort();
  const madd::Verification first = madd::check_fort14(grid);
  if (madd::check_fort14(grid) != first) std::abort();  // deterministic
  if (madd::parse_fort14(text, "fuzz.14") != grid) std::abort();
  return 0;
}
