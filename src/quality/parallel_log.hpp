#pragma once
// A check run in parts on several threads that reports as if it had run in
// one pass: each part logs into a list of its own, and the lists join the
// run's log in part order. A check whose single pass visits [0, count) in
// increasing order and logs as it goes gives the same report (the same
// problems, in the same order, the same count) for any thread count.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "kernel/threads.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

// body(part, begin, end, part_log) for `parts` consecutive ranges of about
// equal length covering [0, count) (at least one part; fewer when count is
// smaller), on `threads` threads.
template <typename Body>
void log_in_parts(std::size_t count, std::size_t parts, unsigned threads, ProblemLog& log, const Body& body) {
  parts = std::clamp<std::size_t>(parts, 1, std::max<std::size_t>(count, 1));
  std::vector<Verification> found(parts);
  std::vector<std::size_t> counted(parts, 0);
  for_each_on_threads(parts, threads, [&](std::size_t i) {
    ProblemLog part_log(found[i]);
    body(i, count * i / parts, count * (i + 1) / parts, part_log);
    counted[i] = part_log.count();
  });
  for (std::size_t i = 0; i < parts; ++i) log.absorb(std::move(found[i].problems), counted[i]);
}

}  // namespace madd::detail
