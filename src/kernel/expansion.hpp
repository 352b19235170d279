#pragma once
// Floating-point expansion arithmetic after Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates" (1997), Sec. 2.
// An expansion is an unevaluated sum of doubles, stored in increasing order of
// magnitude, whose components do not overlap; it represents a real number
// exactly. Every routine here is exact provided the hardware rounds to nearest
// even and no intermediate value overflows or loses bits to underflow.
//
// Include only from translation units compiled with -ffp-contract=off: a fused
// multiply-add the compiler invents would silently break two_sum/two_product.
#include <cmath>
#include <cstddef>

namespace madd::detail {

// Half an ulp of 1.0: the relative rounding error bound of one operation.
inline constexpr double kEpsilon = 0x1p-53;
// 2^ceil(53/2) + 1, splits a double into two 26-bit halves (Dekker).
inline constexpr double kSplitter = 0x1p27 + 1.0;

// hi + lo == exact value, hi is the rounded value and |lo| <= ulp(hi)/2.
struct Pair {
  double hi;
  double lo;
};

// Exact a + b (Knuth's Two-Sum, Shewchuk Thm. 7).
inline Pair two_sum(double a, double b) noexcept {
  const double x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  return {x, (a - av) + (b - bv)};
}

// Exact a - b.
inline Pair two_diff(double a, double b) noexcept {
  const double x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  return {x, (a - av) + (bv - b)};
}

// Exact a + b given |a| >= |b| (Dekker's Fast-Two-Sum, Shewchuk Thm. 6).
inline Pair fast_two_sum(double a, double b) noexcept {
  const double x = a + b;
  return {x, b - (x - a)};
}

// The roundoff of x = fl(a - b): a - b == x + tail exactly.
inline double two_diff_tail(double a, double b, double x) noexcept {
  const double bv = a - x;
  const double av = x + bv;
  return (a - av) + (bv - b);
}

// Exact a * b. With hardware FMA the error term is one fused operation; without
// it Dekker's splitting (Shewchuk Thm. 18) avoids a slow software fma call.
inline Pair two_product(double a, double b) noexcept {
  const double x = a * b;
#if defined(__FMA__)
  return {x, std::fma(a, b, -x)};
#else
  const auto split = [](double v) {
    const double c = kSplitter * v;
    const double big = c - v;
    const double hi = c - big;
    return Pair{hi, v - hi};
  };
  const Pair as = split(a);
  const Pair bs = split(b);
  const double err1 = x - as.hi * bs.hi;
  const double err2 = err1 - as.lo * bs.hi;
  const double err3 = err2 - as.hi * bs.lo;
  return {x, as.lo * bs.lo - err3};
#endif
}

// A fixed-capacity expansion living on the stack; e[0..n) are the nonzero
// components, smallest first. n == 0 means the value zero.
template <std::size_t N>
struct Expansion {
  double e[N];
  std::size_t n = 0;

