// Resource limits (docs/hostile.md). Memory is measured, not estimated: the
// resident set size of the whole process, which over- rather than under-counts
// what decompose() itself holds, so the limit errs on the safe side.
#include "kernel/resource_limits.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

#include "madd/error.hpp"

namespace madd::detail {

std::size_t resident_bytes() noexcept {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  unsigned long long size = 0, resident = 0;
  const int n = std::fscanf(f, "%llu %llu", &size, &resident);
  std::fclose(f);
  const long page = ::sysconf(_SC_PAGESIZE);
  if (n != 2 || page <= 0) return 0;
  return static_cast<std::size_t>(resident) * static_cast<std::size_t>(page);
}

ResourceGuard::ResourceGuard(const Limits& limits)
    : start_(std::chrono::steady_clock::now()), time_limit_(limits.time_limit_seconds),
      memory_limit_(limits.max_memory_bytes), subdomains_(limits.subdomains) {
  if (!(time_limit_ >= 0.0)) {
    throw InvalidInputError(InputProblem::other, "the time limit must be >= 0 seconds (0 = none)");
  }
}

void ResourceGuard::check(std::size_t done) const {
  char buffer[200];
  if (time_limit_ > 0.0) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed > time_limit_) {
      std::snprintf(buffer, sizeof buffer,
                    "time limit of %g s reached after %.3g s (%zu of %u subdomains done); nothing was returned",
                    time_limit_, elapsed, done, subdomains_);
      throw LimitError(buffer);
    }
  }
  if (memory_limit_ > 0) {
    const std::size_t rss = resident_bytes();
    if (rss > memory_limit_) {
      std::snprintf(
          buffer, sizeof buffer,
          "memory limit of %.1f MB reached: %.1f MB resident (%zu of %u subdomains done); nothing was returned",
          static_cast<double>(memory_limit_) / 1048576.0, static_cast<double>(rss) / 1048576.0, done, subdomains_);
      throw LimitError(buffer);
    }
  }
}

}  // namespace madd::detail
