// append_g17 (src/kernel/number_format.cpp) writes exactly what
// std::to_chars(general, 17), i.e. %.17g, writes: brute force over doubles
// of every exponent, of the ranges mesh coordinates take, around powers of
// ten and at exact decimal ties, with fixed seeds.
#include <doctest/doctest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "kernel/number_format.hpp"

namespace {

std::string reference(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
  return {buffer, r.ptr};
}

std::string fast(double v) {
  std::string out;
  madd::detail::append_g17(out, v);
  return out;
}

// Counts the values of `draw()` where the two disagree, reporting the first few.
template <class Draw>
int mismatches(int count, Draw draw) {
  int bad = 0;
  for (int i = 0; i < count; ++i) {
    const double v = draw();
    if (fast(v) == reference(v)) continue;
    if (++bad <= 5) MESSAGE("mismatch for ", reference(v), ": ", fast(v));
  }
  return bad;
}

}  // namespace

TEST_SUITE("number_format") {
TEST_CASE("append_g17 writes %.17g for every kind of double") {
  std::mt19937_64 random(20261206);
  SUBCASE("random bit patterns (every exponent, subnormals, inf and NaN included)") {
    CHECK(mismatches(2'000'000, [&] { return std::bit_cast<double>(random()); }) == 0);
  }
  SUBCASE("coordinates: uniform in ranges from 1e-6 to 1e7, both signs") {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> decade(-6, 7);
    CHECK(mismatches(2'000'000, [&] { return unit(random) * std::pow(10.0, decade(random)); }) == 0);
  }
  SUBCASE("around every power of ten the fast path takes, and integers") {
    int bad = 0;
    for (int k = -20; k <= 20; ++k) {
      double v = std::pow(10.0, k);
      for (int step = 0; step < 200; ++step) v = std::nextafter(v, 0.0);
      for (int step = 0; step < 400; ++step, v = std::nextafter(v, 1e300)) bad += fast(v) != reference(v);
    }
    for (std::int64_t n = -100000; n <= 100000; ++n)
      bad += fast(static_cast<double>(n)) != reference(static_cast<double>(n));
    for (std::int64_t n = (1LL << 53) - 1000; n <= (1LL << 53) + 1000; ++n)
      bad += fast(static_cast<double>(n)) != reference(static_cast<double>(n));
    CHECK(bad == 0);
  }
  SUBCASE("exact decimal ties at the 18th digit round half to even") {
    // m 2^-j (m odd) is exactly m 5^j 10^-j: when m 5^j has 18 digits, its
    // last is a 5 and the 17-digit rounding is a tie, either way.
    __extension__ typedef unsigned __int128 u128;
    const u128 low = static_cast<u128>(100'000'000'000'000'000ULL);
    const u128 high = low * 10;
    int bad = 0, ties = 0, even = 0;
    for (std::uint64_t m = 1; m < (1u << 16); m += 2) {
      u128 a = m;
      for (int j = 1; j <= 26 && a < high; ++j) {
        a *= 5;
        if (a < low || a >= high) continue;
        const double v = std::ldexp(static_cast<double>(m), -j);
        ++ties;
        even += static_cast<int>((a / 10) % 2 == 0);
        bad += fast(v) != reference(v) || fast(-v) != reference(-v);
      }
    }
    CHECK(bad == 0);
    CHECK(ties > 1000);
    CHECK(even > 100);  // ties whose 17th digit is even (kept) and odd (rounded up) both
    CHECK(ties - even > 100);
  }
  SUBCASE("the special values") {
    for (const double v : {0.0, -0.0, 1.0, -1.0, 0.1, 1e-4, 9.9999999999999995e-5, 1e16, 1e17, 123456789012345678.0,
                           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::min()})
      CHECK(fast(v) == reference(v));
  }
}
}
