// Ring geometry: the one implementation of ring area, orientation and point
// location that every stage uses.
#include "kernel/rings.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/containment.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

// What edge a -> b adds to the winding number around p: the crossings of the
// ray from p towards +x. Half-open in y (an end at p's height counts as above
// the ray), so a vertex the ray passes through is counted once; orient2d
// decides on which side of the edge p lies, and an edge through p is not
// crossed (see winding_number for what that means).
int crossing(Point a, Point b, Point p) noexcept {
  if (a.y <= p.y) return b.y > p.y && orient2d(a, b, p) > 0.0 ? 1 : 0;  // upward, p on its left
  return b.y <= p.y && orient2d(a, b, p) < 0.0 ? -1 : 0;                // downward, p on its right
}

bool lower_then_lefter(Point a, Point b) noexcept { return a.y < b.y || (a.y == b.y && a.x < b.x); }

}  // namespace

double ring_signed_area(RingView ring) noexcept {
  if (ring.size() < 3) return 0.0;
  const Point o = ring[0];
  double twice = 0.0;
  for (std::size_t k = 1; k + 1 < ring.size(); ++k) twice += cross(ring[k] - o, ring[k + 1] - o);
  return 0.5 * twice;
}

double rings_area(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) noexcept {
  double area = 0.0;
  for (const auto& ring : rings) area += ring_signed_area(RingView(points, ring));
  return area;
}

// The error of ring_signed_area, in Higham's notation (eps = 2^-53, the unit
// roundoff; gamma_k = k eps / (1 - k eps); every operation is exact up to a
// factor (1 + delta), |delta| <= eps). With o = ring[0], the fan has m = n - 2
// terms c_k = fl(fl(u.x v.y) - fl(u.y v.x)), u = fl(p_k - o), v = fl(p_k+1 - o).
// Let X_k, Y_k be the exact products of the exact differences. Each computed
// product is X_k (1 + theta_3) (two differences, one product), the
// subtraction adds one more factor, so c_k = X_k (1 + theta_4) - Y_k (1 + theta_4').
// Summing the m terms from 0.0 rounds each of them at most m - 1 times, so
// twice = sum_k X_k (1 + theta_m+3) - Y_k (1 + theta'_m+3), and
//   |twice - exact twice area| <= gamma_(n+1) S,   S = sum_k |X_k| + |Y_k|.
// (A fused multiply-add in the subtraction only removes a rounding.)
// S is not available exactly; its floating-point evaluation S' (the same
// products, 2m - 1 additions of nonnegative values) satisfies
// S <= S' / ((1 - gamma_3)(1 - gamma_(2m-1))). For n < 2^32, n eps < 2^-21, and
//   gamma_(n+1) / ((1 - gamma_3)(1 - gamma_2n))  <=  (n + 1) eps (1 + 2^-18),
// so (n + 1) eps S' (1 + 2^-16) bounds the error of twice the area, with room
// for the three roundings of the bound itself. Halving is exact.
double ring_signed_area_error(RingView ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3) return 0.0;
  const Point o = ring[0];
  double magnitude = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Point u = ring[k] - o;
    const Point v = ring[k + 1] - o;
    magnitude += std::abs(u.x * v.y) + std::abs(u.y * v.x);
  }
  constexpr double eps = 0x1p-53;
  return 0.5 * (static_cast<double>(n + 1) * eps) * magnitude * (1.0 + 0x1p-16);
}

// rings_area adds R ring areas a_r from 0.0: |fl(sum a_r) - sum a_r| <=
// gamma_(R-1) sum |a_r|, on top of each ring's own error; the factor
// (1 + 2^-16) again covers gamma's denominator and the roundings of this sum.
double rings_area_error(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) noexcept {
  double each = 0.0;
  double magnitude = 0.0;
  for (const auto& ring : rings) {
    each += ring_signed_area_error(RingView(points, ring));
    magnitude += std::abs(ring_signed_area(RingView(points, ring)));
  }
  constexpr double eps = 0x1p-53;
  return (each + static_cast<double>(rings.size()) * eps * magnitude) * (1.0 + 0x1p-16);
}

