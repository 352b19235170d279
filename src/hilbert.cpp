#include "hilbert.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace madd::detail {

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) noexcept {
  // Classic quadrant descent: at each level pick the quadrant's position on the
  // curve, then rotate/reflect the remaining coordinates into its frame.
  std::uint32_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1u : 0u;
    const std::uint32_t ry = (y & s) ? 1u : 0u;
    d += s * s * ((3u * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
    x &= s - 1;
    y &= s - 1;
  }
  return d;
}

namespace {

// A fixed mixing function (splitmix64 finaliser): BRIO round membership is
// pseudo-random but deterministic, so equal inputs give identical output.
std::uint64_t mix(std::uint64_t z) noexcept {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::uint32_t quantise(double v, double lo, double scale) noexcept {
  const double q = (v - lo) * scale;
  if (!(q > 0.0)) return 0;
  if (q >= 65535.0) return 65535;
  return static_cast<std::uint32_t>(q);
}

struct Item {
  std::uint64_t key;
  std::uint32_t index;
};

// Stable LSD radix sort on the low `bits` bits of the key, 11 bits a pass;
// passes whose digit is constant are skipped.
void radix_sort(std::vector<Item>& items, int bits) {
  std::vector<Item> tmp(items.size());
  std::vector<std::uint32_t> count(2049);
  for (int shift = 0; shift < bits; shift += 11) {
    std::fill(count.begin(), count.end(), 0u);
    for (const Item& v : items) ++count[((v.key >> shift) & 2047u) + 1];
    if (*std::max_element(count.begin(), count.end()) == items.size()) continue;
    for (int i = 0; i < 2048; ++i) count[i + 1] += count[i];
    for (const Item& v : items) tmp[count[(v.key >> shift) & 2047u]++] = v;
    items.swap(tmp);
  }
}

} // namespace

std::vector<std::uint32_t> insertion_order(std::span<const Point> points) {
  const auto n = static_cast<std::uint32_t>(points.size());
  double xlo = INFINITY, ylo = INFINITY, xhi = -INFINITY, yhi = -INFINITY;
  for (const Point& p : points) {
    xlo = std::min(xlo, p.x);
    xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y);
    yhi = std::max(yhi, p.y);
  }
  const double extent = std::max(xhi - xlo, yhi - ylo);
  const double scale = extent > 0.0 && std::isfinite(extent) ? 65535.0 / extent : 0.0;
  // Rounds: level k holds about n / 2^(k+1) points; everything at or above
  // max_level forms the first round, kept at >= ~128 points.
  int max_level = 0;
  while ((n >> (max_level + 8)) > 0 && max_level < 20) ++max_level;
  // Key layout: [round:5][hilbert:32]; ties keep index order (stable sort).
  std::vector<Item> items(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const int level = std::min(std::countr_one(mix(i)), max_level);
    const auto round = static_cast<std::uint64_t>(max_level - level);
    const std::uint64_t h = hilbert_index(quantise(points[i].x, xlo, scale), quantise(points[i].y, ylo, scale));
    items[i] = {(round << 32) | h, i};
  }
  if (n < 512) {
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
  } else {
    radix_sort(items, 37);
  }
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = items[i].index;
  return order;
}

} // namespace madd::detail
