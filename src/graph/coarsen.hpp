#pragma once
// Coarsening by heavy-edge matching (Karypis & Kumar 1998, "HEM"): the
// multilevel hierarchy is a list of coarse graphs plus, per level, the array
// mapping each finer vertex to its coarse vertex (no pointer graphs).
#include <cstdint>
#include <vector>

#include "graph/graph_detail.hpp"
#include "madd/graph.hpp"

namespace madd::detail {

struct CoarsenOptions {
  std::uint32_t coarsen_to = 100;  // stop at about this many vertices
  double min_shrink = 0.10;        // stop when a level shrinks by less than this
  bool sorted_heavy_edge = false;  // visit by heaviest incident edge, not at random
};

// Level i + 1 is graphs[i]; maps[i][v] is the vertex of level i + 1 that
// vertex v of level i collapsed into (level 0 is the caller's graph).
struct Hierarchy {
  std::vector<Graph> graphs;
  std::vector<std::vector<std::uint32_t>> maps;
  std::size_t depth() const noexcept { return graphs.size(); }
};

struct Matching {
  std::vector<std::uint32_t> map;   // fine vertex -> coarse vertex
  std::vector<std::uint32_t> mate;  // partner, or the vertex itself when unmatched
  std::uint32_t coarse_count = 0;
};

// contract() specialised to a matching: coarse vertices are visited in
// fine order, so memory is read nearly sequentially.
Graph contract_matching(const Graph& graph, const Matching& matching);

// One round of heavy-edge matching: each unmatched vertex (visited in a
// seeded, locally shuffled order, or by heaviest edge) pairs with the unmatched
// neighbour across its heaviest edge, provided the pair weighs at most
// `max_vertex_weight` (keeps coarse vertices small enough to balance).
Matching heavy_edge_matching(const Graph& graph, SplitMix64& rng, bool sorted, double max_vertex_weight);

// Coarsens `graph` until it has about options.coarsen_to vertices or stalls.
Hierarchy coarsen(const Graph& graph, SplitMix64& rng, const CoarsenOptions& options);

}  // namespace madd::detail
