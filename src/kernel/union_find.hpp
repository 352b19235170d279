#pragma once
// The find of a union-find forest over vertex ids.
#include <cstdint>
#include <vector>

namespace madd::detail {

// The root of v's tree, halving the path on the way (every vertex passed
// points to its grandparent), so that repeated finds stay near constant time.
inline std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) noexcept {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace madd::detail
