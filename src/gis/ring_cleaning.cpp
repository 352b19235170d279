#include "gis/ring_cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

}  // namespace

double signed_area_of(const MarkedRing& ring) { return ring_signed_area(RingView(ring.points)); }

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
  for (MarkedRing& hole : holes) {
    std::size_t best = bodies.size();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (best < bodies.size() && areas[b] >= areas[best]) continue;
      const RingView outer(bodies[b].outer.points);
      RingLocation where = RingLocation::on_ring;
      for (std::size_t k = 0; k < hole.size() && where == RingLocation::on_ring; ++k)
        where = locate_in_ring(outer, hole.points[k]);
      if (where == RingLocation::inside) best = b;
    }
    if (best < bodies.size()) bodies[best].holes.push_back(std::move(hole));
  }
  return bodies;
}

}  // namespace madd::detail
