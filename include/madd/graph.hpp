#pragma once
// A compact undirected weighted graph in CSR form (METIS graph files:
// madd/metis_io.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace madd {

// Undirected graph: every edge {u,v} is stored twice, once in u's list and
// once in v's, with the same weight. Weights are real-valued (areas, lengths).
struct Graph {
  std::vector<std::uint32_t> offsets;  // vertex_count() + 1 entries
  std::vector<std::uint32_t> adjacency;
  std::vector<double> vertex_weights;  // one per vertex
  std::vector<double> edge_weights;    // parallel to adjacency

  std::size_t vertex_count() const noexcept { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::size_t edge_count() const noexcept { return adjacency.size() / 2; }
  friend bool operator==(const Graph&, const Graph&) = default;
};

struct WeightedEdge {
  std::uint32_t u = 0;
  std::uint32_t v = 0;
  double weight = 1.0;
};

// Builds a Graph from an edge list; parallel edges are merged (weights summed)
// and self-loops dropped. Precondition: every endpoint < vertex_weights.size().
Graph make_graph(std::vector<double> vertex_weights, const std::vector<WeightedEdge>& edges);

}  // namespace madd
