// Adaptive-exact orient2d and incircle after Shewchuk (1997), Sec. 4.
// Each predicate first evaluates the determinant in plain floating point and
// accepts it when it exceeds a forward error bound (stage A). Otherwise the
// determinant is recomputed with expansions, treating the coordinate
// differences as exact (stage B); then the first-order effect of the
// differences' roundoff is added (stage C); finally the exact value is formed
// (stage D). Each stage accepts its answer only when its error bound proves the
// sign, so the returned sign is always exact.
//
// Valid range: like Shewchuk's, these predicates assume no intermediate overflow
// or underflow. Sufficient conditions, where the lower limit applies to every
// nonzero coordinate and every nonzero coordinate difference:
//   orient2d: magnitudes in [1e-137, 1e153] (2^-455 .. 2^508);
//   incircle: magnitudes in [1e-60, 1e76].
// Why: all bits of the inputs then lie at or above 2^-(455+52), so every exact
// product of two (orient2d) or four (incircle, 2^-216 limit) such values is a
// multiple of a number >= 2^-1074 and two_product stays exact; the upper limits
// keep the largest determinant term (and the permanent) below DBL_MAX.
// This file is compiled with -ffp-contract=off (see CMakeLists.txt).
#include "madd/predicates.hpp"

#include "kernel/expansion.hpp"

#include <cmath>

namespace madd {

namespace {

using detail::Expansion;
using detail::kEpsilon;
using detail::two_diff_tail;
using detail::two_product;
using detail::two_two_diff;

// Error-bound coefficients of Shewchuk Sec. 4.2/4.3, evaluated at compile time so
// there is no initialisation call and nothing mutable to share between threads.
constexpr double kResultErrBound = (3.0 + 8.0 * kEpsilon) * kEpsilon;
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kCcwErrBoundB = (2.0 + 12.0 * kEpsilon) * kEpsilon;
constexpr double kCcwErrBoundC = (9.0 + 64.0 * kEpsilon) * kEpsilon * kEpsilon;
constexpr double kIccErrBoundA = (10.0 + 96.0 * kEpsilon) * kEpsilon;
constexpr double kIccErrBoundB = (4.0 + 48.0 * kEpsilon) * kEpsilon;
constexpr double kIccErrBoundC = (44.0 + 576.0 * kEpsilon) * kEpsilon * kEpsilon;

// The rounded difference p - q of two points, and its roundoff (Shewchuk's
// "tail": p - q == difference + tail exactly). Every stage works on these.
struct Offset {
  double x, y;
};
inline Offset difference(Point p, Point q) noexcept { return {p.x - q.x, p.y - q.y}; }
inline Offset difference_tail(Point p, Point q, Offset rounded) noexcept {
  return {two_diff_tail(p.x, q.x, rounded.x), two_diff_tail(p.y, q.y, rounded.y)};
}
inline bool is_zero(Offset o) noexcept { return o.x == 0.0 && o.y == 0.0; }

// Stages B-D of orient2d; detsum = |detleft| + |detright| from stage A.
double orient2d_adapt(Point a, Point b, Point c, double detsum) noexcept {
  const auto [acx, acy] = difference(a, c);
  const auto [bcx, bcy] = difference(b, c);

  const Expansion<4> bdet = two_two_diff(two_product(acx, bcy), two_product(acy, bcx));
  double det = bdet.estimate();
  if (std::abs(det) >= kCcwErrBoundB * detsum) return det;

  const auto [acxtail, acytail] = difference_tail(a, c, {acx, acy});
  const auto [bcxtail, bcytail] = difference_tail(b, c, {bcx, bcy});
  // Exact differences: stage B's expansion is the exact determinant.
  if (is_zero({acxtail, acytail}) && is_zero({bcxtail, bcytail})) return det;

  const double errbound = kCcwErrBoundC * detsum + kResultErrBound * std::abs(det);
  det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail);
  if (std::abs(det) >= errbound) return det;

