// Faulting in fresh pages on several threads (fresh_memory.hpp).
#include "kernel/fresh_memory.hpp"

#include <algorithm>
#include <cstdint>

#include "kernel/threads.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace madd::detail {

void fault_in_on_threads(void* data, std::size_t bytes, unsigned threads) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  // Below a few megabytes the threads cost more than the faults.
  constexpr std::size_t least = std::size_t{4} << 20;
  if (data == nullptr || bytes < least) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  // Whole pages inside the range, in shares that meet at 2 MiB boundaries
  // (each huge page faulted in by one thread).
  constexpr std::uintptr_t block = std::uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if (end <= begin) return;
  const std::uintptr_t first_block = begin & ~(block - 1);
  const std::size_t blocks = (end - first_block + block - 1) / block;
  const std::size_t shares = std::min<std::size_t>(blocks, 4 * std::size_t{thread_count(threads, blocks)});
  for_each_on_threads(shares, threads, [&](std::size_t i) {
    const std::uintptr_t from = std::max(begin, first_block + (i * blocks / shares) * block);
    const std::uintptr_t to = std::min(end, first_block + ((i + 1) * blocks / shares) * block);
    if (to > from) (void)::madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
#else
  (void)data;
  (void)bytes;
  (void)threads;
#endif
}

void release_free_memory() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

}  // namespace madd::detail
