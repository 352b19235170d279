// MPI calls asked for by a helper thread and made by the main thread (funnel.hpp).
#include "funnel.hpp"

namespace madd::mpi {

void Funnel::call(const std::function<void()>& job) {
  std::unique_lock lock(mutex_);
  if (closed_) throw Closed();
  job_ = &job;
  ran_ = false;
  error_ = nullptr;
  changed_.notify_all();
  changed_.wait(lock, [&] { return ran_ || closed_; });
  job_ = nullptr;
  if (!ran_) throw Closed();
  if (error_) std::rethrow_exception(error_);
}

void Funnel::finish() {
  const std::lock_guard lock(mutex_);
  finished_ = true;
  changed_.notify_all();
}

void Funnel::serve() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return finished_ || (job_ != nullptr && !ran_); });
    if (job_ == nullptr || ran_) return;  // finished, nothing waiting
    const std::function<void()>& job = *job_;
    lock.unlock();
    std::exception_ptr error;
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    error_ = error;
    ran_ = true;
    changed_.notify_all();
  }
}

void Funnel::close() {
  const std::lock_guard lock(mutex_);
  closed_ = true;
  changed_.notify_all();
}

}  // namespace madd::mpi
