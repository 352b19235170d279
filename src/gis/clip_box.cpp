#include "gis/clip_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "kernel/coordinate_range.hpp"
#include "gis/ring_cleaning.hpp"
#include "kernel/rings.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Moves `side` outwards (towards `away`) until no coordinate in `values`
// (sorted) equals it; never to a magnitude below 1e-40, which coast_domain
// reads as 0 (the predicates' range), back onto a vertex at 0.
double off_values(double side, double away, const std::vector<double>& values) {
  while (std::binary_search(values.begin(), values.end(), side)) {
    side = std::nextafter(side, away);
    if (std::abs(side) < min_coordinate_magnitude) side = std::copysign(min_coordinate_magnitude, away);
  }
  return side;
}

// `side` moved off the vertices' x (or y) coordinates, as off_values does
// with all of them, from only those within a reach of it: sorting all of a
// world's 10^6 coordinates for every box would be most of the clipping's
// time. The answer is the same when the side moved less than the reach
// (every value it stepped over was within it); else the reach grows.
double off_vertices(std::span<const MarkedPolygon> polygons, bool x, double side, double away) {
  for (double reach = 1e-9 * std::abs(side) + 1e-30;; reach *= 1e6) {
    std::vector<double> values;
    const auto add = [&](const MarkedRing& ring) {
      for (Point p : ring.points)
        if (std::abs((x ? p.x : p.y) - side) <= reach) values.push_back(x ? p.x : p.y);
    };
    for (const MarkedPolygon& polygon : polygons) {
      add(polygon.outer);
      for (const MarkedRing& hole : polygon.holes) add(hole);
    }
    std::sort(values.begin(), values.end());
    const double moved = off_values(side, away, values);
    if (std::abs(moved - side) < reach) return moved;
  }
}

// The sides of the box, counter-clockwise from its south-west corner.
enum Side : int { south = 0, east = 1, north = 2, west = 3 };

// Where a ring edge crosses the box: the side it crosses, decided exactly
// (entry_side), and a coordinate that grows counter-clockwise along that
// side (x on the south side, y on the east, -x on the north, -y on the
// west), with no sums of side lengths, which would round and misorder
// points near a corner. The place keeps the edge: two crossings of a side
// are ordered exactly by their edges (crossing_order), since their rounded
// coordinates tie or swap where it matters most, at a vertex an ulp inside
// the box (box_off_vertices puts one there for every vertex that was on a
// side), and a swap there joins the water the wrong way round the box.
struct Place {
  int side = south;
  double along = 0.0;
  Point point;  // on the box
  Point a, b;   // the ring edge crossing the box here
};

double side_start(const ClipBox& box, int side) {
  const double start[4] = {box.x0, box.y0, -box.x1, -box.y1};
  return start[side];
}

