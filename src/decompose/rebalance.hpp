#pragma once
// Balance repair after the N-way driver (C3; our extension of Sec. 5, not in
// the paper). A split that cannot be even leaves one side larger than its
// share, and on the last levels that side is a final subdomain: on real
// archipelagos the largest subdomain reached 1.6 x the mean. The repair takes
// the largest subdomain, merges it with a smaller neighbour and splits the
// union again in two (the same split, Sec. 4, with every rule of Phi0),
// keeping the result only when every new part is smaller than the subdomain it
// started from and the separators are not much longer. The number of
// subdomains never changes.
#include <cstdint>
#include <functional>

#include "kernel/resource_limits.hpp"
#include "split/split.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct RebalanceOptions {
  // Subdomains larger than target x the mean area are repaired.
  double target = 1.2;
  // Neighbours tried for one subdomain, the smallest first.
  std::uint32_t partners = 3;
  // A repair must make the largest of the new parts at least this much smaller.
  double min_gain = 0.01;
  // ... and may add at most this x sqrt(mean area) of separator length (C2):
  // on the comb at N = 16 the best-balanced union would add 5 x sqrt(mean
  // area) (12% more separator in all); on the real coastlines the repairs add
  // a median of 0 and at most 1.3 x sqrt(mean area) before this bound.
  double max_added_separator = 1.0;
  // The unions tried for one subdomain are tried this many at a time, each
  // on its own copy (0: one per core); the repair kept is the one a single
  // thread trying them in order keeps.
  unsigned threads = 1;
};

// What rebalancing balances: each face's weight, and the density a split of
// a face aims to halve. Unset: the face areas, and uniform splits.
struct FaceMeasure {
  std::function<double(const Subdivision&, std::uint32_t face)> weight;
  std::function<FaceDensity(const Subdivision&, std::uint32_t face)> density;
};

// Repairs the largest subdomains of `sub` (by `measure`: areas by default,
// graded weights of background samples for madd mesh's balance by work)
// until every one is within target x the mean or none can be improved.
// Returns the number of repairs kept. Deterministic: one repair at a time, in
// a fixed order, the same for any thread count. `measure` is called from
// several threads at once when options.threads != 1.
std::uint32_t rebalance(Subdivision& sub, const SplitOptions& split_options, const ResourceGuard& guard,
                        const RebalanceOptions& options = {}, const FaceMeasure& measure = {});

}  // namespace madd::detail
