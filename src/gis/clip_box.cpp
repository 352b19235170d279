#include "gis/clip_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gis/ring_cleaning.hpp"
#include "kernel/rings.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Moves `side` outwards (towards `away`) until no coordinate in `values` equals it.
double off_values(double side, double away, const std::vector<double>& values) {
  while (std::binary_search(values.begin(), values.end(), side)) side = std::nextafter(side, away);
  return side;
}

// The sides of the box, counter-clockwise from its south-west corner.
enum Side : int { south = 0, east = 1, north = 2, west = 3 };

// Where a point on the box lies along its boundary, counter-clockwise from
// the south-west corner: south side [0, w), east [w, w + h), north
// [w + h, 2w + h), west [2w + h, 2w + 2h).
double perimeter_at(const ClipBox& box, Side side, Point p) {
  const double w = box.x1 - box.x0, h = box.y1 - box.y0;
  switch (side) {
  case south:
    return p.x - box.x0;
  case east:
    return w + (p.y - box.y0);
  case north:
    return w + h + (box.x1 - p.x);
  case west:
    return 2 * w + h + (box.y1 - p.y);
  }
  return 0.0;
}

Point corner(const ClipBox& box, int k) {
  switch (k & 3) {
  case 0:
    return {box.x1, box.y0};  // end of the south side
  case 1:
    return {box.x1, box.y1};
  case 2:
    return {box.x0, box.y1};
  default:
    return {box.x0, box.y0};
  }
}

bool inside(const ClipBox& box, Point p) { return box.x0 < p.x && p.x < box.x1 && box.y0 < p.y && p.y < box.y1; }

// Where segment pq crosses into and out of the box (Liang and Barsky's
// parameters), with the side of each crossing; crossings only when t0 < t1.
struct Crossing {
  double t0 = 0.0, t1 = 1.0;
  Side side0 = south, side1 = south;
  bool enters = false, leaves = false;
};

void clip_axis(double p, double d, double lo, double hi, Side low_side, Side high_side, Crossing& c) {
  if (d == 0.0) {
    if (p < lo || p > hi) c.t0 = infinity;
    return;
  }
  double enter = (lo - p) / d, leave = (hi - p) / d;
  Side enter_side = low_side, leave_side = high_side;
  if (d < 0.0) std::swap(enter, leave), std::swap(enter_side, leave_side);
  if (enter > c.t0) c.t0 = enter, c.side0 = enter_side, c.enters = true;
  if (leave < c.t1) c.t1 = leave, c.side1 = leave_side, c.leaves = true;
}

Crossing crossing_of(const ClipBox& box, Point p, Point q) {
  Crossing c;
  clip_axis(p.x, q.x - p.x, box.x0, box.x1, west, east, c);
  clip_axis(p.y, q.y - p.y, box.y0, box.y1, south, north, c);
  return c;
}

// The point at parameter t of pq, put exactly on `side`.
Point on_side(const ClipBox& box, Point p, Point q, double t, Side side) {
  Point x = lerp(p, q, t);
  x.x = std::clamp(x.x, box.x0, box.x1);
  x.y = std::clamp(x.y, box.y0, box.y1);
  if (side == south) x.y = box.y0;
  if (side == north) x.y = box.y1;
  if (side == west) x.x = box.x0;
  if (side == east) x.x = box.x1;
  return x;
}

// A piece of a ring inside the box, from where it enters to where it leaves.
struct Chain {
  MarkedRing ring;  // its last point is the exit; its last marker is unused until it is joined
  double entry = 0.0, exit = 0.0;
};

// The pieces of `ring` inside the box, in ring order, or none when the ring
// is wholly inside (then `whole` is set) or never meets the box.
std::vector<Chain> chains_of(const MarkedRing& ring, const ClipBox& box, bool& whole) {
  const std::size_t n = ring.size();
  std::size_t start = n;
  for (std::size_t k = 0; k < n && start == n; ++k)
    if (!inside(box, ring.points[k])) start = k;
  whole = start == n;
  std::vector<Chain> chains;
  if (whole) return chains;
  Chain current;
  bool open = false;
  const VertexOrigin made{ring.origins[start].polygon, ring.origins[start].ring, no_index};
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t k = (start + step) % n, next = (k + 1) % n;
    const Point p = ring.points[k], q = ring.points[next];
    const int marker = ring.markers[k];
    if (inside(box, q) && open) {
      current.ring.push(q, ring.markers[next], ring.origins[next]);
      continue;
    }
    const Crossing c = crossing_of(box, p, q);
    if (!(c.t0 < c.t1)) continue;  // misses the box, or only touches a corner
    if (!open) {
      current = Chain{};
      current.ring.push(on_side(box, p, q, c.t0, c.side0), marker, made);
      current.entry = perimeter_at(box, c.side0, current.ring.points.back());
      open = true;
    }
    if (inside(box, q)) {
      current.ring.push(q, ring.markers[next], ring.origins[next]);
      continue;
    }
    const Point exit = on_side(box, p, q, c.t1, c.side1);
    current.ring.push(exit, marker, made);
    current.exit = perimeter_at(box, c.side1, exit);
    chains.push_back(std::move(current));
    open = false;
  }
  return chains;
}

