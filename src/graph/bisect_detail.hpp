#pragma once
// Internal stages of the multilevel bisector (bisect.cpp drives them).
#include <cstdint>
#include <vector>

#include "graph/fm.hpp"
#include "graph/graph_detail.hpp"
#include "madd/bisect.hpp"

namespace madd::detail {

// Greedy graph growing (GGGP, Karypis & Kumar 1998): from each of `tries`
// seeds grow side 0 by the best-gain frontier vertex until it reaches its
// target weight, refine with FM, keep the best by (infeasibility, cut).
// Both sides are non-empty when the graph has two or more vertices.
// With `connect` (the graph is connected and both sides must be), every try
// is repaired and refined by connectivity-preserving FM before it competes.
std::vector<std::uint8_t> grow_bisection(const Graph& graph, const Balance& balance, SplitMix64& rng, int tries,
                                         int passes, bool connect);

// Coarsen, grow on the coarsest graph, then project and FM-refine level by
// level (Karypis & Kumar's multilevel scheme). With `connect`, each level's
// result is repaired when FM disconnected a side, then refined again by
// connectivity-preserving FM, so both sides end connected.
std::vector<std::uint8_t> multilevel_bisect(const Graph& graph, const BisectOptions& options, SplitMix64& rng,
                                            bool connect);

// FM refinement followed, with `connect`, by repair and connected FM.
void refine_level(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance, int passes,
                  bool connect);

// Makes both sides connected on a connected graph: flips stray components to
// the other side (which always joins them to that side), then moves boundary
// vertices off an overweight side only when a bounded local search proves
// the side stays connected. Connectivity wins over balance.
void repair_connectivity(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance);

// The balance constraint for a graph of total weight `total`.
Balance make_balance(double total, double target_fraction, double balance_tolerance, double slack = 0.0);

}  // namespace madd::detail
