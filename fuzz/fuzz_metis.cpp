// libFuzzer target: the METIS graph reader, then the bisector on whatever
// parses. Only madd::Error may escape the library; a bisection that fails
// verify_bisection, or leaves a side of a connected graph disconnected, is a bug.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "madd/bisect.hpp"
#include "madd/error.hpp"
#include "madd/graph.hpp"
#include "madd/metis_io.hpp"

namespace {

bool graph_connected(const madd::Graph& g) {
  const std::size_t n = g.vertex_count();
  if (n == 0) return true;
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<std::uint32_t> stack(1, 0);
  seen[0] = 1;
  std::size_t reached = 0;
  while (!stack.empty()) {
    const std::uint32_t u = stack.back();
    stack.pop_back();
    ++reached;
    for (std::uint32_t i = g.offsets[u]; i < g.offsets[u + 1]; ++i) {
      if (!seen[g.adjacency[i]]) {
        seen[g.adjacency[i]] = 1;
        stack.push_back(g.adjacency[i]);
      }
    }
  }
  return reached == n;
}

void check(const madd::Graph& g, const madd::BisectOptions& options) {
  const madd::Bisection b = madd::bisect(g, options);
  if (!madd::verify_bisection(g, b).ok()) std::abort();
  for (const auto& [u, v] : options.keep_together)
    if (b.side[u] != b.side[v]) std::abort();
  // Connectivity is guaranteed when nothing is kept together across the graph.
  if (options.keep_together.empty() && g.vertex_count() >= 2 && graph_connected(g) &&
      !(b.connected[0] && b.connected[1]))
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const madd::Graph g = madd::parse_metis(text, "fuzz.graph");
    if (g.vertex_count() > 20000) return 0;  // keep each run fast
    madd::BisectOptions options;
    options.seed = size;
    check(g, options);
    options.target_fraction = 0.3;
    options.balance_tolerance = 0.0;
    check(g, options);
    if (g.vertex_count() >= 2) {
      options.keep_together.push_back({0, static_cast<std::uint32_t>(g.vertex_count() - 1)});
      check(g, options);
    }
    const madd::Partition p = madd::partition(g, 3);
    if (p.part.size() != g.vertex_count()) std::abort();
  } catch (const madd::Error&) {}
  return 0;
}