// The index of the chain whose entry comes first counter-clockwise from
// `from` (at `from` itself included), ties to the lowest index.
std::size_t next_entry(const std::vector<Chain>& chains, double from, double perimeter) {
  std::size_t best = 0;
  double best_gap = infinity;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    double gap = chains[c].entry - from;
    if (gap < 0.0) gap += perimeter;
    if (gap < best_gap) best_gap = gap, best = c;
  }
  return best;
}

// Appends the box corners passed going counter-clockwise from perimeter
// position `from` to `to` (less than a whole turn).
void add_corners(const ClipBox& box, double from, double to, double perimeter, int open_marker, MarkedRing& out,
                 const VertexOrigin& made) {
  const double w = box.x1 - box.x0, h = box.y1 - box.y0;
  const double corners[4] = {w, w + h, 2 * w + h, perimeter};
  if (to < from) to += perimeter;
  for (int turn = 0; turn < 2; ++turn)
    for (int k = 0; k < 4; ++k) {
      const double at = corners[k] + turn * perimeter;
      if (at > from && at < to) out.push(corner(box, k), open_marker, made);
    }
}

// Joins the chains into closed rings along the box's sides.
std::vector<MarkedRing> join_chains(std::vector<Chain> chains, const ClipBox& box, int open_marker) {
  const double perimeter = 2 * ((box.x1 - box.x0) + (box.y1 - box.y0));
  std::vector<bool> used(chains.size(), false);
  std::vector<MarkedRing> rings;
  for (std::size_t first = 0; first < chains.size(); ++first) {
    if (used[first]) continue;
    MarkedRing ring;
    std::size_t c = first;
    while (!used[c]) {
      used[c] = true;
      const Chain& chain = chains[c];
      for (std::size_t k = 0; k < chain.ring.size(); ++k)
        ring.push(chain.ring.points[k], chain.ring.markers[k], chain.ring.origins[k]);
      ring.markers.back() = open_marker;  // from the exit along the box
      const std::size_t next = next_entry(chains, chain.exit, perimeter);
      add_corners(box, chain.exit, chains[next].entry, perimeter, open_marker, ring, chain.ring.origins.back());
      c = next;
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

// The whole box as a ring of open boundary.
MarkedRing box_ring(const ClipBox& box, int open_marker, std::uint32_t polygon) {
  MarkedRing ring;
  for (int k = 3; k < 7; ++k) ring.push(corner(box, k), open_marker, {polygon, 0, no_index});
  return ring;
}

// Whether p lies in the polygon's water (inside its outer ring, outside its holes).
bool in_water(const MarkedPolygon& polygon, Point p) {
  int winding = winding_number(RingView(polygon.outer.points), p);
  for (const MarkedRing& hole : polygon.holes) winding += winding_number(RingView(hole.points), p);
  return winding != 0;
}

// The rings of one polygon inside the box: outers and holes sorted into bodies.
std::vector<MarkedPolygon> clip_polygon(const MarkedPolygon& polygon, const ClipBox& box, int open_marker) {
  std::vector<Chain> chains;
  std::vector<MarkedRing> rings;
  const auto take = [&](const MarkedRing& ring) {
    bool whole = false;
    std::vector<Chain> own = chains_of(ring, box, whole);
    if (whole) rings.push_back(ring);
    for (Chain& c : own) chains.push_back(std::move(c));
  };
  take(polygon.outer);
  for (const MarkedRing& hole : polygon.holes) take(hole);
  if (chains.empty()) {
    const Point probe{0.5 * (box.x0 + box.x1), box.y0};  // no ring crosses the box: the sides are all water or none
    if (in_water(polygon, probe)) rings.push_back(box_ring(box, open_marker, polygon.outer.origins[0].polygon));
  } else {
    for (MarkedRing& ring : join_chains(std::move(chains), box, open_marker)) rings.push_back(std::move(ring));
  }
  return bodies_of(std::move(rings));
}

}  // namespace

ClipBox box_off_vertices(std::span<const MarkedPolygon> polygons, ClipBox box) {
  std::vector<double> xs, ys;
  const auto add = [&](const MarkedRing& ring) {
    for (Point p : ring.points) xs.push_back(p.x), ys.push_back(p.y);
  };
  for (const MarkedPolygon& polygon : polygons) {
    add(polygon.outer);
    for (const MarkedRing& hole : polygon.holes) add(hole);
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  box.x0 = off_values(box.x0, -infinity, xs);
  box.x1 = off_values(box.x1, infinity, xs);
  box.y0 = off_values(box.y0, -infinity, ys);
  box.y1 = off_values(box.y1, infinity, ys);
  return box;
}

std::vector<MarkedPolygon> clip_to_box(std::span<const MarkedPolygon> polygons, ClipBox box, int open_marker) {
  std::vector<MarkedPolygon> bodies;
  for (const MarkedPolygon& polygon : polygons)
    for (MarkedPolygon& body : clip_polygon(polygon, box, open_marker)) bodies.push_back(std::move(body));
  return bodies;
}

}  // namespace madd::detail
