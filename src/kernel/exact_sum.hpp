#pragma once
// Exact sums of doubles and of products of two doubles, for the checks that
// must compare areas without any rounding (verify_triangulation,
// verify_decomposition). The value is kept as a nonoverlapping expansion
// (Shewchuk 1997, Sec. 2: an unevaluated sum of doubles whose bits do not
// overlap), grown one double at a time (Grow-Expansion, his Thm. 10) and
// compressed now and then (Compress, his Thm. 23) so it stays a few
// components long. Everything is exact provided no product underflows or
// overflows, which holds for every coordinate validate() accepts (0 or
// magnitude in [1e-40, 1e70]: products and their roundoff stay within
// [1e-112, 1e141]).
#include <cstddef>
#include <vector>

#include "kernel/rings.hpp"
#include "madd/geometry.hpp"

namespace madd::detail {

class ExactSum {
public:
  void add(double v);
  void add_product(double a, double b);  // + a * b, exactly
  void add_cross(Point p, Point q);      // + p.x * q.y - p.y * q.x, exactly
  void add(const ExactSum& other);
  void subtract(const ExactSum& other);

  bool is_zero() const noexcept { return e_.empty(); }
  // -1, 0 or +1: the exact sign of the sum.
  int sign() const noexcept;
  // The sum rounded to a double (within a few ulps): for messages.
  double approximate() const noexcept;
  // A double >= |sum|, within a few ulps of it: for error bounds.
  double magnitude_bound() const noexcept;
  // |sum| <= bound, decided exactly (bound >= 0).
  bool magnitude_at_most(double bound) const;

private:
  void grow(double v);
  void compress();

  std::vector<double> e_;  // nonzero components, increasing magnitude
  std::size_t compressed_length_ = 0;
};

// Twice the signed area of the ring, exactly: the shoelace sum of
// x_k y_{k+1} - x_{k+1} y_k over its edges, every product exact.
ExactSum ring_twice_area_exact(RingView ring);

// Twice the signed area of triangle abc, exactly (positive when
// counter-clockwise): cross(b - a, c - a) without rounding the differences.
ExactSum triangle_twice_area_exact(Point a, Point b, Point c);

// Exact dot(p - a, w - v): how far p lies along the direction v -> w from a
// (times |w - v|), without rounding any difference.
ExactSum dot_of_differences_exact(Point p, Point a, Point w, Point v);

// An upper bound on a nonnegative quantity that was computed as `value` by at
// most `roundings` floating-point operations, each exact up to a relative error
// of eps = 2^-53 and none of them cancelling (sums and products of
// nonnegative values, quotients, square roots): the exact quantity is at most
// value / (1 - eps)^roundings <= value (1 + 2 roundings eps) while
// roundings eps <= 1/2; two more roundings cover the multiplication here.
double rounded_up(double value, std::size_t roundings) noexcept;

}  // namespace madd::detail
