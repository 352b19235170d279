// The public bisection entry point: input checks, keep-together contraction,
// the multilevel bisector, connectivity repair, and the independent verifier.
#include "madd/bisect.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "graph/bisect_detail.hpp"

namespace madd {

namespace {

[[noreturn]] void reject(InputProblem problem, const char* message, std::vector<std::int64_t> ids = {}) {
  throw InvalidInputError(problem, message, std::move(ids));
}

// Checked once on entry (docs/design.md, "Errors"); the stages below only assert.
void check_input(const Graph& g, const BisectOptions& o) {
  const std::size_t n = g.vertex_count();
  if (!g.offsets.empty() && g.offsets.front() != 0) reject(InputProblem::other, "graph offsets must start at 0");
  if (g.vertex_weights.size() != n) reject(InputProblem::other, "graph needs one vertex weight per vertex");
  if (g.edge_weights.size() != g.adjacency.size() ||
      (n == 0 ? !g.adjacency.empty() : g.offsets[n] != g.adjacency.size()))
    reject(InputProblem::other, "graph adjacency and edge weights disagree with the offsets");
  for (std::size_t v = 0; v < n; ++v) {
    if (g.offsets[v] > g.offsets[v + 1])
      reject(InputProblem::other, "graph offsets decrease", {static_cast<std::int64_t>(v)});
    if (!(std::isfinite(g.vertex_weights[v]) && g.vertex_weights[v] >= 0.0))
      reject(InputProblem::bad_weight, "vertex weight must be finite and non-negative", {static_cast<std::int64_t>(v)});
  }
  for (std::size_t i = 0; i < g.adjacency.size(); ++i) {
    if (g.adjacency[i] >= n) reject(InputProblem::other, "neighbour index out of range", {g.adjacency[i]});
    if (!(std::isfinite(g.edge_weights[i]) && g.edge_weights[i] >= 0.0))
      reject(InputProblem::bad_weight, "edge weight must be finite and non-negative", {static_cast<std::int64_t>(i)});
  }
  check_options(o);
  for (const auto& [a, b] : o.keep_together)
    if (a >= n || b >= n) reject(InputProblem::other, "keep_together vertex out of range", {a, b});
}

}  // namespace

void check_options(const BisectOptions& o) {
  if (!(o.target_fraction > 0.0 && o.target_fraction < 1.0))
    throw OptionError("target_fraction", "must lie strictly between 0 and 1");
  if (!(std::isfinite(o.balance_tolerance) && o.balance_tolerance >= 0.0))
    throw OptionError("balance_tolerance", "must be a finite number >= 0");
  if (o.refinement_passes < 0) throw OptionError("refinement_passes", "must be >= 0");
}

namespace {

// Union-find over the keep_together pairs; returns each vertex's group id,
// numbered in order of first vertex, and the group count.
std::vector<std::uint32_t> group_pairs(std::uint32_t n, const BisectOptions& o, std::uint32_t& groups) {
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [a, b] : o.keep_together) {
    const std::uint32_t ra = find(a), rb = find(b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<std::uint32_t> id(n, detail::no_vertex), map(n);
  groups = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t r = find(v);
    if (id[r] == detail::no_vertex) id[r] = groups++;
    map[v] = id[r];
  }
  return map;
}

std::vector<std::uint8_t> bisect_work_graph(const Graph& g, const BisectOptions& o) {
  const auto n = static_cast<std::uint32_t>(g.vertex_count());
  if (n < 2) return std::vector<std::uint8_t>(n, 0);
  detail::SplitMix64 rng(o.seed);
  const bool connect = o.connected && detail::is_connected(g);
  std::vector<std::uint8_t> side = detail::multilevel_bisect(g, o, rng, connect);
  if (connect && !detail::sides_connected(g, side)) {  // a safety net: refine_level already repaired
    const double total = std::accumulate(g.vertex_weights.begin(), g.vertex_weights.end(), 0.0);
    detail::repair_connectivity(g, side, detail::make_balance(total, o.target_fraction, o.balance_tolerance));
  }
  return side;
}

}  // namespace

Bisection bisect(const Graph& graph, const BisectOptions& options) {
  check_input(graph, options);
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  Bisection result;
  if (options.keep_together.empty()) {
    result.side = bisect_work_graph(graph, options);
  } else {
    // Contract each keep-together group to one vertex, bisect, project back:
    // a group can then never be split.
    std::uint32_t groups = 0;
    const std::vector<std::uint32_t> map = group_pairs(n, options, groups);
    const Graph work = detail::contract(graph, map, groups);
    const std::vector<std::uint8_t> work_side = bisect_work_graph(work, options);
    result.side.resize(n);
    for (std::uint32_t v = 0; v < n; ++v) result.side[v] = work_side[map[v]];
  }
  result.cut = detail::cut_weight(graph, result.side);
  const detail::Components comps = detail::connected_components(graph, result.side.data());
  std::uint32_t pieces[2] = {0, 0};
  std::vector<std::uint8_t> counted(comps.count, 0);
  for (std::uint32_t v = 0; v < n; ++v) {
    result.weight[result.side[v]] += graph.vertex_weights[v];
    if (!counted[comps.label[v]]) {
      counted[comps.label[v]] = 1;
      ++pieces[result.side[v]];
    }
  }
  result.connected[0] = pieces[0] <= 1;
  result.connected[1] = pieces[1] <= 1;
  return result;
}

Verification verify_bisection(const Graph& graph, const Bisection& bisection) {
  Verification check;
  const std::size_t n = graph.vertex_count();
  if (bisection.side.size() != n) {
    check.add("side has " + std::to_string(bisection.side.size()) + " entries for " + std::to_string(n) + " vertices");
    return check;
  }
  double weight[2] = {0.0, 0.0};
  for (std::size_t v = 0; v < n; ++v) {
    if (bisection.side[v] > 1) {
      check.add("vertex " + std::to_string(v) + " has side " + std::to_string(bisection.side[v]));
      return check;
    }
    weight[bisection.side[v]] += graph.vertex_weights[v];
  }
  // Independent recount: every stored edge direction, halved.
  double cut2 = 0.0, total_edge = 0.0, total_vertex = weight[0] + weight[1];
  for (std::size_t u = 0; u < n; ++u) {
    for (std::uint32_t i = graph.offsets[u]; i < graph.offsets[u + 1]; ++i) {
      total_edge += graph.edge_weights[i];
      if (bisection.side[u] != bisection.side[graph.adjacency[i]]) cut2 += graph.edge_weights[i];
    }
  }
  const double cut = 0.5 * cut2;
  if (std::abs(cut - bisection.cut) > 1e-9 * std::max(total_edge, 1.0))
    check.add("cut is " + std::to_string(cut) + ", bisection claims " + std::to_string(bisection.cut));
  for (int s = 0; s < 2; ++s) {
    if (std::abs(weight[s] - bisection.weight[s]) > 1e-9 * std::max(total_vertex, 1.0))
      check.add("side " + std::to_string(s) + " weighs " + std::to_string(weight[s]) + ", bisection claims " +
                std::to_string(bisection.weight[s]));
  }
  // Connectivity by a plain BFS per side from its first vertex.
  for (std::uint8_t s = 0; s < 2; ++s) {
    std::vector<std::uint8_t> seen(n, 0);
    std::vector<std::uint32_t> stack;
    std::size_t members = 0, reached = 0;
    for (std::size_t v = 0; v < n; ++v) {
      if (bisection.side[v] != s) continue;
      if (members++ == 0) {
        stack.push_back(static_cast<std::uint32_t>(v));
        seen[v] = 1;
      }
    }
    while (!stack.empty()) {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      ++reached;
      for (std::uint32_t i = graph.offsets[u]; i < graph.offsets[u + 1]; ++i) {
        const std::uint32_t v = graph.adjacency[i];
        if (bisection.side[v] == s && !seen[v]) {
          seen[v] = 1;
          stack.push_back(v);
        }
      }
    }
    const bool connected = reached == members;
    if (connected != bisection.connected[s])
      check.add("side " + std::to_string(s) + (connected ? " is connected" : " is not connected") +
                ", bisection claims otherwise");
  }
  return check;
}

}  // namespace madd
