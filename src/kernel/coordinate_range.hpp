#pragma once
// The range of coordinates madd keeps exact, written once: 0 or a magnitude
// within [1e-40, 1e70]. The exact predicates (predicates.hpp) are exact only
// without overflow or underflow in their products (nonzero magnitudes within
// about [1e-60, 1e76] for incircle); coordinates in this range keep every
// value and every difference of two values inside that, with margin for the
// constructions (midpoints, circumcentres) made from them later. validate()
// refuses what lies outside it; the readers whose own exact tests come before
// validate() refuse it too, and constructions that may round below it flush
// to 0.
#include <cmath>

namespace madd::detail {

inline constexpr double min_coordinate_magnitude = 1e-40;
inline constexpr double max_coordinate_magnitude = 1e70;

inline bool in_exact_range(double v) noexcept {
  const double m = std::abs(v);
  return m == 0.0 || (m >= min_coordinate_magnitude && m <= max_coordinate_magnitude);
}

// v, or 0 when its magnitude is below the range (a sub-femtometre change).
inline double flush_below_range(double v) noexcept { return std::abs(v) < min_coordinate_magnitude ? 0.0 : v; }

}  // namespace madd::detail
