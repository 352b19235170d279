#pragma once
// Adaptive-exact geometric predicates, after Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates" (1997).
// These two functions are the only place in madd where a geometric sign is
// decided (the core's walk, src/triangulation/walk.cpp, repeats orient2d's
// first stage inline and calls orient2d whenever that stage cannot decide).
// The sign of the result is always exact; its magnitude is an approximation
// of the determinant.
// Valid range (no intermediate overflow/underflow, as Shewchuk assumes): zero or
// |coordinate| in about [1e-137, 1e153] for orient2d and [1e-60, 1e76] for incircle
// (the lower limit applies to nonzero coordinates and nonzero coordinate
// differences). Thread-safe; no initialisation call.
#include "madd/geometry.hpp"

namespace madd {

// Positive if a, b, c are in counter-clockwise order, negative if clockwise,
// zero if collinear.
double orient2d(Point a, Point b, Point c) noexcept;

// Positive if d lies inside the circle through a, b, c (which must be in
// counter-clockwise order), negative if outside, zero if on it.
double incircle(Point a, Point b, Point c, Point d) noexcept;

}  // namespace madd
