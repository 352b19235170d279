#pragma once
// Exact reference arithmetic for the predicate tests, independent of the
// expansion code under test: a minimal signed big integer, and exact signs of
// the orient2d and incircle determinants of arbitrary finite doubles (each
// double is m * 2^e, so scaling all inputs by one power of two makes them
// integers without changing any sign).
#include "madd/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace madd::test_ref {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

// ---- A minimal signed big integer: sign + little-endian 32-bit limbs. ----
struct Big {
  bool neg = false;
  std::vector<std::uint32_t> mag;  // no leading zero limbs; empty means 0
};

inline void trim(Big& a) {
  while (!a.mag.empty() && a.mag.back() == 0) a.mag.pop_back();
  if (a.mag.empty()) a.neg = false;
}

inline int cmp_mag(const Big& a, const Big& b) {
  if (a.mag.size() != b.mag.size()) return a.mag.size() < b.mag.size() ? -1 : 1;
  for (std::size_t i = a.mag.size(); i-- > 0;)
    if (a.mag[i] != b.mag[i]) return a.mag[i] < b.mag[i] ? -1 : 1;
  return 0;
}

// |a| + |b|
inline std::vector<std::uint32_t> add_mag(const Big& a, const Big& b) {
  std::vector<std::uint32_t> r(std::max(a.mag.size(), b.mag.size()) + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const std::uint64_t s = carry + (i < a.mag.size() ? a.mag[i] : 0u) + (i < b.mag.size() ? b.mag[i] : 0u);
    r[i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  r.back() = static_cast<std::uint32_t>(carry);
  return r;
}

// |a| - |b|, requires |a| >= |b|
inline std::vector<std::uint32_t> sub_mag(const Big& a, const Big& b) {
  std::vector<std::uint32_t> r(a.mag.size(), 0);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    std::int64_t s = static_cast<std::int64_t>(a.mag[i]) - borrow - (i < b.mag.size() ? b.mag[i] : 0u);
    borrow = s < 0 ? 1 : 0;
    if (s < 0) s += std::int64_t{1} << 32;
    r[i] = static_cast<std::uint32_t>(s);
  }
  return r;
}

inline Big operator+(const Big& a, const Big& b) {
  Big r;
  if (a.neg == b.neg) {
    r.mag = add_mag(a, b);
    r.neg = a.neg;
  } else if (cmp_mag(a, b) >= 0) {
    r.mag = sub_mag(a, b);
    r.neg = a.neg;
  } else {
    r.mag = sub_mag(b, a);
    r.neg = b.neg;
  }
  trim(r);
  return r;
}

inline Big operator-(const Big& a, const Big& b) {
  Big nb = b;
  if (!nb.mag.empty()) nb.neg = !nb.neg;
  return a + nb;
}

inline Big operator*(const Big& a, const Big& b) {
  Big r;
  r.mag.assign(a.mag.size() + b.mag.size() + 1, 0);
  for (std::size_t i = 0; i < a.mag.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.mag.size(); ++j) {
      const std::uint64_t t = std::uint64_t{a.mag[i]} * b.mag[j] + r.mag[i + j] + carry;
      r.mag[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    for (std::size_t k = i + b.mag.size(); carry != 0; ++k) {
      const std::uint64_t t = std::uint64_t{r.mag[k]} + carry;
      r.mag[k] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
  }
  r.neg = a.neg != b.neg;
  trim(r);
  return r;
}

inline int sign(const Big& a) { return a.mag.empty() ? 0 : (a.neg ? -1 : 1); }

// x == mantissa * 2^exponent with an integer 53-bit mantissa.
inline int exponent_of(double x) {
  int e = 0;
  (void)std::frexp(x, &e);
  return e - 53;
}

// Exactly x * 2^-base as a Big; base must not exceed exponent_of(x).
inline Big to_big(double x, int base) {
  Big r;
  if (x == 0.0) return r;
  int e = 0;
  const double m = std::frexp(std::abs(x), &e);
  const auto mant = static_cast<std::uint64_t>(std::ldexp(m, 53));
  const int shift = e - 53 - base;
  r.mag.assign(static_cast<std::size_t>(shift / 32) + 3, 0);
  const unsigned bits = static_cast<unsigned>(shift % 32);
  const std::size_t limb = static_cast<std::size_t>(shift / 32);
  const u128 v = static_cast<u128>(mant) << bits;
  r.mag[limb] = static_cast<std::uint32_t>(v);
  r.mag[limb + 1] = static_cast<std::uint32_t>(v >> 32);
  r.mag[limb + 2] = static_cast<std::uint32_t>(v >> 64);
  r.neg = x < 0;
  trim(r);
  return r;
}

// The common power of two that turns every coordinate into an integer.
inline int common_base(std::initializer_list<Point> pts) {
  int base = 0;
  bool first = true;
  for (const Point& p : pts)
    for (double v : {p.x, p.y})
      if (v != 0.0) {
        base = first ? exponent_of(v) : std::min(base, exponent_of(v));
        first = false;
      }
  return base;
}

// True when q == p + t exactly.
inline bool exact_sum(double p, double t, double q) {
  const int s = common_base({{p, t}, {q, 0.0}});
  return sign(to_big(p, s) + to_big(t, s) - to_big(q, s)) == 0;
}

inline int exact_orient(Point a, Point b, Point c) {
  const int s = common_base({a, b, c});
  const Big ax = to_big(a.x, s), ay = to_big(a.y, s), bx = to_big(b.x, s), by = to_big(b.y, s);
  const Big cx = to_big(c.x, s), cy = to_big(c.y, s);
  return sign((ax - cx) * (by - cy) - (ay - cy) * (bx - cx));
}

inline int exact_incircle(Point a, Point b, Point c, Point d) {
  const int s = common_base({a, b, c, d});
  const Big dx = to_big(d.x, s), dy = to_big(d.y, s);
  const Big adx = to_big(a.x, s) - dx, ady = to_big(a.y, s) - dy;
  const Big bdx = to_big(b.x, s) - dx, bdy = to_big(b.y, s) - dy;
  const Big cdx = to_big(c.x, s) - dx, cdy = to_big(c.y, s) - dy;
  const Big alift = adx * adx + ady * ady;
  const Big blift = bdx * bdx + bdy * bdy;
  const Big clift = cdx * cdx + cdy * cdy;
  return sign(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady));
}

}  // namespace madd::test_ref
