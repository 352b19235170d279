#pragma once
// Our own multilevel graph bisector: heavy-edge matching, greedy graph
// growing, boundary Fiduccia-Mattheyses refinement, connectivity repair.
//
// How it works (src/graph/coarsen.cpp, src/graph/bisect_initial.cpp,
// src/graph/fm.cpp, src/graph/bisect_connect.cpp):
// - Coarsening: heavy-edge matching in a seeded splitmix64 order (locally
//   shuffled blocks, for cache locality), no coarse vertex heavier than
//   1.5 W / 100; stops near 100 vertices or when a level shrinks < 10%. The
//   hierarchy is a list of coarse graphs plus fine->coarse maps.
// - Initial bisection: greedy graph growing from 8 seeds, each refined, best
//   kept by (balance violation, cut).
// - Refinement: boundary FM with rollback to the best prefix, at most
//   refinement_passes passes per level. Weights stay doubles; gains live in an
//   indexed binary max-heap with update-key (no integer scaling, so real
//   areas and lengths are used exactly as given).
// - Balance: side s may weigh at most target_s * (1 + balance_tolerance), with
//   target_0 = target_fraction * W (METIS's ubfactor semantics). Coarse levels
//   get one average vertex weight of extra slack.
// - Connectivity (options.connected on a connected graph): at every level, if
//   FM disconnected a side, stray components are flipped to the side they
//   touch, an overweight side sheds boundary vertices that a bounded BFS
//   proves removable, and FM runs again moving only such vertices.
// - keep_together: pairs are merged by union-find into one vertex before
//   bisecting and projected back, so they can never be split. Connectivity is
//   then guaranteed for the merged graph (exact when pairs are adjacent).
#include <cstdint>
#include <utility>
#include <vector>

#include "madd/error.hpp"
#include "madd/graph.hpp"

namespace madd {

struct BisectOptions {
  double target_fraction = 0.5;     // desired share of total vertex weight on side 0
  double balance_tolerance = 0.03;  // a side may weigh up to (1 + this) x its target (0.03 = 3%)
  std::uint64_t seed = 1;
  bool sorted_heavy_edge = false;  // visit vertices by heaviest edge instead of random order
  int refinement_passes = 8;       // FM passes per level (at most)
  bool connected = true;           // repair so both sides are connected when the graph is
  // Pairs of vertices that must end on the same side (e.g. both ends of an
  // edge that must not be cut; Sec. 4.3 of the MADD paper).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keep_together;
  friend bool operator==(const BisectOptions&, const BisectOptions&) = default;
};

// Throws OptionError on an option out of its range (bisect() calls it).
void check_options(const BisectOptions& options);

struct Bisection {
  std::vector<std::uint8_t> side;    // 0 or 1 per vertex
  double cut = 0.0;                  // total weight of edges between the sides
  double weight[2] = {0.0, 0.0};     // vertex weight on each side
  bool connected[2] = {true, true};  // each side induces a connected subgraph
  friend bool operator==(const Bisection&, const Bisection&) = default;
};

// Bisects `graph`. Deterministic for a given graph and options. When the graph
// is connected and options.connected, both sides are connected; if balance and
// connectivity conflict, connectivity wins and the achieved weights say so.
// Graphs with fewer than two vertices give all vertices side 0.
Bisection bisect(const Graph& graph, const BisectOptions& options = {});

// Recomputes cut, side weights and side connectivity from scratch and
// compares them with what `bisection` claims.
Verification verify_bisection(const Graph& graph, const Bisection& bisection);

// Part i of k: recursive bisection, side 0 taking floor(k/2) of the parts and
// floor(k/2)/k of the weight at each step (explicit work stack, no recursion).
struct PartitionOptions {
  double balance_tolerance = 0.03;  // per bisection level
  std::uint64_t seed = 1;
  bool connected = false;                                     // --contig
  int refinement_passes = BisectOptions{}.refinement_passes;  // per level of every bisection (--niter)
  friend bool operator==(const PartitionOptions&, const PartitionOptions&) = default;
};

// Throws OptionError on an option out of its range (partition() calls it).
void check_options(const PartitionOptions& options);

struct Partition {
  std::vector<std::uint32_t> part;  // 0..k-1 per vertex
  double cut = 0.0;
  std::vector<double> part_weights;
  friend bool operator==(const Partition&, const Partition&) = default;
};

// K-way partition by recursive bisection (the k > 2 mode of `madd partition`).
Partition partition(const Graph& graph, std::uint32_t k, const PartitionOptions& options = {});

}  // namespace madd
