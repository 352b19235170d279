#pragma once
// Internal graph helpers shared by the bisector, the K-way driver and the
// METIS reader. Not part of the public API.
#include <cstdint>
#include <span>
#include <vector>

#include "madd/graph.hpp"

namespace madd::detail {

inline constexpr std::uint32_t no_vertex = 0xffffffffu;

// Component id per vertex of the subgraph induced by edges whose endpoints
// share the same side (side == nullptr: the whole graph). Iterative BFS.
struct Components {
  std::vector<std::uint32_t> label;  // per vertex
  std::uint32_t count = 0;
};
Components connected_components(const Graph& graph, const std::uint8_t* side = nullptr);

bool is_connected(const Graph& graph);

// Sum of the weights of edges whose endpoints lie on different sides.
double cut_weight(const Graph& graph, std::span<const std::uint8_t> side);

// Collapses vertices with the same `map` value (in [0, coarse_count)) into one
// vertex: vertex weights add, parallel edges merge with summed weights, edges
// inside a group vanish. Deterministic (neighbour order follows first sight).
Graph contract(const Graph& graph, std::span<const std::uint32_t> map, std::uint32_t coarse_count);

// Appends fine vertex x's edges to the coarse row being built for coarse
// vertex c (whose first entry is at `row_begin`): neighbours map through `map`,
// edges inside c vanish and parallel edges merge with summed weights. `slot`
// (one entry per coarse vertex, initially no_vertex) remembers where each
// neighbour sits; entries before row_begin are stale rows and are ignored.
inline void append_merged_edges(const Graph& graph, std::span<const std::uint32_t> map, std::uint32_t x,
                                std::uint32_t c, std::uint32_t row_begin, std::vector<std::uint32_t>& slot,
                                Graph& coarse) {
  for (std::uint32_t i = graph.offsets[x]; i < graph.offsets[x + 1]; ++i) {
    const std::uint32_t cu = map[graph.adjacency[i]];
    if (cu == c) continue;
    if (slot[cu] != no_vertex && slot[cu] >= row_begin) {
      coarse.edge_weights[slot[cu]] += graph.edge_weights[i];
      continue;
    }
    slot[cu] = static_cast<std::uint32_t>(coarse.adjacency.size());
    coarse.adjacency.push_back(cu);
    coarse.edge_weights.push_back(graph.edge_weights[i]);
  }
}

// The subgraph induced by `vertices` (renumbered 0..size-1 in that order).
Graph induced_subgraph(const Graph& graph, std::span<const std::uint32_t> vertices);

// Proves cheaply that taking vertex v off its side leaves that side connected:
// a BFS inside the side, avoiding v, must reach all of v's same-side
// neighbours within `budget` visited vertices. Conservative (false when
// unsure); false when v has no same-side neighbour.
class RemovalGuard {
public:
  explicit RemovalGuard(std::size_t vertex_count) : stamp_(vertex_count, 0) {}
  bool removable(const Graph& graph, std::span<const std::uint8_t> side, std::uint32_t v, std::size_t budget = 400);

private:
  std::vector<std::uint32_t> stamp_, queue_;
  std::uint32_t clock_ = 0;
};

// True when each side induces a connected, non-empty subgraph.
bool sides_connected(const Graph& graph, std::span<const std::uint8_t> side);

// splitmix64 (Steele, Lea, Flood 2014): a fixed, portable generator, so a seed
// gives the same bisection on every standard library.
class SplitMix64 {
public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n) for n > 0 (Lemire's multiply-shift; the tiny bias is irrelevant here).
  std::uint32_t below(std::uint32_t n) noexcept {
    return static_cast<std::uint32_t>(((next() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
  }

private:
  std::uint64_t state_;
};

// A random permutation of 0..n-1 (Fisher-Yates with SplitMix64).
std::vector<std::uint32_t> random_permutation(std::uint32_t n, SplitMix64& rng);

}  // namespace madd::detail
