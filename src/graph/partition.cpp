// K-way partitioning by recursive bisection (explicit work stack).
#include <cmath>
#include <numeric>

#include "graph/graph_detail.hpp"
#include "madd/bisect.hpp"

namespace madd {

namespace {
struct Task {
  std::vector<std::uint32_t> vertices;  // in the input graph
  std::uint32_t first_part = 0;
  std::uint32_t parts = 1;
};
}  // namespace

void check_options(const PartitionOptions& options) {
  if (!(std::isfinite(options.balance_tolerance) && options.balance_tolerance >= 0.0))
    throw OptionError("balance_tolerance", "must be a finite number >= 0");
}

Partition partition(const Graph& graph, std::uint32_t k, const PartitionOptions& options) {
  if (k == 0) throw OptionError("k", "(the number of parts) must be at least 1");
  check_options(options);
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  Partition result;
  result.part.assign(n, 0);
  std::vector<Task> stack;
  Task all;
  all.vertices.resize(n);
  std::iota(all.vertices.begin(), all.vertices.end(), 0u);
  all.parts = k;
  stack.push_back(std::move(all));
  std::uint64_t task_index = 0;
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    if (task.parts == 1) {
      for (const std::uint32_t v : task.vertices) result.part[v] = task.first_part;
      continue;
    }
    // Side 0 gets floor(k/2) of the parts and that share of the weight.
    const std::uint32_t left = task.parts / 2;
    BisectOptions bo;
    bo.target_fraction = static_cast<double>(left) / static_cast<double>(task.parts);
    bo.balance_tolerance = options.balance_tolerance;
    bo.seed = options.seed + 0x9e3779b97f4a7c15ull * task_index++;
    bo.connected = options.connected;
    bo.refinement_passes = options.refinement_passes;
    // The first task holds every vertex in order: bisect the graph itself
    // rather than a copy.
    const bool whole = task.vertices.size() == n;
    const Bisection b = whole ? bisect(graph, bo) : bisect(detail::induced_subgraph(graph, task.vertices), bo);
    Task lo, hi;
    lo.first_part = task.first_part;
    lo.parts = left;
    hi.first_part = task.first_part + left;
    hi.parts = task.parts - left;
    for (std::size_t i = 0; i < task.vertices.size(); ++i)
      (b.side[i] == 0 ? lo : hi).vertices.push_back(task.vertices[i]);
    stack.push_back(std::move(hi));
    stack.push_back(std::move(lo));
  }
  result.part_weights.assign(k, 0.0);
  for (std::uint32_t v = 0; v < n; ++v) {
    result.part_weights[result.part[v]] += graph.vertex_weights[v];
    for (std::uint32_t i = graph.offsets[v]; i < graph.offsets[v + 1]; ++i) {
      const std::uint32_t u = graph.adjacency[i];
      if (v < u && result.part[v] != result.part[u]) result.cut += graph.edge_weights[i];
    }
  }
  return result;
}

}  // namespace madd
