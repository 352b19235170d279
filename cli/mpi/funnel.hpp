#pragma once
// MPI calls asked for by a helper thread and made by the main thread.
//
// madd-mpi starts meshing its share on a helper thread while the main thread
// is still in MPI_Init_thread (docs/mpi.md, "Start-up"): with
// MPI_THREAD_FUNNELED only the main thread may call MPI, so the helper's
// exchanges between refinement rounds go through a Funnel. The helper's
// call() waits until the main thread, once MPI has started and the ranks
// have agreed to go on this way, runs the job in serve(); or until the main
// thread closes the funnel, when call() throws Funnel::Closed and the helper
// unwinds (the ranks then mesh the usual way, after MPI_Init).
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>

namespace madd::mpi {

class Funnel {
public:
  // What call() throws once the funnel is closed.
  struct Closed : std::runtime_error {
    Closed() : std::runtime_error("the MPI funnel was closed") {}
  };

  // On the helper: has the main thread run `job`, and returns when it has
  // (rethrowing what it threw); throws Closed when the funnel is or becomes
  // closed before the job runs. One job at a time (one helper).
  void call(const std::function<void()>& job);

  // On the helper, last: it will ask for nothing more (serve() returns).
  void finish();

  // On the main thread: runs the helper's jobs as they come, until finish().
  void serve();

  // On the main thread: refuses every job, waiting or to come.
  void close();

private:
  std::mutex mutex_;
  std::condition_variable changed_;
  const std::function<void()>* job_ = nullptr;  // the waiting job, if any
  std::exception_ptr error_;                    // what the last job threw
  bool ran_ = false;                            // the waiting job has run
  bool closed_ = false;
  bool finished_ = false;
};

}  // namespace madd::mpi
