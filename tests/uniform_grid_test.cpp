// The one uniform grid (src/kernel/uniform_grid.hpp) and the searches built
// on it: both indexes list the same entries, a segment is listed in every
// cell it passes through, the ring search reaches every item, and the local
// feature size (src/mesh/feature_distance.hpp) is the one a scan of every
// feature finds, bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "kernel/segment_grid.hpp"
#include "kernel/segment_distance.hpp"
#include "kernel/uniform_grid.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"
#include "mesh/feature_distance.hpp"

using madd::Point;
using madd::Segment;
using madd::detail::UniformGrid;

namespace {

// Random segments in [0, 10] x [0, 4]: mostly short, some long, some
// axis-parallel, some of length 0, many sharing ends.
struct Segments {
  std::vector<Point> points;
  std::vector<Segment> segments;
};

Segments random_segments(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Segments s;
  for (int i = 0; i < n; ++i) {
    const Point a{10.0 * unit(rng), 4.0 * unit(rng)};
    Point b = a + 0.3 * Point{unit(rng) - 0.5, unit(rng) - 0.5};
    if (i % 7 == 0) b = {10.0 * unit(rng), 4.0 * unit(rng)};
    if (i % 11 == 0) b.y = a.y;
    if (i % 13 == 0) b.x = a.x;
    if (i % 17 == 0) b = a;
    const auto first = static_cast<std::uint32_t>(s.points.size());
    s.points.push_back(a);
    s.points.push_back(b);
    s.segments.push_back({first, first + 1, 1});
    if (i % 3 == 0 && first > 0) s.segments.push_back({first - 1, first, 1});  // shares an end
  }
  return s;
}

// The cells of a square grid over the segments, both ways.
UniformGrid segment_grid(const Segments& s, UniformGrid::Index index) {
  UniformGrid grid({0.0, 0.0}, 0.25, 0.25, 41, 17);
  grid.fill(static_cast<std::uint32_t>(s.segments.size()), index, [&](std::uint32_t i, auto&& add) {
    grid.segment_cells(s.points[s.segments[i].a], s.points[s.segments[i].b], 1e-6, 1e-6, add);
  });
  return grid;
}

// FeatureDistance's definition, by a scan of every feature: the distance to
// each segment sharing no end with a-b, and to the far end of each one that
// shares one.
double nearest_feature_by_scan(const Segments& s, Point p, std::uint32_t a, std::uint32_t b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& t : s.segments) {
    const bool shares_end = t.a == a || t.a == b || t.b == a || t.b == b;
    if (!shares_end) {
      // The same distance to one segment as the search's (exact equality
      // below): what is tested is that the search finds the nearest.
      best = std::min(best, madd::detail::segment_distance(p, s.points[t.a], s.points[t.b]));
      continue;
    }
    for (const std::uint32_t w : {t.a, t.b})
      if (w != a && w != b) best = std::min(best, madd::distance(p, s.points[w]));
  }
  return best;
}

}  // namespace

