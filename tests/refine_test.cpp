// Boundary refinement of one face (paper Sec. 3, src/split/refine.cpp):
// uniform pieces at the spacing, and, with boundary weights, the adaptive
// refine level (Table I): a heavy edge gets min(its weight / the mean, L)
// times more pieces.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "split/refine.hpp"
#include "subdivision/subdivision.hpp"

namespace {

using madd::Point;
using madd::Pslg;
using madd::detail::EndRef;
using madd::detail::FaceDomain;

// A unit square with the midpoint of every side as a vertex (8 vertices,
// 8 segments of length 0.5, segment k from vertex k to k + 1).
Pslg square_with_midpoints() {
  Pslg p;
  p.first_index = 0;
  p.points = {{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}};
  for (std::uint32_t i = 0; i < 8; ++i) p.segments.push_back({i, (i + 1) % 8, 1});
  return p;
}

std::size_t points_inside_segment(const FaceDomain& fd, std::uint32_t segment) {
  std::size_t n = 0;
  for (const EndRef& r : fd.refs) n += r.kind == EndRef::inside_segment && r.id == segment ? 1 : 0;
  return n;
}

}  // namespace

TEST_SUITE("refine") {

TEST_CASE("each edge is cut into ceil(length / spacing) equal pieces") {
  const auto sub = madd::detail::Subdivision::from_domain(square_with_midpoints());
  const FaceDomain fd = madd::detail::refine_face(sub, 0, 0.05);
  CHECK(fd.pslg.points.size() == 8 * 10);  // 8 vertices + 8 x 9 interior points
  for (std::uint32_t s = 0; s < 8; ++s) CHECK(points_inside_segment(fd, s) == 9);
}

TEST_CASE("adaptive refine level: a heavy edge gets min(weight / mean, L) times more pieces") {
  const auto sub = madd::detail::Subdivision::from_domain(square_with_midpoints());
  // Vertices 0 and 1 weigh 1, the others 0: the mean vertex weight is 1/4, so
  // segment 0 (0 -> 1) weighs 4 x the mean, its neighbours 7 and 1 twice the
  // mean, the others nothing.
  std::vector<double> weights(sub.points.size(), 0.0);
  weights[0] = weights[1] = 1.0;
  for (const double level : {1.0, 2.0, 3.0, 4.0, 8.0}) {
    CAPTURE(level);
    const FaceDomain fd = madd::detail::refine_face(sub, 0, 0.05, &weights, level);
    const double heavy = std::min(4.0, level), half = std::min(2.0, level);
    CHECK(points_inside_segment(fd, 0) == static_cast<std::size_t>(10 * heavy) - 1);
    CHECK(points_inside_segment(fd, 1) == static_cast<std::size_t>(10 * half) - 1);
    CHECK(points_inside_segment(fd, 7) == static_cast<std::size_t>(10 * half) - 1);
    for (const std::uint32_t s : {2u, 3u, 4u, 5u, 6u}) CHECK(points_inside_segment(fd, s) == 9);
  }
}

}  // TEST_SUITE("refine")
