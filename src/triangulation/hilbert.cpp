#include "triangulation/hilbert.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "kernel/box.hpp"

namespace madd::detail {

namespace {

// The curve's orientation state: bit 0 = coordinates swapped, bit 1 =
// coordinates complemented. One level maps raw bits (bx, by) through the state
// to a quadrant, emits its position (0..3) on the curve and updates the state.
struct Level {
  std::uint32_t digit, state;
};

constexpr Level step(std::uint32_t state, std::uint32_t bx, std::uint32_t by) {
  std::uint32_t rx = bx ^ (state >> 1), ry = by ^ (state >> 1);
  if (state & 1u) {
    const std::uint32_t t = rx;
    rx = ry;
    ry = t;
  }
  const std::uint32_t digit = (3u * rx) ^ ry;
  if (ry == 0) state ^= rx == 1 ? 3u : 1u;
  return {digit, state};
}

// Two levels at a time: entry [state][xx yy] = 4 output bits | next state << 4.
struct Table {
  std::uint8_t entry[4][16];
};

constexpr Table make_table() {
  Table t{};
  for (std::uint32_t s = 0; s < 4; ++s) {
    for (std::uint32_t in = 0; in < 16; ++in) {
      const Level hi = step(s, (in >> 3) & 1u, (in >> 1) & 1u);
      const Level lo = step(hi.state, (in >> 2) & 1u, in & 1u);
      t.entry[s][in] = static_cast<std::uint8_t>((hi.digit << 2) | lo.digit | (lo.state << 4));
    }
  }
  return t;
}

constexpr Table table = make_table();

}  // namespace

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) noexcept {
  std::uint32_t d = 0, state = 0;
  for (int l = bits - 2; l >= 0; l -= 2) {
    const std::uint32_t e = table.entry[state][(((x >> l) & 3u) << 2) | ((y >> l) & 3u)];
    d = (d << 4) | (e & 15u);
    state = e >> 4;
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

std::uint32_t quantise(double v, double lo, double scale, double top) noexcept {
  const double q = (v - lo) * scale;
  if (!(q > 0.0)) return 0;
  if (q >= top) return static_cast<std::uint32_t>(top);
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

}  // namespace

std::vector<std::uint32_t> insertion_order(std::span<const Point> points) {
  const auto n = static_cast<std::uint32_t>(points.size());
  const Box box = bounding_box(points);
  // Grid of 2^bits cells a side, about 16 cells per point: finer only costs time.
  const int bits = std::clamp(static_cast<int>(std::bit_width(n) + 1) / 2 + 2, 4, 16) & ~1;
  const double top = static_cast<double>((1u << bits) - 1);
  const double extent = std::max(box.width(), box.height());
  const double scale = extent > 0.0 && std::isfinite(extent) ? top / extent : 0.0;
  // Rounds grow by a factor of 4: level k holds about 3n / 4^(k+1) points, so
  // the last round, in one Hilbert sweep, holds 3/4 of them (fewer sweeps, better
  // locality than halving). Everything at or above max_level forms the first
  // round, kept at >= ~64 points.
  int max_level = 0;
  while ((n >> (2 * max_level + 8)) > 0 && max_level < 20) ++max_level;
  // Key layout: [round:5][hilbert:2*bits]; ties keep index order (stable sort).
  std::vector<Item> items(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const int level = std::min(std::countr_one(mix(i)) / 2, max_level);
    const auto round = static_cast<std::uint64_t>(max_level - level);
    const std::uint64_t h =
        hilbert_index(quantise(points[i].x, box.lo.x, scale, top), quantise(points[i].y, box.lo.y, scale, top), bits);
    items[i] = {(round << (2 * bits)) | h, i};
  }
  if (n < 512) {
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
  } else {
    radix_sort(items, 2 * bits + 5);
  }
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = items[i].index;
  return order;
}

}  // namespace madd::detail
