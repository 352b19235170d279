#pragma once
// Resource limits of one decompose() call (DecomposeOptions::time_limit_seconds and
// DecomposeOptions::max_memory_bytes): checked between splits and between the
// refinement rounds of one split.
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace madd::detail {

// What ResourceGuard enforces (0 = no limit), and the run's size for its message.
struct Limits {
  double time_limit_seconds = 0.0;
  std::size_t max_memory_bytes = 0;
  std::uint32_t subdomains = 0;  // N, to say "k of N subdomains done"
};

// Resident set size of this process in bytes, read from /proc/self/statm;
// 0 when it cannot be read (then the memory limit is not enforced).
std::size_t resident_bytes() noexcept;

// Started when decompose() starts; check() throws LimitError once the time or
// the resident memory exceeds the limit. Cheap (one clock read, one small
// /proc read when a memory limit is set), so it may run once per split.
class ResourceGuard {
public:
  explicit ResourceGuard(const Limits& limits);
  // `done`: subdomains finished so far, for the message.
  void check(std::size_t done) const;

private:
  std::chrono::steady_clock::time_point start_;
  double time_limit_;
  std::size_t memory_limit_;
  std::uint32_t subdomains_;
};

}  // namespace madd::detail
