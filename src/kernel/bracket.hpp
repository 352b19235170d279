#pragma once
// Expressions of two products of differences of doubles, evaluated in
// floating point with a bound on their error: the first stage of
// Shewchuk's orient2d (Shewchuk 1997, Sec. 4.2: |det - exact| <=
// (3 + 16 eps) eps (|detleft| + |detright|)), which holds for any such
// expression, a sum or a difference. The exact value lies in
// [estimate - error, estimate + error]; a check decides from that interval
// when it can, and computes the value exactly (ExactSum,
// kernel/exact_sum.hpp) only when it cannot. Valid for the coordinates
// validate() accepts (no product underflows; exact_sum.hpp says why); a
// bracket of tiny products is never decisive, to be safe.
#include <cmath>

#include "madd/geometry.hpp"

namespace madd::detail {

struct Bracket {
  double estimate = 0.0;
  double error = 0.0;
  bool decisive = false;  // false: the products are too small for the bound (use the exact value)

  bool certainly_positive() const noexcept { return decisive && estimate > error; }
  // A double >= |exact value| (the sum rounded up).
  double magnitude_bound() const noexcept { return (std::abs(estimate) + error) * (1.0 + 0x1p-50); }
  // |exact value| <= bound certainly; and > bound certainly.
  bool certainly_at_most(double bound) const noexcept { return decisive && magnitude_bound() <= bound; }
  bool certainly_above(double bound) const noexcept {
    return decisive && (std::abs(estimate) - error) * (1.0 - 0x1p-50) > bound;
  }
};

namespace bracket_detail {
inline Bracket of_products(double left, double right, double value) noexcept {
  constexpr double epsilon = 0x1p-53;
  constexpr double bound_factor = (3.0 + 16.0 * epsilon) * epsilon;
  const double sum = std::abs(left) + std::abs(right);
  return {value, bound_factor * sum, sum > 1e-250};
}
}  // namespace bracket_detail

// dot(p - a, w - v), as dot_of_differences_exact.
inline Bracket dot_of_differences_bracket(Point p, Point a, Point w, Point v) noexcept {
  const double left = (p.x - a.x) * (w.x - v.x), right = (p.y - a.y) * (w.y - v.y);
  return bracket_detail::of_products(left, right, left + right);
}

// Twice the signed area of triangle abc, as triangle_twice_area_exact
// (orient2d's first stage itself).
inline Bracket triangle_twice_area_bracket(Point a, Point b, Point c) noexcept {
  const double left = (a.x - c.x) * (b.y - c.y), right = (a.y - c.y) * (b.x - c.x);
  return bracket_detail::of_products(left, right, left - right);
}

}  // namespace madd::detail