TEST_SUITE("uniform grid") {

TEST_CASE("uniform grid: the row index and the cell index list the same entries, in order") {
  const Segments s = random_segments(1, 400);
  const UniformGrid by_row = segment_grid(s, UniformGrid::Index::by_row);
  const UniformGrid by_cell = segment_grid(s, UniformGrid::Index::by_cell);
  REQUIRE(by_row.entries() == by_cell.entries());
  std::mt19937_64 rng(2);
  for (std::uint32_t row = 0; row < by_row.rows(); ++row) {
    const auto whole = by_row.row_range(row, 0, by_row.cols() - 1);
    // Sorted by column, then item: a cell's items increase.
    for (std::size_t k = 1; k < whole.size(); ++k)
      CHECK(
          (whole[k - 1].col < whole[k].col || (whole[k - 1].col == whole[k].col && whole[k - 1].item < whole[k].item)));
    for (int q = 0; q < 20; ++q) {
      auto c0 = static_cast<std::uint32_t>(rng() % by_row.cols()),
           c1 = static_cast<std::uint32_t>(rng() % by_row.cols());
      if (q % 5 == 0) c1 = c0;
      const auto x = by_row.row_range(row, c0, c1), y = by_cell.row_range(row, c0, c1);
      REQUIRE(x.size() == y.size());
      for (std::size_t k = 0; k < x.size(); ++k) {
        CHECK(x[k].col == y[k].col);
        CHECK(x[k].item == y[k].item);
        CHECK((x[k].col >= c0 && x[k].col <= c1));
      }
    }
  }
}

TEST_CASE("uniform grid: a segment is listed in the cell of every point along it") {
  const Segments s = random_segments(3, 300);
  const UniformGrid grid = segment_grid(s, UniformGrid::Index::by_cell);
  for (std::uint32_t i = 0; i < s.segments.size(); ++i) {
    const Point a = s.points[s.segments[i].a], b = s.points[s.segments[i].b];
    for (int k = 0; k <= 64; ++k) {
      const Point p = madd::lerp(a, b, k / 64.0);
      const std::uint32_t col = grid.col_of(p.x);
      const auto cell = grid.row_range(grid.row_of(p.y), col, col);
      CHECK(std::any_of(cell.begin(), cell.end(), [&](const UniformGrid::Entry& e) { return e.item == i; }));
    }
  }
}

TEST_CASE("uniform grid: the ring search reaches every item unless told to stop, nearest rings first") {
  const Segments s = random_segments(4, 200);
  const UniformGrid grid = segment_grid(s, UniformGrid::Index::by_row);
  for (const Point p : {Point{5, 2}, Point{0, 0}, Point{-30, 50}, Point{10.2, 1}}) {
    std::set<std::uint32_t> seen;
    grid.rings(
        p, [&](std::uint32_t i) { seen.insert(i); }, [](double) { return false; });
    CHECK(seen.size() == s.segments.size());
    // The bound handed to done() never exceeds the distance to an item not
    // yet visited: checked on the segments' ends.
    std::set<std::uint32_t> visited;
    grid.rings(
        p, [&](std::uint32_t i) { visited.insert(i); },
        [&](double lower) {
          for (std::uint32_t i = 0; i < s.segments.size(); ++i)
            if (visited.count(i) == 0)
              for (const std::uint32_t v : {s.segments[i].a, s.segments[i].b})
                CHECK(madd::distance(p, s.points[v]) >= lower);
          return false;
        });
  }
  CHECK(UniformGrid().cols() == 0);
  int visits = 0;
  UniformGrid().rings(
      {0, 0}, [&](std::uint32_t) { ++visits; }, [](double) { return false; });
  CHECK(visits == 0);
}

TEST_CASE("uniform grid: the local feature size is the scan's, bit for bit") {
  for (const std::uint64_t seed : {5u, 6u}) {
    Segments s = random_segments(seed, seed == 5 ? 500 : 40);
    // Isolated vertices, as discretise adds them: segments of length 0.
    s.points.push_back({5.0, 2.0});
    s.segments.push_back(
        {static_cast<std::uint32_t>(s.points.size() - 1), static_cast<std::uint32_t>(s.points.size() - 1), 0});
    const madd::detail::FeatureDistance features(s.points, s.segments);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::uint32_t j = 0; j < s.segments.size(); ++j) {
      const Segment& seg = s.segments[j];
      for (const double t : {0.0, 0.5, unit(rng), 1.0}) {
        const Point p = madd::lerp(s.points[seg.a], s.points[seg.b], t);
        CAPTURE(j);
        REQUIRE(features.to_nonincident(p, seg.a, seg.b) == nearest_feature_by_scan(s, p, seg.a, seg.b));
      }
    }
    // A query beside the segments, and one far outside the grid.
    for (const Point p : {Point{-3.0, 7.0}, Point{1e4, -2e3}})
      CHECK(features.to_nonincident(p, 0, 1) == nearest_feature_by_scan(s, p, 0, 1));
  }
  const std::vector<Point> none_points;
  const std::vector<Segment> none;
  CHECK(madd::detail::FeatureDistance(none_points, none).to_nonincident({0, 0}, 0, 1) ==
        std::numeric_limits<double>::infinity());
}

TEST_CASE("uniform grid: SegmentGrid lists each segment in the cells of its ends") {
  const Segments s = random_segments(7, 300);
  const madd::detail::SegmentGrid grid(s.points, s.segments);
  for (std::uint32_t i = 0; i < s.segments.size(); ++i)
    for (const std::uint32_t v : {s.segments[i].a, s.segments[i].b}) {
      const Point p = s.points[v];
      CHECK(grid.contains(p));
      const std::uint32_t col = grid.col_of(p.x);
      const auto cell = grid.row_range(grid.row_of(p.y), col, col);
      CHECK(std::any_of(cell.begin(), cell.end(), [&](const UniformGrid::Entry& e) { return e.item == i; }));
    }
}

}  // TEST_SUITE("uniform grid")
