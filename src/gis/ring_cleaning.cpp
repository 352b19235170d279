#include "gis/ring_cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "kernel/containment.hpp"
#include "kernel/rings.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

void reverse_ring(MarkedRing& ring) {
  // Edge k (points[k] -> points[k + 1]) becomes the edge from points[k + 1]
  // back to points[k]: reverse the points, then shift the markers by one.
  const std::size_t n = ring.size();
  if (n < 2) return;
  std::vector<int> markers(n);
  for (std::size_t k = 0; k < n; ++k) markers[n - 1 - k] = ring.markers[k];
  std::reverse(ring.points.begin(), ring.points.end());
  std::reverse(ring.origins.begin(), ring.origins.end());
  // After reversing, the edge from new vertex j to j + 1 is old edge n - 2 - j.
  for (std::size_t j = 0; j < n; ++j) ring.markers[j] = markers[(j + 1) % n];
}

// b doubles back: the ring goes on from b along the way it came (exactly
// collinear, reversing; a repeated vertex is a merge, not a spike).
bool spike(Point a, Point b, Point c) { return orient2d(a, b, c) == 0.0 && dot(b - a, c - b) < 0.0; }

// The ring as a circular list that vertices leave one at a time.
struct RingList {
  const MarkedRing& ring;
  std::vector<std::size_t> prev, next;
  std::vector<int> marker;  // of the edge from a vertex to its next one still in the list
  std::vector<bool> alive;
  std::size_t size;

  explicit RingList(const MarkedRing& r)
      : ring(r), prev(r.size()), next(r.size()), marker(r.markers), alive(r.size(), true), size(r.size()) {
    for (std::size_t k = 0; k < size; ++k) next[k] = (k + 1) % size, prev[(k + 1) % size] = k;
  }
  Point at(std::size_t v) const { return ring.points[v]; }
  // Removes v; the edge from prev(v) now runs to next(v) with the marker of
  // the longer of the two edges it replaces.
  void remove(std::size_t v) {
    const std::size_t p = prev[v], n = next[v];
    if (distance(at(v), at(n)) > distance(at(p), at(v))) marker[p] = marker[v];
    next[p] = n, prev[n] = p, alive[v] = false, --size;
  }
};

// An outer ring's edges filed by rows of y, for locate_in_ring's answer at
// many points (the islands of a clipped sea: thousands of holes against
// rings of 10^5 vertices) in the time of the edges of one row. Exactly
// locate_in_ring's: only an edge whose y-span holds p's height can hold p
// or cross the ray from p, and every such edge is filed in p's row.
class RowLocator {
public:
  explicit RowLocator(const std::vector<Point>& ring) {
    for (Point p : ring)
      x0_ = std::min(x0_, p.x), x1_ = std::max(x1_, p.x), y0_ = std::min(y0_, p.y), y1_ = std::max(y1_, p.y);
    rows_ = std::clamp<std::size_t>(ring.size() / 2, 1, std::size_t{1} << 16);
    height_ = y1_ > y0_ ? (y1_ - y0_) / static_cast<double>(rows_) : 1.0;
    std::vector<std::uint32_t> count(rows_ + 1, 0);
    const auto each_edge = [&](auto&& f) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Point a = ring[k], b = ring[(k + 1) % ring.size()];
        for (std::size_t r = row_of(std::min(a.y, b.y)); r <= row_of(std::max(a.y, b.y)); ++r) f(r, a, b);
      }
    };
    each_edge([&](std::size_t r, Point, Point) { ++count[r + 1]; });
    first_.assign(rows_ + 1, 0);
    for (std::size_t r = 0; r < rows_; ++r) first_[r + 1] = first_[r] + count[r + 1];
    ends_.resize(2 * static_cast<std::size_t>(first_[rows_]));
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    each_edge([&](std::size_t r, Point a, Point b) {
      ends_[2 * static_cast<std::size_t>(fill[r])] = a, ends_[2 * static_cast<std::size_t>(fill[r]) + 1] = b;
      ++fill[r];
    });
  }

  RingLocation locate(Point p) const {
    if (!(p.x >= x0_ && p.x <= x1_ && p.y >= y0_ && p.y <= y1_)) return RingLocation::outside;
    const std::size_t r = row_of(p.y);
    int winding = 0;
    for (std::size_t e = first_[r]; e < first_[r + 1]; ++e) {
      const Point a = ends_[2 * e], b = ends_[2 * e + 1];
      if (on_segment(a, b, p)) return RingLocation::on_ring;
      // The crossings of the ray from p towards +x, half-open in y, as kernel/rings.cpp counts them.
      const bool up = a.y <= p.y && b.y > p.y && orient2d(a, b, p) > 0.0;
      const bool down = a.y > p.y && b.y <= p.y && orient2d(a, b, p) < 0.0;
      winding += up ? 1 : down ? -1 : 0;
    }
    return winding != 0 ? RingLocation::inside : RingLocation::outside;
  }

