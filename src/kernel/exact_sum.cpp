// ExactSum: Grow-Expansion and Compress after Shewchuk (1997), Sec. 2.
// This file is compiled with -ffp-contract=off (see CMakeLists.txt): a fused
// multiply-add the compiler invents would break two_sum and two_product.
#include "kernel/exact_sum.hpp"

#include <cmath>

#include "kernel/expansion.hpp"

namespace madd::detail {

// h = e + v (Grow-Expansion, Shewchuk Thm. 10): a running Two-Sum carries v up
// through the components; the roundoff left behind at each step is the new
// component there. A nonoverlapping e gives a nonoverlapping h. Zero
// components are dropped, which keeps it nonoverlapping. In place: step i
// reads e_[i] before anything is written at an index > i - (dropped so far).
void ExactSum::grow(double v) {
  if (v == 0.0) return;
  double carry = v;
  std::size_t out = 0;
  for (std::size_t i = 0; i < e_.size(); ++i) {
    const Pair s = two_sum(carry, e_[i]);
    if (s.lo != 0.0) e_[out++] = s.lo;
    carry = s.hi;
  }
  e_.resize(out);
  if (carry != 0.0) e_.push_back(carry);
  // Grow-Expansion never merges components, so a long run of additions can
  // leave many small ones; compressing whenever the length has doubled keeps
  // the amortised cost per addition at a few operations per component.
  if (e_.size() > 2 * compressed_length_ + 8) compress();
}

// Compress (Shewchuk Thm. 23): a pass from the top down with Fast-Two-Sum
// merges every component that fits into its neighbour above, then a pass from
// the bottom up renormalises. The value is unchanged and the result is
// nonadjacent: as short as the bits of the value allow.
void ExactSum::compress() {
  const std::size_t n = e_.size();
  if (n < 2) {
    compressed_length_ = n;
    return;
  }
  std::vector<double> g(n);
  std::size_t bottom = n;  // g[bottom, n) filled, largest last
  double q = e_[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) {
    const Pair s = fast_two_sum(q, e_[i]);  // |q| >= |e_[i]|: e is ordered and nonoverlapping
    if (s.lo != 0.0) {
      g[--bottom] = s.hi;
      q = s.lo;
    } else {
      q = s.hi;
    }
  }
  g[--bottom] = q;
  std::size_t top = 0;
  q = g[bottom];
  for (std::size_t i = bottom + 1; i < n; ++i) {
    const Pair s = fast_two_sum(g[i], q);
    if (s.lo != 0.0) e_[top++] = s.lo;
    q = s.hi;
  }
  e_[top++] = q;
  e_.resize(top);
  compressed_length_ = top;
}

void ExactSum::add(double v) { grow(v); }

void ExactSum::add_product(double a, double b) {
  const Pair p = two_product(a, b);
  grow(p.lo);
  grow(p.hi);
}

void ExactSum::add_cross(Point p, Point q) {
  add_product(p.x, q.y);
  add_product(-p.y, q.x);
}

// Via a copy: growing changes e_, which `other` may be.
void ExactSum::add(const ExactSum& other) {
  const std::vector<double> parts = other.e_;
  for (const double v : parts) grow(v);
}

void ExactSum::subtract(const ExactSum& other) {
  const std::vector<double> parts = other.e_;
  for (const double v : parts) grow(-v);
}

// The largest component of a nonoverlapping expansion outweighs all the
// others together, so it carries the sign of the sum.
int ExactSum::sign() const noexcept {
  if (e_.empty()) return 0;
  return e_.back() > 0.0 ? 1 : -1;
}

double ExactSum::approximate() const noexcept {
  double sum = 0.0;
  for (const double v : e_) sum += v;
  return sum;
}

// |sum| <= sum of |components|; adding those up in floating point takes
// length - 1 roundings of nonnegative values.
double ExactSum::magnitude_bound() const noexcept {
  double sum = 0.0;
  for (const double v : e_) sum += std::abs(v);
  return rounded_up(sum, e_.size());
}

bool ExactSum::magnitude_at_most(double bound) const {
  ExactSum above = *this;
  above.grow(-bound);  // sum - bound <= 0
  if (above.sign() > 0) return false;
  ExactSum below = *this;
  below.grow(bound);  // sum + bound >= 0
  return below.sign() >= 0;
}

ExactSum ring_twice_area_exact(RingView ring) {
  ExactSum twice;
  if (ring.size() < 3) return twice;
  for (std::size_t k = 0; k < ring.size(); ++k) twice.add_cross(ring[k], ring.after(k));
  return twice;
}

// cross(b - a, c - a) = cross(a, b) + cross(b, c) + cross(c, a): the shoelace
// sum of the triangle, whose products of coordinates are all exact.
ExactSum triangle_twice_area_exact(Point a, Point b, Point c) {
  ExactSum twice;
  twice.add_cross(a, b);
  twice.add_cross(b, c);
  twice.add_cross(c, a);
  return twice;
}

// dot(p - a, w - v) = p.w - p.v - a.w + a.v, each dot product of coordinates
// two exact products.
ExactSum dot_of_differences_exact(Point p, Point a, Point w, Point v) {
  ExactSum d;
  d.add_product(p.x, w.x);
  d.add_product(p.y, w.y);
  d.add_product(-p.x, v.x);
  d.add_product(-p.y, v.y);
  d.add_product(-a.x, w.x);
  d.add_product(-a.y, w.y);
  d.add_product(a.x, v.x);
  d.add_product(a.y, v.y);
  return d;
}

double rounded_up(double value, std::size_t roundings) noexcept {
  return value * (1.0 + 2.0 * static_cast<double>(roundings + 2) * kEpsilon);
}

}  // namespace madd::detail
