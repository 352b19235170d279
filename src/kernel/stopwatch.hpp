#pragma once
// Wall-clock laps for the per-phase times of a decomposition (docs/quality.md).
#include <chrono>

namespace madd::detail {

// Wall seconds since construction or the previous lap.
class Stopwatch {
public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace madd::detail
