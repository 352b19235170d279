#pragma once
// The distance term on the background, kept on the safe side: the point
// values the term may take so that its linear interpolant never exceeds
// hmin + G d(x), d the exact distance to the coast, anywhere in an inside
// triangle (the check madd's users make from outside: a triangle's area at
// most sqrt(3)/4 min(hmax, hmin + G d(centroid))^2).
//
// Why it is safe. Let T be an inside triangle, v its corners, L the linear
// interpolant of the values d(v), x in T and lambda its barycentric
// coordinates. d = min over coast pieces s of d_s, the distance to s, and
// d(v) <= d_s(v), so L <= L_s, the interpolant of d_s. Two bounds on
// L_s(x) - d_s(x), each valid for every s:
// - Lipschitz: d_s is 1-Lipschitz, so d_s(x) >= d_s(v) - |x - v| for each
//   corner, and L_s(x) - d_s(x) <= sum lambda_v |x - v|
//   <= sqrt(sum lambda_v |x - v|^2) = sqrt(R^2 - |x - c|^2) <= rho,
//   (Cauchy-Schwarz; c, R the circumcentre and circumradius), rho the
//   radius of T's smallest enclosing circle (R when T is acute, half its
//   longest edge otherwise: the largest value of R^2 - |x - c|^2 over T).
// - Convexity: d_s is convex; T crosses no coast piece (they are
//   constrained edges of the background), so on T d_s is linear where x
//   projects into s and the distance to an end p of s elsewhere, C^1 across,
//   with Hessian at most 1 / |x - p| <= 1 / r, r a lower bound of the
//   distance from T to every end of a coast piece. Then d_s - |x|^2 / (2r)
//   is concave and L_s(x) - d_s(x) <= (R^2 - |x - c|^2) / (2r) <= rho^2 / (2r).
// So d(x) = d_s(x) for the nearest s >= L_s(x) - delta_T >= L(x) - delta_T
// with delta_T = min(rho, rho^2 / (2r)), r = max over the corners v of
// (distance from v to the nearest coast vertex - the longest edge at v),
// when positive. A point's value is hmin + G (d(v) - max over its inside
// triangles of delta_T), less 1e-9 of it against rounding: then in every
// inside triangle the interpolant is <= hmin + G (L(x) - delta_T) <=
// hmin + G d(x). Values below hmin + G d only lower the field (safe), and
// hmax needs nothing: an interpolant of values <= hmax is <= hmax.
#include <span>
#include <vector>

#include "sizing/raw_field.hpp"
#include "sizing/size_background.hpp"

namespace madd::detail {

// delta_T of inside triangle t (in units of distance), and the centre and
// radius of its smallest enclosing circle.
struct TriangleBound {
  double delta = 0.0;
  Point centre;
  double rho = 0.0;
};
TriangleBound triangle_bound(const SizeBackground& background, std::span<const RawSample> samples, std::uint32_t t);

// Per point of `background`, the largest value the distance term may take
// there (+infinity for points of no inside triangle, and without a distance
// term), over the inside triangles `exact` does not flag (those read the
// exact distance instead, coast_candidates.hpp; empty: none is). `samples`
// are the raw terms at the points.
std::vector<double> safe_distance_values(const SizeBackground& background, std::span<const RawSample> samples,
                                         double hmin, double rate, const std::vector<bool>& exact = {});

}  // namespace madd::detail
