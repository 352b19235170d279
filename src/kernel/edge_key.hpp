#pragma once
// The key of the undirected edge {a, b} of two 32-bit vertex ids, for hash
// sets and maps of edges: the same for (a, b) and (b, a).
#include <algorithm>
#include <cstdint>

namespace madd::detail {

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

}  // namespace madd::detail