double side_line(const ClipBox& box, int side) {
  const double line[4] = {box.y0, box.x1, box.y1, box.x0};
  return line[side];
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// The sign of h1 - h2, where edge k (ak, bk) crosses the vertical line
// x = c at height hk, exactly, for edges that both span the line and do not
// cross each other; nullopt when they cross (their order then depends on
// where, which orient2d cannot say). In the overlap [lo, hi] of their
// x-spans the height difference is linear in x: its sign at lo and at hi
// is the side of the edge ending there against the other edge.
std::optional<int> height_order(Point a1, Point b1, Point a2, Point b2) {
  if (a1.x > b1.x) std::swap(a1, b1);
  if (a2.x > b2.x) std::swap(a2, b2);
  const auto above = [](Point a, Point b, Point w) { return sign(orient2d(a, b, w)); };  // ab runs left to right
  const int at_lo = a2.x >= a1.x ? -above(a1, b1, a2) : above(a2, b2, a1);
  const int at_hi = b2.x <= b1.x ? -above(a1, b1, b2) : above(a2, b2, b1);
  if (at_lo == 0 || at_lo == at_hi) return at_hi;
  if (at_hi == 0) return at_lo;
  return std::nullopt;
}

// Whether two crossings of one side come in this order (-1), at one point
// (0) or the other way (1) going counter-clockwise; nullopt when undecided.
std::optional<int> crossing_order(const ClipBox& box, const Place& p, const Place& q) {
  const bool vertical = p.side == east || p.side == west;
  const auto flip = [&](Point v) { return vertical ? v : Point{v.y, v.x}; };  // the side's line vertical
  const double c = side_line(box, p.side);
  const auto spans = [&](const Place& x) { return (flip(x.a).x < c) != (flip(x.b).x < c); };
  if (!spans(p) || !spans(q)) return std::nullopt;
  const std::optional<int> order = height_order(flip(p.a), flip(p.b), flip(q.a), flip(q.b));
  if (!order) return std::nullopt;
  return p.side == south || p.side == east ? *order : -*order;
}

// p comes strictly before q counter-clockwise from the south-west corner.
bool before(const ClipBox& box, const Place& p, const Place& q) {
  if (p.side != q.side) return p.side < q.side;
  if (const std::optional<int> order = crossing_order(box, p, q)) return *order < 0;
  return p.along < q.along;
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

// Whether the edge pq, both ends outside the box, passes through it: the
// part of its line in the box (Liang and Barsky's parameters) lies within
// the edge. Rounded; a wrong answer only for an edge grazing a corner,
// which then cuts off or misses a sliver.
bool passes_through(const ClipBox& box, Point p, Point q) {
  double t0 = 0.0, t1 = 1.0;
  const auto axis = [&](double a, double d, double lo, double hi) {
    if (d == 0.0) {
      if (a < lo || a > hi) t0 = infinity;
      return;
    }
    double enter = (lo - a) / d, leave = (hi - a) / d;
    if (d < 0.0) std::swap(enter, leave);
    t0 = std::max(t0, enter), t1 = std::min(t1, leave);
  };
  axis(p.x, q.x - p.x, box.x0, box.x1);
  axis(p.y, q.y - p.y, box.y0, box.y1);
  return t0 < t1;
}

// The side through which pq, p outside the box, gets in (or would, were it
// long enough), exactly: the side whose outer half-plane p is in, or, for p
// beyond a corner, the side before or after that corner as q is to the left
// or the right of the ray from p through it (seen from outside, the side
// after a corner, counter-clockwise, is on the right). Rounded crossing
// parameters tie near a corner and can pick the side not crossed, and then
// the order of crossings along the box, and the water joined along it,
// goes wrong.
Side entry_side(const ClipBox& box, Point p, Point q) {
  const bool w = p.x<box.x0, e = p.x> box.x1, s = p.y<box.y0, n = p.y> box.y1;
  int k = -1;  // the corner p is beyond: corner(k) ends side k and starts side k + 1
  if (s && e) k = 0;
  if (e && n) k = 1;
  if (n && w) k = 2;
  if (w && s) k = 3;
  if (k < 0) return s ? south : e ? east : n ? north : west;
  return static_cast<Side>(orient2d(p, corner(box, k), q) > 0.0 ? k : (k + 1) % 4);
}

// Where pq meets the line of `side`, exactly on it and within the box:
// interpolated from the end nearer the line (p + t (q - p) at t near 1 can
// be off by an ulp of p, more than that end's distance to the box).
Place crossing_place(const ClipBox& box, Point p, Point q, Side side) {
  const bool vertical = side == east || side == west;
  const double c = side_line(box, side);
  const auto u = [&](Point v) { return vertical ? v.x : v.y; };
  const auto w = [&](Point v) { return vertical ? v.y : v.x; };
  const Point near = std::abs(u(p) - c) <= std::abs(u(q) - c) ? p : q, far = near == p ? q : p;
  double at = u(far) == u(near) ? w(near) : w(near) + (c - u(near)) * ((w(far) - w(near)) / (u(far) - u(near)));
  at = vertical ? std::clamp(at, box.y0, box.y1) : std::clamp(at, box.x0, box.x1);
  const Point point = vertical ? Point{c, at} : Point{at, c};
  const double along[4] = {point.x, point.y, -point.x, -point.y};
  return {side, along[side], point, p, q};
}

// A piece of a ring inside the box, from where it enters to where it leaves.
struct Chain {
  MarkedRing ring;  // its last point is the exit; its last marker is unused until it is joined
  Place entry, exit;
};

// The pieces of `ring` inside the box, in ring order, or none when the ring
// is wholly inside (then `whole` is set) or never meets the box. Whether an
// edge enters or leaves is decided by its ends (exactly: no vertex is on the
// box), not by the rounded crossing parameters, which can say that an edge
// from far outside to a vertex an ulp inside never gets in.
std::vector<Chain> chains_of(const MarkedRing& ring, const ClipBox& box, bool& whole) {
  const std::size_t n = ring.size();
  std::size_t start = n;
  for (std::size_t k = 0; k < n && start == n; ++k)
    if (!inside(box, ring.points[k])) start = k;
  whole = start == n;
  std::vector<Chain> chains;
  if (whole) return chains;
  Chain current;
  bool open = false;  // the last vertex was inside
  const VertexOrigin made{ring.origins[start].polygon, ring.origins[start].ring, no_index};
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t k = (start + step) % n, next = (k + 1) % n;
    const Point p = ring.points[k], q = ring.points[next];
    const bool q_inside = inside(box, q);
    if (open && q_inside) {
      current.ring.push(q, ring.markers[next], ring.origins[next]);
      continue;
    }
    if (!open) {
      if (!q_inside && !passes_through(box, p, q)) continue;
      current = Chain{};
      current.entry = crossing_place(box, p, q, entry_side(box, p, q));
      current.ring.push(current.entry.point, ring.markers[k], made);
      open = true;
      if (q_inside) {
        current.ring.push(q, ring.markers[next], ring.origins[next]);
        continue;
      }
    }
    current.exit = crossing_place(box, p, q, entry_side(box, q, p));
    current.ring.push(current.exit.point, ring.markers[k], made);
    chains.push_back(std::move(current));
    open = false;
  }
  return chains;
}

// Of the chains not yet used (and `first`, the one the ring being joined
// started with), the one whose entry comes first counter-clockwise from
// `from` (at `from` itself included), ties to the lowest index. Always
// finding one that is free keeps every ring closed along the box even when
// crossing rings give entries and exits that do not pair up.
std::size_t next_entry(const ClipBox& box, const std::vector<Chain>& chains, const std::vector<bool>& used,
                       std::size_t first, const Place& from) {
  std::size_t best = first;
  bool best_wrapped = before(box, chains[first].entry, from);  // only reached past the south-west corner
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if ((used[c] && c != first) || c == best) continue;
    const Place& entry = chains[c].entry;
    const bool wrapped = before(box, entry, from);
    if (wrapped == best_wrapped ? before(box, entry, chains[best].entry) : !wrapped) best = c, best_wrapped = wrapped;
  }
  return best;
}

