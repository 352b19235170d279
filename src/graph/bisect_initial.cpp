// Initial bisection of the coarsest graph and the multilevel driver.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "graph/bisect_detail.hpp"
#include "graph/coarsen.hpp"

namespace madd::detail {

Balance make_balance(double total, double target_fraction, double balance_tolerance, double slack) {
  Balance b;
  b.target[0] = total * target_fraction;
  b.target[1] = total - b.target[0];
  for (int s = 0; s < 2; ++s) b.max[s] = b.target[s] * (1.0 + balance_tolerance) + slack;
  return b;
}

namespace {

double vertex_total(const Graph& g) { return std::accumulate(g.vertex_weights.begin(), g.vertex_weights.end(), 0.0); }

// Grows side 0 from `seed`; when the frontier runs dry (disconnected graph)
// the next untouched vertex of `order` restarts it.
std::vector<std::uint8_t> grow_from(const Graph& g, std::uint32_t seed, const std::vector<std::uint32_t>& order,
                                    double target0, GainHeap& heap) {
  const auto n = static_cast<std::uint32_t>(g.vertex_count());
  std::vector<std::uint8_t> side(n, 1);
  std::vector<double> gain(n, 0.0);
  for (std::uint32_t v = 0; v < n; ++v) {
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) gain[v] -= g.edge_weights[i];
  }
  heap.clear();
  heap.push(seed, gain[seed]);
  double w0 = 0.0;
  std::uint32_t moved = 0;
  std::size_t next = 0;
  while (moved + 1 < n) {
    if (heap.empty()) {
      while (side[order[next]] == 0) ++next;
      heap.push(order[next], gain[order[next]]);
    }
    const std::uint32_t v = heap.top();
    const double after = w0 + g.vertex_weights[v];
    if (moved > 0 && after > target0 && after - target0 > target0 - w0) break;
    heap.remove(v);
    side[v] = 0;
    w0 = after;
    ++moved;
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
      const std::uint32_t u = g.adjacency[i];
      if (side[u] == 0) continue;
      gain[u] += 2.0 * g.edge_weights[i];
      if (heap.contains(u)) heap.update(u, gain[u]);
      else heap.push(u, gain[u]);
    }
    if (w0 >= target0) break;
  }
  return side;
}

}  // namespace

void refine_level(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance, int passes,
                  bool connect) {
  fm_refine(graph, side, balance, passes);
  if (!connect || sides_connected(graph, side)) return;
  repair_connectivity(graph, side, balance);
  fm_refine(graph, side, balance, passes, true);
}

std::vector<std::uint8_t> grow_bisection(const Graph& graph, const Balance& balance, SplitMix64& rng, int tries,
                                         int passes, bool connect) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  if (n < 2) return std::vector<std::uint8_t>(n, 0);
  const std::vector<std::uint32_t> order = random_permutation(n, rng);
  GainHeap heap;
  heap.reset(n);
  std::vector<std::uint8_t> best;
  double best_infeas = 0.0, best_cut = 0.0;
  for (int t = 0; t < std::max(tries, 1); ++t) {
    const std::uint32_t seed = order[static_cast<std::uint32_t>(t) % n];
    std::vector<std::uint8_t> side = grow_from(graph, seed, order, balance.target[0], heap);
    refine_level(graph, side, balance, passes, connect);
    double w[2] = {0.0, 0.0};
    for (std::uint32_t v = 0; v < n; ++v) w[side[v]] += graph.vertex_weights[v];
    if (std::find(side.begin(), side.end(), 0) == side.end() || std::find(side.begin(), side.end(), 1) == side.end())
      continue;
    const double infeas = balance.infeasibility(w);
    const double cut = cut_weight(graph, side);
    if (best.empty() || infeas < best_infeas || (infeas == best_infeas && cut < best_cut)) {
      best = std::move(side);
      best_infeas = infeas;
      best_cut = cut;
    }
  }
  if (best.empty()) {  // every try emptied a side: fall back to a plain split
    best.assign(n, 1);
    best[order[0]] = 0;
  }
  return best;
}

std::vector<std::uint8_t> multilevel_bisect(const Graph& graph, const BisectOptions& options, SplitMix64& rng,
                                            bool connect) {
  CoarsenOptions co;
  co.sorted_heavy_edge = options.sorted_heavy_edge;
  const Hierarchy h = coarsen(graph, rng, co);
  const double total = vertex_total(graph);
  // Coarse levels get METIS's extra slack of one average vertex weight: exact
  // balance is impossible with heavy vertices and finer levels restore it.
  auto level_balance = [&](std::size_t level) {
    const Graph& g = level == 0 ? graph : h.graphs[level - 1];
    const double slack = level == 0 ? 0.0 : total / static_cast<double>(std::max<std::size_t>(g.vertex_count(), 1));
    return make_balance(total, options.target_fraction, options.balance_tolerance, slack);
  };
  const std::size_t depth = h.depth();
  const Graph& coarsest = depth == 0 ? graph : h.graphs.back();
  const int passes = std::max(options.refinement_passes, 1);
  std::vector<std::uint8_t> side = grow_bisection(coarsest, level_balance(depth), rng, 8, passes, connect);
  for (std::size_t level = depth; level-- > 0;) {
    const Graph& fine = level == 0 ? graph : h.graphs[level - 1];
    const std::vector<std::uint32_t>& map = h.maps[level];
    std::vector<std::uint8_t> projected(fine.vertex_count());
    for (std::size_t v = 0; v < projected.size(); ++v) projected[v] = side[map[v]];
    side = std::move(projected);
    refine_level(fine, side, level_balance(level), options.refinement_passes, connect);
  }
  return side;
}

}  // namespace madd::detail
