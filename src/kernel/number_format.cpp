// %.17g without printf (kernel/number_format.hpp): the 17 significant digits
// of a double, correctly rounded, by one exact integer product. A double is
// m 2^e (m < 2^53); for 10^-16 <= |v| < 10^17 the 17 digits are the integer
// m 5^p 2^(e + p), p = 16 - E (E the decimal exponent), rounded half to even,
// and m 5^p fits in 128 bits for p <= 32. Everything else (0, subnormals,
// tiny and huge values, inf, NaN) goes to std::to_chars, which writes the
// same bytes the slower way (tests/number_format_test.cpp compares the two).
#include "kernel/number_format.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>

namespace madd::detail {

namespace {

__extension__ typedef unsigned __int128 u128;

constexpr int max_power = 32;

constexpr std::array<u128, max_power + 1> powers_of_five = [] {
  std::array<u128, max_power + 1> p{};
  p[0] = 1;
  for (int i = 1; i <= max_power; ++i) p[i] = p[i - 1] * 5;
  return p;
}();

// 10^0 ... 10^18, each a double exactly.
constexpr std::array<double, 19> powers_of_ten = [] {
  std::array<double, 19> p{};
  p[0] = 1;
  for (std::size_t k = 1; k < p.size(); ++k) p[k] = p[k - 1] * 10;
  return p;
}();

constexpr std::uint64_t ten_to_16 = 10'000'000'000'000'000ULL;
constexpr std::uint64_t ten_to_17 = 100'000'000'000'000'000ULL;

// round(m 5^p 2^shift), half to even, when it is below 2^64; false when it is not.
bool scaled(std::uint64_t m, int p, int shift, std::uint64_t& q) {
  const u128 a = static_cast<u128>(m) * powers_of_five[static_cast<std::size_t>(p)];
  if (shift >= 0) {
    if (shift >= 64 || (a >> (64 - shift)) != 0) return false;
    q = static_cast<std::uint64_t>(a << shift);
    return true;
  }
  const int down = -shift;
  if (down >= 128) return false;
  const u128 whole = a >> down;
  if ((whole >> 64) != 0) return false;
  const u128 rest = a - (whole << down);
  const u128 half = static_cast<u128>(1) << (down - 1);
  q = static_cast<std::uint64_t>(whole);
  if (rest > half || (rest == half && (q & 1) != 0)) ++q;
  return true;
}

// The 17 digits q (10^16 <= q < 10^17) and decimal exponent of |v|, or false.
bool seventeen_digits(double v, std::uint64_t& q, int& exponent) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0 || biased == 0x7ff) return false;  // 0, subnormal, inf, NaN
  const std::uint64_t m = (bits & ((1ULL << 52) - 1)) | (1ULL << 52);
  const int e = biased - 1075;  // v = m 2^e
  // floor(log10 |v|): from the binary exponent (log10(2) ~ 78913 / 2^18)
  // at most one below, then against the power of ten above when that is a
  // double exactly (10^0 ... 10^18); else the loop below counts up.
  int guess = ((biased - 1023) * 78913) >> 18;
  if (guess >= -1 && guess < 18 && std::fabs(v) >= powers_of_ten[static_cast<std::size_t>(guess + 1)]) ++guess;
  for (int tries = 0; tries < 3; ++tries) {
    const int p = 16 - guess;
    if (p < 0 || p > max_power) return false;
    if (!scaled(m, p, e + p, q)) return false;
    if (q < ten_to_16) {
      --guess;
    } else if (q >= ten_to_17) {
      if (q == ten_to_17) {  // rounded up to the next power of ten
        q = ten_to_16;
        exponent = guess + 1;
        return true;
      }
      ++guess;
    } else {
      exponent = guess;
      return true;
    }
  }
  return false;
}

// "00" to "99".
constexpr std::array<char, 200> digit_pairs = [] {
  std::array<char, 200> t{};
  for (int i = 0; i < 100; ++i) {
    t[static_cast<std::size_t>(2 * i)] = static_cast<char>('0' + i / 10);
    t[static_cast<std::size_t>(2 * i + 1)] = static_cast<char>('0' + i % 10);
  }
  return t;
}();

// The 17 digits of q (10^16 <= q < 10^17), two at a time from the right.
void write_17_digits(std::uint64_t q, char* digits) {
  auto low = static_cast<std::uint32_t>(q % 100'000'000);  // digits 9..16
  auto high = q / 100'000'000;                             // digits 0..8, below 10^9
  for (int i = 15; i >= 9; i -= 2, low /= 100) std::memcpy(digits + i, &digit_pairs[2 * (low % 100)], 2);
  auto top = static_cast<std::uint32_t>(high);
  for (int i = 7; i >= 1; i -= 2, top /= 100) std::memcpy(digits + i, &digit_pairs[2 * (top % 100)], 2);
  digits[0] = static_cast<char>('0' + top);
}

}  // namespace

void append_g17(std::string& out, double v) {
  std::uint64_t q = 0;
  int exponent = 0;
  if (!seventeen_digits(v, q, exponent) || exponent >= 17) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
    out.append(buffer, result.ptr);
    return;
  }
  char digits[17];
  write_17_digits(q, digits);
  char text[32];
  char* c = text;
  if (v < 0) *c++ = '-';
  if (exponent >= -4) {  // %g's fixed notation: 17 - 1 - exponent digits after the point, zeros trimmed
    int last = 16;
    while (last > exponent && last > 0 && digits[last] == '0') --last;
    if (exponent >= 0) {
      std::memcpy(c, digits, static_cast<std::size_t>(exponent) + 1);
      c += exponent + 1;
      if (last > exponent) {
        *c++ = '.';
        std::memcpy(c, digits + exponent + 1, static_cast<std::size_t>(last - exponent));
        c += last - exponent;
      }
    } else {
      *c++ = '0';
      *c++ = '.';
      for (int i = -1; i > exponent; --i) *c++ = '0';
      std::memcpy(c, digits, static_cast<std::size_t>(last) + 1);
      c += last + 1;
    }
  } else {  // scientific: d.dddd (zeros trimmed) e-XX
    int last = 16;
    while (last > 0 && digits[last] == '0') --last;
    *c++ = digits[0];
    if (last > 0) {
      *c++ = '.';
      std::memcpy(c, digits + 1, static_cast<std::size_t>(last));
      c += last;
    }
    *c++ = 'e';
    *c++ = '-';
    const int magnitude = -exponent;
    if (magnitude >= 100) *c++ = static_cast<char>('0' + magnitude / 100);
    *c++ = static_cast<char>('0' + magnitude / 10 % 10);
    *c++ = static_cast<char>('0' + magnitude % 10);
  }
  out.append(text, c);
}

}  // namespace madd::detail