private:
  std::size_t row_of(double y) const {
    const double at = (y - y0_) / height_;
    return at <= 0.0 ? 0 : std::min(rows_ - 1, static_cast<std::size_t>(at));
  }
  double x0_ = std::numeric_limits<double>::infinity(), x1_ = -x0_, y0_ = x0_, y1_ = -x0_, height_ = 1.0;
  std::size_t rows_ = 1;
  std::vector<std::uint32_t> first_;
  std::vector<Point> ends_;
};

}  // namespace

double signed_area_of(const MarkedRing& ring) { return ring_signed_area(RingView(ring.points)); }

bool flat(const MarkedRing& ring) {
  const std::size_t n = ring.size();
  std::size_t other = 1;
  while (other < n && ring.points[other] == ring.points[0]) ++other;
  for (std::size_t k = other + 1; k < n; ++k)
    if (orient2d(ring.points[0], ring.points[other], ring.points[k]) != 0.0) return false;
  return true;
}

void orient_for_water(MarkedPolygon& polygon) {
  if (signed_area_of(polygon.outer) < 0.0) reverse_ring(polygon.outer);
  for (MarkedRing& hole : polygon.holes)
    if (signed_area_of(hole) > 0.0) reverse_ring(hole);
}

RingCleaning clean_ring(MarkedRing& ring, double merge_distance) {
  RingCleaning done;
  if (ring.size() < 3) return done;
  RingList list(ring);
  std::vector<std::size_t> work(ring.size());
  for (std::size_t k = 0; k < work.size(); ++k) work[k] = work.size() - 1 - k;  // vertex 0 first
  while (!work.empty() && list.size >= 3) {
    const std::size_t v = work.back();
    work.pop_back();
    if (!list.alive[v]) continue;
    const std::size_t p = list.prev[v], n = list.next[v];
    if (distance(list.at(p), list.at(v)) <= merge_distance) {
      list.remove(v);  // merged into the vertex before it
      ++done.merged;
    } else if (spike(list.at(p), list.at(v), list.at(n))) {
      list.remove(v);
      ++done.spikes;
    } else {
      continue;
    }
    work.push_back(n), work.push_back(p);
  }
  MarkedRing kept;
  std::size_t first = 0;
  while (first < ring.size() && !list.alive[first]) ++first;
  if (list.size >= 1 && first < ring.size()) {
    std::size_t v = first;
    do {
      kept.push(ring.points[v], list.marker[v], ring.origins[v]);
      v = list.next[v];
    } while (v != first);
  }
  ring = std::move(kept);
  return done;
}

std::vector<MarkedPolygon> bodies_of(std::vector<MarkedRing> rings) {
  std::vector<MarkedPolygon> bodies;
  std::vector<double> areas;
  std::vector<MarkedRing> holes;
  for (MarkedRing& ring : rings) {
    const double area = signed_area_of(ring);
    if (area > 0.0) {
      bodies.push_back({std::move(ring), {}});
      areas.push_back(area);
    } else if (area < 0.0) {
      holes.push_back(std::move(ring));
    }
  }
  std::vector<RowLocator> outers;
  if (!holes.empty())
    for (const MarkedPolygon& body : bodies) outers.emplace_back(body.outer.points);
  for (MarkedRing& hole : holes) {
    std::size_t best = bodies.size();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (best < bodies.size() && areas[b] >= areas[best]) continue;
      RingLocation where = RingLocation::on_ring;
      for (std::size_t k = 0; k < hole.size() && where == RingLocation::on_ring; ++k)
        where = outers[b].locate(hole.points[k]);
      if (where == RingLocation::inside) best = b;
    }
    if (best < bodies.size()) bodies[best].holes.push_back(std::move(hole));
  }
  return bodies;
}

}  // namespace madd::detail
