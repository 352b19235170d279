// Large arrays resized with their fresh pages faulted in on several threads
// (src/kernel/fresh_memory.hpp): the same vector as resize/assign makes,
// whatever the thread count, size or alignment.
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/fresh_memory.hpp"

TEST_CASE("fresh memory: resize_on_threads keeps the old elements and value-initialises the new") {
  // Sizes below and above the 4 MiB the faulting starts at, odd ones too.
  for (const std::size_t n :
       {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{1} << 20, (std::size_t{3} << 20) + 7}) {
    for (const unsigned threads : {1u, 2u, 3u, 8u}) {
      std::vector<std::array<std::uint32_t, 3>> v(5, {7, 8, 9});
      madd::detail::resize_on_threads(v, n, threads);
      REQUIRE(v.size() == n);
      const std::size_t kept = std::min<std::size_t>(n, 5);
      for (std::size_t i = 0; i < kept; ++i) CHECK(v[i] == std::array<std::uint32_t, 3>{7, 8, 9});
      bool zero = true;
      for (std::size_t i = kept; i < v.size(); ++i) zero = zero && v[i] == std::array<std::uint32_t, 3>{0, 0, 0};
      CHECK(zero);
      // Writable everywhere (ASan would see a write outside the array).
      for (std::size_t i = 0; i < v.size(); i += 4099) v[i][1] = static_cast<std::uint32_t>(i);
      for (std::size_t i = 0; i < v.size(); i += 4099) CHECK(v[i][1] == static_cast<std::uint32_t>(i));
    }
  }
}

TEST_CASE("fresh memory: assign_on_threads fills with the value, and shrinking works as resize") {
  for (const unsigned threads : {1u, 2u, 5u}) {
    std::vector<double> v(10, 1.5);
    madd::detail::assign_on_threads(v, std::size_t{3} << 20, -2.25, threads);
    REQUIRE(v.size() == std::size_t{3} << 20);
    bool all = true;
    for (const double x : v) all = all && x == -2.25;
    CHECK(all);
    madd::detail::resize_on_threads(v, 4, threads);
    CHECK(v == std::vector<double>(4, -2.25));
  }
  // A range that is no array at all is only a hint: nothing happens.
  madd::detail::fault_in_on_threads(nullptr, std::size_t{64} << 20, 2);
}