  // Stage D: add the three remaining product groups exactly.
  const auto c1 = detail::sum(bdet, two_two_diff(two_product(acxtail, bcy), two_product(acytail, bcx)));
  const auto c2 = detail::sum(c1, two_two_diff(two_product(acx, bcytail), two_product(acy, bcxtail)));
  const auto d = detail::sum(c2, two_two_diff(two_product(acxtail, bcytail), two_product(acytail, bcxtail)));
  return d.most_significant();
}

// (px^2 + py^2) * minor, with px, py treated as exact doubles (incircle stage B).
Expansion<32> lifted_term(const Expansion<4>& minor, double px, double py) noexcept {
  const auto xx = detail::scale(detail::scale(minor, px), px);
  const auto yy = detail::scale(detail::scale(minor, py), py);
  return detail::sum(xx, yy);
}

// Exact incircle determinant from scratch: every coordinate difference is an
// exact two-component expansion, then minors, lifts and products are exact.
// Only reached for inputs within a few ulps of cocircular with inexact
// differences, so its ~40 KB of stack buffers are rarely touched.
double incircle_exact(Point a, Point b, Point c, Point d) noexcept {
  using detail::exact_diff;
  using detail::product;
  const auto adx = exact_diff(a.x, d.x);
  const auto ady = exact_diff(a.y, d.y);
  const auto bdx = exact_diff(b.x, d.x);
  const auto bdy = exact_diff(b.y, d.y);
  const auto cdx = exact_diff(c.x, d.x);
  const auto cdy = exact_diff(c.y, d.y);

  const auto minor = [](const Expansion<2>& px, const Expansion<2>& qy, const Expansion<2>& qx,
                        const Expansion<2>& py) {
    return detail::sum(product(px, qy), detail::negate(product(qx, py)));
  };
  const auto lift = [](const Expansion<2>& x, const Expansion<2>& y) {
    return detail::sum(product(x, x), product(y, y));
  };
  const auto adet = product(lift(adx, ady), minor(bdx, cdy, cdx, bdy));
  const auto bdet = product(lift(bdx, bdy), minor(cdx, ady, adx, cdy));
  const auto cdet = product(lift(cdx, cdy), minor(adx, bdy, bdx, ady));
  return detail::sum(detail::sum(adet, bdet), cdet).most_significant();
}

// Stages B-D of incircle; permanent bounds the magnitude of stage A's terms.
double incircle_adapt(Point a, Point b, Point c, Point d, double permanent) noexcept {
  const auto [adx, ady] = difference(a, d);
  const auto [bdx, bdy] = difference(b, d);
  const auto [cdx, cdy] = difference(c, d);

  const Expansion<4> bc = two_two_diff(two_product(bdx, cdy), two_product(cdx, bdy));
  const Expansion<4> ca = two_two_diff(two_product(cdx, ady), two_product(adx, cdy));
  const Expansion<4> ab = two_two_diff(two_product(adx, bdy), two_product(bdx, ady));
  const auto fin =
      detail::sum(detail::sum(lifted_term(bc, adx, ady), lifted_term(ca, bdx, bdy)), lifted_term(ab, cdx, cdy));
  double det = fin.estimate();
  if (std::abs(det) >= kIccErrBoundB * permanent) return det;

  const auto [adxtail, adytail] = difference_tail(a, d, {adx, ady});
  const auto [bdxtail, bdytail] = difference_tail(b, d, {bdx, bdy});
  const auto [cdxtail, cdytail] = difference_tail(c, d, {cdx, cdy});
  if (is_zero({adxtail, adytail}) && is_zero({bdxtail, bdytail}) && is_zero({cdxtail, cdytail})) return det;

  // Stage C: the first-order terms in the tails (Shewchuk Sec. 4.3).
  const double errbound = kIccErrBoundC * permanent + kResultErrBound * std::abs(det);
  det += ((adx * adx + ady * ady) * ((bdx * cdytail + cdy * bdxtail) - (bdy * cdxtail + cdx * bdytail)) +
          2.0 * (adx * adxtail + ady * adytail) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) * ((cdx * adytail + ady * cdxtail) - (cdy * adxtail + adx * cdytail)) +
          2.0 * (bdx * bdxtail + bdy * bdytail) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) * ((adx * bdytail + bdy * adxtail) - (ady * bdxtail + bdx * adytail)) +
          2.0 * (cdx * cdxtail + cdy * cdytail) * (adx * bdy - ady * bdx));
  if (std::abs(det) >= errbound) return det;

  // Stage D: Shewchuk refines incrementally; we recompute exactly instead, which
  // is simpler and costs nothing measurable since this stage is so rare.
  return incircle_exact(a, b, c, d);
}

}  // namespace

double orient2d(Point a, Point b, Point c) noexcept {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  double detsum = 0.0;
  // When the two products differ in sign (or one is zero) the subtraction
  // cannot cancel, so the floating-point sign is already exact.
  if (detleft > 0.0) {
    if (detright <= 0.0) return det;
    detsum = detleft + detright;
  } else if (detleft < 0.0) {
    if (detright >= 0.0) return det;
    detsum = -detleft - detright;
  } else {
    return det;
  }
  if (std::abs(det) >= kCcwErrBoundA * detsum) return det;
  return orient2d_adapt(a, b, c, detsum);
}

double incircle(Point a, Point b, Point c, Point d) noexcept {
  const auto [adx, ady] = difference(a, d);
  const auto [bdx, bdy] = difference(b, d);
  const auto [cdx, cdy] = difference(c, d);

  const double bdxcdy = bdx * cdy;
  const double cdxbdy = cdx * bdy;
  const double alift = adx * adx + ady * ady;
  const double cdxady = cdx * ady;
  const double adxcdy = adx * cdy;
  const double blift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy;
  const double bdxady = bdx * ady;
  const double clift = cdx * cdx + cdy * cdy;

  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * alift +
                           (std::abs(cdxady) + std::abs(adxcdy)) * blift +
                           (std::abs(adxbdy) + std::abs(bdxady)) * clift;
  const double errbound = kIccErrBoundA * permanent;
  if (det > errbound || -det > errbound) return det;
  return incircle_adapt(a, b, c, d, permanent);
}

}  // namespace madd