Orientation ring_orientation(RingView ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3) return Orientation::degenerate;
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < n; ++k) {
    if (lower_then_lefter(ring[k], ring[lowest])) lowest = k;
  }
  const double turn = orient2d(ring[(lowest + n - 1) % n], ring[lowest], ring.after(lowest));
  if (turn > 0.0) return Orientation::counter_clockwise;
  return turn < 0.0 ? Orientation::clockwise : Orientation::degenerate;
}

int winding_number(RingView ring, Point p) noexcept {
  int winding = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) winding += crossing(ring[k], ring.after(k), p);
  return winding;
}

WindingIndex::WindingIndex(std::span<const Point> points, std::span<const std::vector<std::uint32_t>> rings) {
  std::size_t edges = 0;
  bool any = false;
  for (const auto& ring : rings) {
    edges += ring.size();
    for (const std::uint32_t v : ring) {
      y0_ = any ? std::min(y0_, points[v].y) : points[v].y;
      y1_ = any ? std::max(y1_, points[v].y) : points[v].y;
      any = true;
    }
  }
  // About two edges a row; coast edges span a row or two.
  rows_ = std::clamp<std::size_t>(edges / 2, 1, std::size_t{1} << 16);
  row_height_ = y1_ > y0_ ? (y1_ - y0_) / static_cast<double>(rows_) : 1.0;
  // Two passes: count each row's edges, then file them. row_of is
  // monotone in y, so an edge filed in rows row_of(lower end) to
  // row_of(upper end) is in the row of every height it spans.
  std::vector<std::uint32_t> count(rows_ + 1, 0);
  const auto each_edge = [&](auto&& f) {
    for (const auto& ring : rings) {
      const RingView view(points, ring);
      for (std::size_t k = 0; k < view.size(); ++k) f(view[k], view.after(k));
    }
  };
  each_edge([&](Point a, Point b) {
    for (std::size_t r = row_of(std::min(a.y, b.y)); r <= row_of(std::max(a.y, b.y)); ++r) ++count[r + 1];
  });
  first_.assign(rows_ + 1, 0);
  for (std::size_t r = 0; r < rows_; ++r) first_[r + 1] = first_[r] + count[r + 1];
  edges_.resize(2 * static_cast<std::size_t>(first_[rows_]));
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  each_edge([&](Point a, Point b) {
    for (std::size_t r = row_of(std::min(a.y, b.y)); r <= row_of(std::max(a.y, b.y)); ++r) {
      edges_[2 * static_cast<std::size_t>(fill[r])] = a;
      edges_[2 * static_cast<std::size_t>(fill[r]) + 1] = b;
      ++fill[r];
    }
  });
}

std::size_t WindingIndex::row_of(double y) const noexcept {
  const double r = std::floor((y - y0_) / row_height_);
  if (!(r > 0.0)) return 0;
  return std::min(rows_ - 1, static_cast<std::size_t>(r));
}

int WindingIndex::winding(Point p) const noexcept {
  // Every edge counted spans p's height (half-open): none outside [y0, y1].
  if (!(p.y >= y0_ && p.y <= y1_)) return 0;
  const std::size_t r = row_of(p.y);
  int winding = 0;
  for (std::size_t e = first_[r]; e < first_[r + 1]; ++e) winding += crossing(edges_[2 * e], edges_[2 * e + 1], p);
  return winding;
}

RingLocation locate_in_ring(RingView ring, Point p) noexcept {
  int winding = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k], b = ring.after(k);
    if (on_segment(a, b, p)) return RingLocation::on_ring;
    winding += crossing(a, b, p);
  }
  return winding != 0 ? RingLocation::inside : RingLocation::outside;
}

}  // namespace madd::detail
