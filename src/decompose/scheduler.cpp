// The scheduling of one round: worker threads take tasks in order from a
// shared counter; the calling thread commits finished results in task order
// and, while the next result is not ready, computes tasks itself.
#include "decompose/scheduler.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <vector>

#include "kernel/threads.hpp"

namespace madd::detail {

namespace {

class Round {
public:
  Round(const Subdivision& snapshot, std::span<const RoundTask> tasks, const SplitOptions& options,
        const ResourceGuard& guard)
      : snapshot_(snapshot), tasks_(tasks), options_(options), guard_(guard), faces_(snapshot.faces.size()),
        results_(tasks.size()), errors_(tasks.size()), done_(tasks.size(), 0) {}

  // Computes tasks until none is left or the round is stopped.
  void work() {
    while (!stop_.load(std::memory_order_relaxed) && compute_next()) {}
  }

  // Commits every task in order; computes tasks while waiting for the next one.
  void commit_all(const CommitFn& commit, const FailFn& failed) {
    try {
      for (std::size_t i = 0; i < tasks_.size(); ++i) {
        while (!is_done(i)) {
          if (!compute_next()) wait_for(i);
        }
        if (errors_[i]) {
          if (!report_unsplittable(i, failed)) std::rethrow_exception(errors_[i]);
          continue;
        }
        commit(i, results_[i]);
        results_[i] = SplitResult{};  // release the geometry early
      }
    } catch (...) {
      stop_ = true;
      throw;
    }
  }

private:
  // A face without a valid separator goes to `failed`; false for any other error.
  bool report_unsplittable(std::size_t i, const FailFn& failed) {
    try {
      std::rethrow_exception(errors_[i]);
    } catch (const DecompositionError& e) {
      failed(i, e);
      return true;
    } catch (...) {
      return false;
    }
  }

  // Takes the next uncomputed task and computes it; false when none is left.
  bool compute_next() {
    const std::size_t i = next_.fetch_add(1);
    if (i >= tasks_.size()) return false;
    try {
      guard_.check(faces_);  // limits are checked before every split
      const RoundTask& t = tasks_[i];
      results_[i] = compute_split(snapshot_, t.face, t.plan, options_, t.density, &guard_);
    } catch (...) {
      errors_[i] = std::current_exception();
    }
    {
      const std::lock_guard lock(mutex_);
      done_[i] = 1;
    }
    ready_.notify_all();
    return true;
  }

  bool is_done(std::size_t i) {
    const std::lock_guard lock(mutex_);
    return done_[i] != 0;
  }

  void wait_for(std::size_t i) {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return done_[i] != 0; });
  }

  const Subdivision& snapshot_;
  std::span<const RoundTask> tasks_;
  const SplitOptions& options_;
  const ResourceGuard& guard_;
  const std::size_t faces_;  // subdomains done when the round began (for limit messages)
  std::vector<SplitResult> results_;
  std::vector<std::exception_ptr> errors_;
  std::vector<char> done_;  // guarded by mutex_: set once the result or error is stored
  std::mutex mutex_;
  std::condition_variable ready_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
};

}  // namespace

void run_round(const Subdivision& snapshot, std::span<const RoundTask> tasks, const SplitOptions& options,
               unsigned threads, const ResourceGuard& guard, const CommitFn& commit, const FailFn& failed) {
  Round round(snapshot, tasks, options, guard);
  // The calling thread commits in order while the others split; all have
  // returned before `round` is destroyed.
  run_on_threads(std::max(threads, 1u), [&](unsigned id) {
    if (id == 0) round.commit_all(commit, failed);
    else round.work();
  });
}

}  // namespace madd::detail
