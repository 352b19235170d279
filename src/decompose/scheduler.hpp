#pragma once
// The scheduler of the N-way driver: one round (Algorithm 4, Sec. 5): the splits of every
// face planned for this round are computed in parallel from one snapshot of
// the subdivision and committed in task order, each as soon as it and every
// task before it are computed, so that the serial commits overlap the
// remaining parallel work. Results depend on the snapshot only, never on the
// thread count or on timing.
#include <cstdint>
#include <functional>
#include <span>

#include "madd/error.hpp"
#include "kernel/resource_limits.hpp"
#include "split/split.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct RoundTask {
  std::uint32_t face = 0;
  std::uint32_t plan = 2;  // final subdomains the face will become
  FaceDensity density;
};

// Calls commit(i, result) for i = 0, 1, ... in order, on the calling thread.
// `snapshot` is only read (by every thread), so commit must write elsewhere.
// An error of task i (or of its commit) is rethrown once every thread has
// stopped; tasks after it are not committed, so failures are deterministic.
// A task whose face has no valid separator (DecompositionError) is not an
// error of the round: failed(i, error) is called in its place, in the same
// order, and the round goes on. Any other error stops the round.
using CommitFn = std::function<void(std::size_t task, const SplitResult& result)>;
using FailFn = std::function<void(std::size_t task, const DecompositionError& error)>;
void run_round(const Subdivision& snapshot, std::span<const RoundTask> tasks, const SplitOptions& options,
               unsigned threads, const ResourceGuard& guard, const CommitFn& commit, const FailFn& failed);

}  // namespace madd::detail
