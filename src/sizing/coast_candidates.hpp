#pragma once
// The exact distance to the coast inside the background's triangles.
// A piecewise linear distance term would have to be lowered by its safety
// bound (distance_bound.hpp), loosest at the coast: a triangle with a corner
// on a coast vertex may only trust d to within its enclosing radius, and
// the interpolant of the concave d (a minimum of distances) lies below it
// besides. Measured on real coastlines, that made meshes a third to a half
// larger than the raw term asks. So each inside triangle keeps the few
// coast pieces that can be nearest to any of its points, and the field
// reads hmin + G d(x) exactly, as the minimum with its linear part.
//
// Which pieces: for x in T, d(x) <= d(v) + |x - v| <= D_T = min over the
// corners v of (d(v) + the longest edge at v), and every x is within rho
// (T's enclosing radius) of the enclosing circle's centre c: the piece
// nearest to x is within D_T + rho of c. Every coast piece that close is
// kept, so the minimum over them is d(x) itself; then those farther from T
// than some piece's largest distance to T's corners are dropped (they are
// never the nearest in T). (Keeping lists per quarter of T halved a query's
// pieces, but cost more to build than it saved on the queries a mesh of 20
// triangles per background triangle makes.)
//
// An outside triangle with a corner on the water keeps the pieces of the
// inside triangles around its water corners: a point on the coast, or a
// rounding off it onto the land, reads hmin + G d as from the water beside
// it, not the linear part, which the land does not grade
// (coast_candidates.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "sizing/coast.hpp"
#include "sizing/raw_field.hpp"
#include "sizing/size_background.hpp"

namespace madd::detail {

class CoastCandidates {
public:
  CoastCandidates() = default;
  // The lists are found on `threads` threads (0: one per core), the same for any count.
  CoastCandidates(const SizeBackground& background, std::span<const RawSample> samples, const Coast& coast,
                  unsigned threads = 1);
  bool exact(std::uint32_t t) const noexcept { return !start_.empty() && start_[t] != start_[t + 1]; }
  // d(p) for p in exact triangle t.
  double distance(std::uint32_t t, Point p) const noexcept {
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t k = start_[t]; k < start_[t + 1]; ++k) {
      const Piece& e = pieces_[piece_[k]];
      const Point ap = p - e.a;
      const double s = std::clamp(dot(ap, e.ab) * e.inverse, 0.0, 1.0);
      const Point q = ap - s * e.ab;
      best = std::min(best, dot(q, q));
    }
    return std::sqrt(best);
  }
  std::size_t exact_triangles() const noexcept;
  std::size_t candidates() const noexcept { return piece_.size(); }

private:
  void prune(const Point (&corner)[3], std::vector<std::uint32_t>& near) const;
  std::vector<std::uint32_t> start_;        // per triangle + 1: offsets into piece_
  std::vector<std::uint32_t> piece_;        // indices into ends_
  std::vector<std::array<Point, 2>> ends_;  // the coast pieces' ends
  // The same, for the query: a start, the vector to the end and 1 / its
  // squared length (a multiplication where the query would divide).
  struct Piece {
    Point a, ab;
    double inverse;
  };
  std::vector<Piece> pieces_;
};

}  // namespace madd::detail
