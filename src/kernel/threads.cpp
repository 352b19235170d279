// The process's parked helper threads (kernel/threads.hpp, run_on_threads).
#include "kernel/threads.hpp"

#include <condition_variable>
#include <cstdint>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#endif

namespace madd::detail {

namespace {

// Helpers wait for a job, each takes the next id of it, runs the body and
// reports back; ids past the job's n send a helper back to sleep. One job
// at a time: `busy_` is claimed by the caller for the whole job.
class ParkedThreads {
public:
  // False, doing nothing, when another job holds the helpers.
  bool try_run(unsigned n, const std::function<void(unsigned)>& body) {
    bool expected = false;
    if (!busy_.compare_exchange_strong(expected, true)) return false;
    try {
      // One helper more than the job needs: the files' writer runs its
      // formatters beside the calling thread (J + 1 threads at -j J), and a
      // helper made at that moment started on a busy core, two formatters
      // sharing one CPU for 15 ms while the other idled (the pipe at -j 2);
      // made with the run's first job, it has its own core long before.
      while (helpers_ < n) {
        std::thread(&ParkedThreads::serve, this, generation()).detach();
        ++helpers_;
      }
    } catch (...) {  // no thread to be had: the caller runs the job another way
      busy_ = false;
      return false;
    }
    {
      const std::lock_guard lock(mutex_);
      body_ = &body;
      n_ = n;
      next_id_ = 1;
      pending_ = n - 1;
      error_ = nullptr;
      ++generation_;
    }
    wake_.notify_all();
    std::exception_ptr mine;
    try {
      body(0);
    } catch (...) {
      mine = std::current_exception();
    }
    std::exception_ptr theirs;
    {
      std::unique_lock lock(mutex_);
      finished_.wait(lock, [&] { return pending_ == 0; });
      body_ = nullptr;
      theirs = error_;
    }
    busy_ = false;
    if (mine) std::rethrow_exception(mine);
    if (theirs) std::rethrow_exception(theirs);
    return true;
  }

private:
  std::uint64_t generation() {
    const std::lock_guard lock(mutex_);
    return generation_;
  }

  // A helper's life: jobs after the one current when it was made.
  void serve(std::uint64_t seen) {
    for (;;) {
      const std::function<void(unsigned)>* body = nullptr;
      unsigned id = 0;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (body_ == nullptr || next_id_ >= n_) continue;
        body = body_;
        id = next_id_++;
      }
      std::exception_ptr error;
      try {
        (*body)(id);
      } catch (...) {
        error = std::current_exception();
      }
      {
        const std::lock_guard lock(mutex_);
        if (error && !error_) error_ = error;
        if (--pending_ == 0) finished_.notify_all();
      }
    }
  }

  std::atomic<bool> busy_{false};
  unsigned helpers_ = 0;  // only the job's caller (holding busy_) reads or adds
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  const std::function<void(unsigned)>* body_ = nullptr;
  unsigned n_ = 0, next_id_ = 1, pending_ = 0;
  std::uint64_t generation_ = 0;
  std::exception_ptr error_;
};

// The helpers live as long as the process (never destroyed: a helper may
// still be parked on the object when static destructors run). After fork()
// the child has none of them: it starts a fresh, empty set.
std::atomic<ParkedThreads*> parked{nullptr};

ParkedThreads& parked_threads() {
  static const bool once = [] {
    parked = new ParkedThreads;
#if defined(__unix__) || defined(__APPLE__)
    pthread_atfork(nullptr, nullptr, [] { parked = new ParkedThreads; });
#endif
    return true;
  }();
  (void)once;
  return *parked.load();
}

}  // namespace

void run_on_threads(unsigned n, const std::function<void(unsigned)>& body) {
  if (n <= 1) return body(0);
  if (parked_threads().try_run(n, body)) return;
  // The helpers are busy with another job (this one nested in it, or
  // another caller's): threads of its own.
  std::exception_ptr first;
  std::mutex first_mutex;
  const auto guarded = [&](unsigned id) {
    try {
      body(id);
    } catch (...) {
      const std::lock_guard lock(first_mutex);
      if (!first) first = std::current_exception();
    }
  };
  std::vector<std::thread> own;
  for (unsigned id = 1; id < n; ++id) own.emplace_back(guarded, id);
  guarded(0);
  for (std::thread& t : own) t.join();
  if (first) std::rethrow_exception(first);
}

}  // namespace madd::detail
