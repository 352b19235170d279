#pragma once
// Running independent tasks on a few threads: the per-subdomain stages
// (refinement, the work estimate, the MPI shares) and the decomposition's
// levels. Each task writes only its own slot of a result, so the outcome is
// the same for any thread count.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace madd::detail {

// The threads to use for `tasks` tasks when `asked` were asked for (0: one
// per core), never more than there are tasks, at least one.
inline unsigned thread_count(unsigned asked, std::size_t tasks) {
  const unsigned n = asked != 0 ? asked : std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(n, std::max<std::size_t>(tasks, 1)));
}

// Runs body(id) for every id in [0, n): id 0 on the calling thread, the
// others on helper threads the process keeps parked between calls (made on
// first need, never more than the largest n asked for less one), and returns
// once all have returned; the first exception any body threw is rethrown
// then. Threads made afresh for every parallel step started, as often as
// not, on the core of the thread that made them, and shared it for the
// first few milliseconds while the other core idled (1-4 ms lost a step,
// some twenty steps a run: docs/performance.md, "Parked threads"); parked
// ones wake where they slept. A call made while the parked threads serve
// another (a nested step, or a second caller) gets threads of its own, as
// before.
void run_on_threads(unsigned n, const std::function<void(unsigned id)>& body);

// Runs body(i) for every i in [0, count) on thread_count(threads, count)
// threads, the calling thread one of them, tasks taken in order as threads
// free up; the first exception is rethrown once all have stopped (tasks not
// yet started are then skipped).
template <typename Body>
void for_each_on_threads(std::size_t count, unsigned threads, const Body& body) {
  const unsigned n = thread_count(threads, count);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < count && !failed.load();) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  if (n == 1) worker();
  else run_on_threads(n, [&](unsigned) { worker(); });
  if (error) std::rethrow_exception(error);
}

}  // namespace madd::detail