  void push(double v) noexcept {
    if (v != 0.0) e[n++] = v;
  }
  // The component of largest magnitude; it carries the exact sign of the sum.
  double most_significant() const noexcept { return n == 0 ? 0.0 : e[n - 1]; }
  // Floating-point approximation of the value, with the sign forced exact:
  // summing many small components may in rare cases round onto -top.
  double estimate() const noexcept {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += e[i];
    const double top = most_significant();
    return ((sum > 0.0) == (top > 0.0) && (sum < 0.0) == (top < 0.0)) ? sum : top;
  }
};

// Exact (a.hi + a.lo) - (b.hi + b.lo), by two Grow-Expansion steps (Sec. 2.6).
inline Expansion<4> two_two_diff(Pair a, Pair b) noexcept {
  Expansion<4> out;
  // Grow {a.lo, a.hi} by -b.lo: three components.
  const Pair s0 = two_sum(a.lo, -b.lo);
  const Pair s1 = two_sum(a.hi, s0.hi);
  // Grow {s0.lo, s1.lo, s1.hi} by -b.hi.
  const Pair t0 = two_sum(s0.lo, -b.hi);
  const Pair t1 = two_sum(s1.lo, t0.hi);
  const Pair t2 = two_sum(s1.hi, t1.hi);
  out.push(t0.lo);
  out.push(t1.lo);
  out.push(t2.lo);
  out.push(t2.hi);
  return out;
}

// h = e + f with zero elimination (Fast-Expansion-Sum, Shewchuk Thm. 13):
// merge the components by magnitude and carry a running Two-Sum. Inputs must be
// strongly nonoverlapping, which every routine here produces. h needs room for
// elen + flen components; returns its length.
inline std::size_t expansion_sum(std::size_t elen, const double* e, std::size_t flen, const double* f,
                                 double* h) noexcept {
  // Starting the running sum at 0 makes the first Two-Sum exact with a zero
  // tail, so every write below lands at an index < elen + flen.
  double q = 0.0;
  std::size_t len = 0;
  const auto add = [&](double v) {
    const Pair s = two_sum(q, v);
    h[len] = s.lo;
    len += s.lo != 0.0;
    q = s.hi;
  };
  // The merge order is data dependent and unpredictable: select with
  // conditional moves rather than branches while both inputs remain.
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < elen && j < flen) {
    const double ev = e[i];
    const double fv = f[j];
    const bool from_e = std::abs(ev) < std::abs(fv);
    add(from_e ? ev : fv);
    i += from_e;
    j += !from_e;
  }
  for (; i < elen; ++i) add(e[i]);
  for (; j < flen; ++j) add(f[j]);
  if (elen + flen == 0) return 0;
  h[len] = q;
  len += q != 0.0;
  return len;
}

// h = e * b with zero elimination (Scale-Expansion, Shewchuk Thm. 19); h needs
// room for 2 * elen components; returns its length.
inline std::size_t expansion_scale(std::size_t elen, const double* e, double b, double* h) noexcept {
  if (elen == 0) return 0;
  std::size_t len = 0;
  const Pair p0 = two_product(e[0], b);
  h[len] = p0.lo;  // every write is at an index < 2 * elen
  len += p0.lo != 0.0;
  double q = p0.hi;
  for (std::size_t i = 1; i < elen; ++i) {
    const Pair p = two_product(e[i], b);
    const Pair s = two_sum(q, p.lo);
    h[len] = s.lo;
    len += s.lo != 0.0;
    const Pair t = fast_two_sum(p.hi, s.hi);
    h[len] = t.lo;
    len += t.lo != 0.0;
    q = t.hi;
  }
  h[len] = q;
  len += q != 0.0;
  return len;
}

template <std::size_t M, std::size_t N>
Expansion<M + N> sum(const Expansion<M>& a, const Expansion<N>& b) noexcept {
  Expansion<M + N> out;
  out.n = expansion_sum(a.n, a.e, b.n, b.e, out.e);
  return out;
}

template <std::size_t M>
Expansion<2 * M> scale(const Expansion<M>& a, double b) noexcept {
  Expansion<2 * M> out;
  out.n = expansion_scale(a.n, a.e, b, out.e);
  return out;
}

template <std::size_t M>
Expansion<M> negate(Expansion<M> a) noexcept {
  for (std::size_t i = 0; i < a.n; ++i) a.e[i] = -a.e[i];
  return a;
}

// Exact product of two expansions: the sum over b's components of a scaled by
// each, accumulated in two ping-pong buffers.
template <std::size_t M, std::size_t N>
Expansion<2 * M * N> product(const Expansion<M>& a, const Expansion<N>& b) noexcept {
  Expansion<2 * M * N> out;
  Expansion<2 * M * N> spare;
  double* cur = out.e;
  double* next = spare.e;
  std::size_t len = 0;
  for (std::size_t j = 0; j < b.n; ++j) {
    const Expansion<2 * M> part = scale(a, b.e[j]);
    len = expansion_sum(len, cur, part.n, part.e, next);
    double* t = cur;
    cur = next;
    next = t;
  }
  if (cur != out.e)
    for (std::size_t i = 0; i < len; ++i) out.e[i] = cur[i];
  out.n = len;
  return out;
}

// The exact difference a - b of two doubles as an expansion.
inline Expansion<2> exact_diff(double a, double b) noexcept {
  const Pair d = two_diff(a, b);
  Expansion<2> out;
  out.push(d.lo);
  out.push(d.hi);
  return out;
}

}  // namespace madd::detail
