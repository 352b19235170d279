#pragma once
// Running independent tasks on a few threads: the per-subdomain stages
// (refinement, the work estimate, the MPI shares) and the decomposition's
// levels. Each task writes only its own slot of a result, so the outcome is
// the same for any thread count.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
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
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace madd::detail
