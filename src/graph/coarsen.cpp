// Heavy-edge matching and the coarsening loop of the multilevel bisector.
#include "graph/coarsen.hpp"

#include <algorithm>
#include <numeric>

namespace madd::detail {

namespace {

// Visit order for the sorted variant: heaviest incident edge first; ties keep
// the random order, so the result still depends only on the seed.
std::vector<std::uint32_t> sorted_order(const Graph& graph, std::vector<std::uint32_t> order) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  std::vector<double> heaviest(n, 0.0);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t i = graph.offsets[v]; i < graph.offsets[v + 1]; ++i)
      heaviest[v] = std::max(heaviest[v], graph.edge_weights[i]);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return heaviest[a] > heaviest[b]; });
  return order;
}

// A visit order that is random but cache-friendly: consecutive blocks of the
// vertex range, each shuffled, in a shuffled block order. A fully random order
// turns every adjacency read into a cache miss on large graphs (METIS makes
// the same trade with its partial shuffle).
std::vector<std::uint32_t> local_shuffle(std::uint32_t n, SplitMix64& rng) {
  constexpr std::uint32_t block = 64;
  const std::uint32_t blocks = (n + block - 1) / block;
  const std::vector<std::uint32_t> block_order = random_permutation(blocks, rng);
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (const std::uint32_t b : block_order) {
    const std::uint32_t first = b * block, last = std::min(n, first + block);
    const auto begin = static_cast<std::ptrdiff_t>(order.size());
    for (std::uint32_t v = first; v < last; ++v) order.push_back(v);
    for (std::uint32_t i = last - first; i > 1; --i)
      std::swap(order[static_cast<std::size_t>(begin) + i - 1], order[static_cast<std::size_t>(begin) + rng.below(i)]);
  }
  return order;
}

}  // namespace

Graph contract_matching(const Graph& graph, const Matching& m) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  Graph coarse;
  coarse.offsets.assign(m.coarse_count + 1, 0);
  coarse.vertex_weights.resize(m.coarse_count);
  coarse.adjacency.reserve(graph.adjacency.size());
  coarse.edge_weights.reserve(graph.adjacency.size());
  std::vector<std::uint32_t> slot(m.coarse_count, no_vertex);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (m.mate[v] < v) continue;  // handled with its partner
    const std::uint32_t c = m.map[v];
    const auto begin = static_cast<std::uint32_t>(coarse.adjacency.size());
    const std::uint32_t members[2] = {v, m.mate[v]};
    coarse.vertex_weights[c] = graph.vertex_weights[v] + (m.mate[v] != v ? graph.vertex_weights[m.mate[v]] : 0.0);
    for (int k = 0; k < (m.mate[v] != v ? 2 : 1); ++k) {
      append_merged_edges(graph, m.map, members[k], c, begin, slot, coarse);
    }
    coarse.offsets[c + 1] = static_cast<std::uint32_t>(coarse.adjacency.size());
  }
  return coarse;
}

Matching heavy_edge_matching(const Graph& graph, SplitMix64& rng, bool sorted, double max_vertex_weight) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  std::vector<std::uint32_t> order = local_shuffle(n, rng);
  if (sorted) order = sorted_order(graph, std::move(order));
  std::vector<std::uint32_t> mate(n, no_vertex);
  for (const std::uint32_t v : order) {
    if (mate[v] != no_vertex) continue;
    std::uint32_t best = v;
    double best_weight = -1.0;
    const double room = max_vertex_weight - graph.vertex_weights[v];
    for (std::uint32_t i = graph.offsets[v]; i < graph.offsets[v + 1]; ++i) {
      const std::uint32_t u = graph.adjacency[i];
      if (mate[u] != no_vertex || graph.edge_weights[i] <= best_weight) continue;
      if (graph.vertex_weights[u] > room) continue;
      best = u;
      best_weight = graph.edge_weights[i];
    }
    mate[v] = best;
    mate[best] = v;
  }
  // Number coarse vertices in fine-vertex order (as METIS does), not in the
  // random visit order: keeps the memory locality of the input at every level.
  Matching m;
  m.map.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) m.map[v] = mate[v] < v ? m.map[mate[v]] : m.coarse_count++;
  m.mate = std::move(mate);
  return m;
}

Hierarchy coarsen(const Graph& graph, SplitMix64& rng, const CoarsenOptions& options) {
  Hierarchy h;
  const double total = std::accumulate(graph.vertex_weights.begin(), graph.vertex_weights.end(), 0.0);
  // METIS's bound: no coarse vertex heavier than 1.5 W / coarsen_to, so the
  // coarsest graph still has enough pieces to balance.
  const double max_vertex_weight = 1.5 * total / static_cast<double>(std::max(options.coarsen_to, 1u));
  const Graph* current = &graph;
  while (current->vertex_count() > options.coarsen_to) {
    const auto n = static_cast<double>(current->vertex_count());
    Matching m = heavy_edge_matching(*current, rng, options.sorted_heavy_edge, max_vertex_weight);
    if (m.coarse_count == current->vertex_count()) break;  // nothing matched
    h.graphs.push_back(contract_matching(*current, m));
    h.maps.push_back(std::move(m.map));
    current = &h.graphs.back();
    if (static_cast<double>(m.coarse_count) > (1.0 - options.min_shrink) * n) break;
  }
  return h;
}

}  // namespace madd::detail
