#pragma once
// Wall-clock time for the CLI's summaries and reports (madd and madd-mpi).
#include <chrono>

namespace madd::cli {

// Seconds from `start` to now, on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace madd::cli