// Appends the box corners passed going counter-clockwise from `from` to `to`
// (less than a whole turn; none when they are at one point).
void add_corners(const ClipBox& box, const Place& from, const Place& to, int open_marker, MarkedRing& out,
                 const VertexOrigin& made) {
  const int passed = to.side - from.side + (before(box, to, from) ? 4 : 0);
  for (int k = 1; k <= passed; ++k) {
    const int side = (from.side + k) % 4;
    if (k == passed && to.along == side_start(box, side)) break;  // `to` is the corner
    out.push(corner(box, side + 3), open_marker, made);
  }
}

// Joins the chains into closed rings along the box's sides.
std::vector<MarkedRing> join_chains(std::vector<Chain> chains, const ClipBox& box, int open_marker) {
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
      const std::size_t next = next_entry(box, chains, used, first, chain.exit);
      add_corners(box, chain.exit, chains[next].entry, open_marker, ring, chain.ring.origins.back());
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
  box.x0 = off_vertices(polygons, true, box.x0, -infinity);
  box.x1 = off_vertices(polygons, true, box.x1, infinity);
  box.y0 = off_vertices(polygons, false, box.y0, -infinity);
  box.y1 = off_vertices(polygons, false, box.y1, infinity);
  return box;
}

std::vector<MarkedPolygon> clip_to_box(std::span<const MarkedPolygon> polygons, ClipBox box, int open_marker) {
  std::vector<MarkedPolygon> bodies;
  for (const MarkedPolygon& polygon : polygons)
    for (MarkedPolygon& body : clip_polygon(polygon, box, open_marker)) bodies.push_back(std::move(body));
  return bodies;
}

}  // namespace madd::detail
