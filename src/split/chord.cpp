// The chord fallback (chord.hpp): every pair of refined boundary points
// is rated by the balance it would give, in O(1) from prefix sums of the
// shoelace terms (and, graded, in O(samples) from prefix sums of the angle
// each ring edge subtends at each sample); only balanced pairs have their
// end angles measured, and only the best few are checked exactly against
// the boundary.
#include "split/chord.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <utility>
#include <numbers>
#include <vector>

#include "kernel/containment.hpp"
#include "kernel/sample_grid.hpp"
#include "kernel/segment_distance.hpp"
#include "medial/medial_detail.hpp"
#include "madd/predicates.hpp"
#include "split/split.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {

namespace {

constexpr double angle_margin_deg = 1e-9;  // as medial/medial.cpp: the committed check never disagrees
constexpr std::size_t max_exact_checks = 256;
constexpr std::size_t max_ring_points = 4000;

struct Ring {
  std::vector<std::uint32_t> at;  // the outer ring's working points in ring order
  std::vector<double> prefix;     // prefix[k]: twice the area swept by ring edges 0..k-1
  Point origin;                   // shoelace terms are taken relative to it (fewer cancellations)
  // The holes (the face's rings 1, 2, ...): their working points in order
  // and their areas.
  std::vector<std::vector<std::uint32_t>> holes;
  std::vector<double> hole_area;
  // Which points lie on which side of a chord, each a column of
  // `crossings`: the samples (graded), then one vertex of each hole
  // (column_at). crossings[k * columns + c] is the signed count of ring
  // edges 0..k-1 crossing the ray from column c's point towards +x (upward
  // +1, downward -1, by exact orient2d: Sunday's winding number). Ring
  // i..j closed by the chord j -> i winds round the point
  // crossings[j] - crossings[i] + the chord's own crossing times: nonzero
  // inside side 0 (a sample on the chord itself may go either way; a
  // hole's vertex is never on it).
  std::size_t samples = 0, columns = 0;
  std::vector<Point> column_at;
  std::vector<std::int32_t> crossings;
  std::vector<Point> point;  // the outer ring's points (at's coordinates), when columns > 0
};

// The cycle of working points from `first` (links' next), or empty when it
// does not close within `limit` points.
std::vector<std::uint32_t> cycle_from(const FaceDomain& fd, std::uint32_t first, std::size_t limit) {
  std::vector<std::uint32_t> out;
  std::uint32_t v = first;
  do {
    out.push_back(v);
    v = fd.links[v].next;
  } while (v != first && v < limit && out.size() <= limit);
  if (v != first) out.clear();
  return out;
}

double ring_area(const FaceDomain& fd, const std::vector<std::uint32_t>& cycle) {
  double twice = 0.0;
  const Point o = fd.pslg.points[cycle[0]];
  for (std::size_t k = 0; k < cycle.size(); ++k)
    twice += cross(fd.pslg.points[cycle[k]] - o, fd.pslg.points[cycle[(k + 1) % cycle.size()]] - o);
  return 0.5 * twice;
}

// The face's rings, in order. Empty when a point of them is one where a
// ring passes twice or two rings meet (the chord rules below assume simple
// polygons, the holes apart from the outer ring and each other).
Ring ring_of(const FaceDomain& fd) {
  Ring ring;
  const auto& pts = fd.pslg.points;
  // The rings' working points come first, ring by ring (refine_face), the interior ones after.
  const std::size_t ring_points = fd.ring_segments;
  if (ring_points < 4) return ring;
  for (std::size_t w = 0; w < ring_points; ++w) {
    if (fd.links[w].prev == no_index) return ring;
  }
  ring.origin = pts[0];
  ring.at = cycle_from(fd, 0, ring_points);
  std::size_t covered = ring.at.size();
  while (covered < ring_points && !ring.at.empty()) {
    std::vector<std::uint32_t> hole = cycle_from(fd, static_cast<std::uint32_t>(covered), ring_points);
    if (hole.empty()) return Ring{};
    covered += hole.size();
    ring.hole_area.push_back(std::abs(ring_area(fd, hole)));  // (holes run clockwise)
    ring.holes.push_back(std::move(hole));
  }
  if (ring.at.empty() || covered != ring_points || ring.holes.size() != fd.pslg.holes.size()) return Ring{};
  ring.prefix.assign(ring.at.size() + 1, 0.0);
  for (std::size_t k = 0; k < ring.at.size(); ++k) {
    const Point a = pts[ring.at[k]] - ring.origin;
    const Point b = pts[ring.at[(k + 1) % ring.at.size()]] - ring.origin;
    ring.prefix[k + 1] = ring.prefix[k] + cross(a, b);
  }
  return ring;
}

// Edge u -> v's part in the winding number round q: +1 crossing the ray
// from q towards +x upwards with q on its left, -1 downwards with q on its
// right, else 0.
int crossing(Point u, Point v, Point q) {
  if (u.y <= q.y) return v.y > q.y && orient2d(u, v, q) > 0 ? 1 : 0;
  return v.y <= q.y && orient2d(u, v, q) < 0 ? -1 : 0;
}

// Fills ring.crossings for the options' samples (graded) and the holes.
void add_crossings(const FaceDomain& fd, const ChordOptions& o, Ring& ring) {
  std::vector<Point>& at = ring.column_at;
  if (o.sample_weight > 0.0)
    for (const ValuedPoint& s : o.samples) at.push_back(s.at);
  ring.samples = at.size();
  for (const auto& hole : ring.holes) at.push_back(fd.pslg.points[hole[0]]);
  const std::size_t n = ring.at.size(), count = at.size();
  ring.columns = count;
  for (const std::uint32_t v : ring.at) ring.point.push_back(fd.pslg.points[v]);
  ring.crossings.assign((n + 1) * count, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Point a = ring.point[k], b = ring.point[(k + 1) % n];
    for (std::size_t c = 0; c < count; ++c)
      ring.crossings[(k + 1) * count + c] = ring.crossings[k * count + c] + crossing(a, b, at[c]);
  }
}

// Whether column c's point is inside side 0 of chord (i, j) (ring.crossings).
bool inside_side0(const Ring& ring, std::size_t c, std::size_t i, std::size_t j) {
  const std::size_t n = ring.point.size();  // j = n: the whole ring, closed by no chord
  const Point pi = ring.point[i % n], pj = ring.point[j % n];
  return ring.crossings[j * ring.columns + c] - ring.crossings[i * ring.columns + c] +
             crossing(pj, pi, ring.column_at[c]) !=
         0;
}

// Area of the part bounded by the outer ring from position i to j and the
// chord back (its holes not taken off).
double side_area(const FaceDomain& fd, const Ring& ring, std::size_t i, std::size_t j) {
  const Point pi = fd.pslg.points[ring.at[i]] - ring.origin;
  const Point pj = fd.pslg.points[ring.at[j]] - ring.origin;
  return 0.5 * (ring.prefix[j] - ring.prefix[i] + cross(pj, pi));
}

// The samples' weight inside the ring from i to j closed by a chord (i = 0,
// j = n: the whole ring).
double samples_inside(const Ring& ring, const ChordOptions& o, std::size_t i, std::size_t j) {
  double inside = 0.0;
  for (std::size_t s = 0; s < ring.samples; ++s)
    if (inside_side0(ring, s, i, j)) inside += o.samples[s].value;
  return inside;
}

// The holes' area there.
double holes_inside(const Ring& ring, std::size_t i, std::size_t j) {
  double area = 0.0;
  for (std::size_t h = 0; h < ring.holes.size(); ++h)
    if (inside_side0(ring, ring.samples + h, i, j)) area += ring.hole_area[h];
  return area;
}

// What side 0 of chord (i, j) weighs: its area less its holes', or graded
// r x that area + a x its samples.
double side_weight(const FaceDomain& fd, const Ring& ring, const ChordOptions& o, std::size_t i, std::size_t j) {
  const double area = side_area(fd, ring, i, j) - holes_inside(ring, i, j);
  if (ring.samples == 0) return area;
  return o.area_weight * area + o.sample_weight * samples_inside(ring, o, i, j);
}

// What the whole face weighs, in side_weight's units.
double face_weight(const Ring& ring, const ChordOptions& o) {
  double area = 0.5 * ring.prefix[ring.at.size()];
  for (const double a : ring.hole_area) area -= a;
  if (ring.samples == 0) return area;
  return o.area_weight * area + o.sample_weight * samples_inside(ring, o, 0, ring.at.size());
}

// Per boundary point: the directions that leave it at exactly Phi0 from the
// ring edge to next (turned counter-clockwise) and to prev (turned
// clockwise). A chord meets Phi0 there when it leaves between the two. An
// inexact prefilter: the chosen chord is measured again with boundary_angle.
struct Cone {
  Point from, to;
  bool empty = true;  // the wedge is narrower than 2 Phi0
  bool reflex = false;
};

Point rotate(Point d, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * d.x - s * d.y, s * d.x + c * d.y};
}

std::vector<Cone> cones(const FaceDomain& fd, const Ring& ring, double separator_angle_deg) {
  const auto& pts = fd.pslg.points;
  std::vector<Cone> out(ring.at.size());
  const double phi = radians(separator_angle_deg);
  for (std::size_t k = 0; k < ring.at.size(); ++k) {
    const std::uint32_t v = ring.at[k];
    const Point o = pts[v], next = pts[fd.links[v].next] - o, prev = pts[fd.links[v].prev] - o;
    double wedge = std::atan2(cross(next, prev), dot(next, prev));
    if (wedge < 0.0) wedge += 2.0 * std::numbers::pi;
    Cone& c = out[k];
    c.empty = !(wedge > 2.0 * phi) || fd.links[v].no_end;  // no separator ends where an interior segment meets the ring
    c.reflex = wedge - 2.0 * phi > std::numbers::pi;
    c.from = rotate(next, phi);
    c.to = rotate(prev, -phi);
  }
  return out;
}

bool inside_cone(const Cone& c, Point d) {
  if (c.empty) return false;
  const bool after_from = cross(c.from, d) >= 0.0, before_to = cross(d, c.to) >= 0.0;
  return c.reflex ? (after_from || before_to) : (after_from && before_to);
}

double end_angle(const FaceDomain& fd, std::uint32_t at, std::uint32_t towards) {
  const auto& pts = fd.pslg.points;
  const BoundaryLinks& l = fd.links[at];
  return boundary_angle(pts[at], pts[l.prev], pts[l.next], pts[towards]);
}

// The chord from ring position i to j meets the boundary only at its two ends
// (exact, validate's segment test: touching or overlapping counts).
bool chord_is_clear(const FaceDomain& fd, const Ring& ring, std::size_t i, std::size_t j) {
  const Segment chord{ring.at[i], ring.at[j], 0};
  const auto& pts = fd.pslg.points;
  // Every ring's edges: the outer ring's and the holes'.
  for (std::size_t k = 0; k < fd.ring_segments; ++k) {
    const Segment edge{fd.pslg.segments[k].a, fd.pslg.segments[k].b, 0};
    if (classify_contact(pts, chord, edge).kind != Contact::none) return false;
    // Clear of the boundary along its middle, as every separator
    // (medial/medial_detail.hpp): a chord past a headland a hair away leaves a
    // strip of water that hair wide (on Lake Ladoga at N = 256, a subdomain
    // of 30 x its expected triangles).
    if (hugs_separator(pts[chord.a], pts[chord.b], pts[edge.a], pts[edge.b])) return false;
  }
  // Nor any interior constraint: it may not even touch one (a crossing is the
  // medial separators' business, with its angles on both sides).
  const Point a = fd.pslg.points[chord.a], b = fd.pslg.points[chord.b];
  for (std::size_t s = fd.ring_segments; s < fd.pslg.segments.size(); ++s) {
    const Point c = fd.pslg.points[fd.pslg.segments[s].a], d = fd.pslg.points[fd.pslg.segments[s].b];
    if (closed_segments_meet(a, b, c, d)) return false;
  }
  for (const Point& p : fd.isolated)
    if (on_segment(a, b, p)) return false;
  return true;
}

// Which side of the chord each interior working edge (its midpoint) and each
// isolated point lies on: side 0 is the polygon of ring positions i..j.
void place_by_chord(const FaceDomain& fd, const Ring& ring, std::size_t i, std::size_t j, SplitResult& r) {
  std::vector<Point> side0;
  for (std::size_t k = i;; k = (k + 1) % ring.at.size()) {
    side0.push_back(fd.pslg.points[ring.at[k]]);
    if (k == j) break;
  }
  const auto in_side0 = [&](Point q) {  // crossing number; q is off the chord and the ring
    bool in = false;
    for (std::size_t k = 0; k < side0.size(); ++k) {
      const Point u = side0[k], w = side0[(k + 1) % side0.size()];
      if ((u.y > q.y) != (w.y > q.y) && orient2d(u, w, q) * (w.y - u.y) > 0.0) in = !in;
    }
    return in;
  };
  r.inner_sides.clear();
  for (const std::uint32_t m : fd.inner_edges_of) r.inner_sides.emplace_back(m, std::uint8_t{0});
  for (std::size_t s = fd.ring_segments; s < fd.pslg.segments.size(); ++s) {
    const auto& [piece, along] = fd.inner_edge[s - fd.ring_segments];
    const Point mid = midpoint(fd.pslg.points[fd.pslg.segments[s].a], fd.pslg.points[fd.pslg.segments[s].b]);
    r.inner_sides[piece][along] = in_side0(mid) ? 0 : 1;
  }
  r.point_sides.clear();
  for (const Point& p : fd.isolated) r.point_sides.push_back(in_side0(p) ? 0 : 1);
}

// A point strictly inside side `which` of chord (i, j): the polygon of ring
// positions i..j (side 0) or j..i (side 1, cyclic), less its holes.
Point triangulated_interior_point(const FaceDomain& fd, const Ring& ring, std::size_t i, std::size_t j, int which) {
  const std::size_t n = ring.at.size();
  Pslg side;
  side.first_index = 0;
  const auto add_ring = [&](const auto& cycle) {
    const auto first = static_cast<std::uint32_t>(side.points.size());
    const auto m = static_cast<std::uint32_t>(cycle.size());
    for (std::uint32_t k = 0; k < m; ++k) {
      side.points.push_back(fd.pslg.points[cycle[k]]);
      side.segments.push_back({first + k, first + (k + 1) % m, 1});
    }
  };
  std::vector<std::uint32_t> outer;
  for (std::size_t k = which == 0 ? i : j;; k = (k + 1) % n) {
    outer.push_back(ring.at[k]);
    if (k == (which == 0 ? j : i)) break;
  }
  add_ring(outer);
  for (std::size_t h = 0; h < ring.holes.size(); ++h) {
    if (inside_side0(ring, ring.samples + h, i, j) != (which == 0)) continue;
    add_ring(ring.holes[h]);
    side.holes.push_back(fd.pslg.holes[h]);
  }
  return largest_triangle_centroid(side);
}

// A point strictly inside side 0 (left of chord q -> p) or side 1: the chord's
// midpoint moved off it by a quarter of its distance to the boundary, so that
// no boundary lies between them. The side is checked exactly, and the move
// for rounding; otherwise a triangulation of the side decides.
Point interior_point(const FaceDomain& fd, const Ring& ring, std::size_t i, std::size_t j, int side) {
  const auto& pts = fd.pslg.points;
  const Point p = pts[ring.at[i]], q = pts[ring.at[j]];
  const Point m = midpoint(p, q);
  double clear = distance(p, q);
  for (std::size_t k = 0; k < fd.ring_segments; ++k)  // the holes' edges too
    clear = std::min(clear, segment_distance(m, pts[fd.pslg.segments[k].a], pts[fd.pslg.segments[k].b]));
  const Point d = q - p;
  const Point left = (1.0 / length(d)) * Point{d.y, -d.x};  // left of q -> p
  const Point x = m + (side == 0 ? 0.25 * clear : -0.25 * clear) * left;
  const double o = orient2d(q, p, x);
  if ((side == 0 && o > 0.0) || (side == 1 && o < 0.0)) {
    if (distance(x, m) < 0.5 * clear) return x;
  }
  return triangulated_interior_point(fd, ring, i, j, side);
}

// balance_quality that also counts the lighter side: with the best sharing of
// `plan`, the worse of mean / heaviest and lightest / mean per final subdomain.
double two_sided_quality(std::uint32_t plan, double w0, double w1) {
  const double mean = (w0 + w1) / plan;
  double best = 0.0;
  for (std::uint32_t k0 = 1; k0 < plan; ++k0) {
    const double a = w0 / k0, b = w1 / (plan - k0);
    best = std::max(best, std::min(mean / std::max(a, b), std::min(a, b) / mean));
  }
  return best;
}

// The areas of side 0 whose two_sided_quality can exceed `min_quality`: for
// each sharing k0 of the plan, both sides' per-subdomain areas within
// [q, 1/q] x the mean. Sorted, merged, and a little wider than exact (a cheap
// prefilter; the quality itself decides).
std::vector<std::pair<double, double>> balanced_area_ranges(std::uint32_t plan, double total, double min_quality) {
  std::vector<std::pair<double, double>> out;
  const double q = std::max(min_quality, 1e-3) * (1.0 - 1e-9), mean = total / plan;
  for (std::uint32_t k0 = 1; k0 < plan; ++k0) {
    const double k1 = plan - k0;
    const double lo = std::max(k0 * q * mean, total - k1 * mean / q);
    const double hi = std::min(k0 * mean / q, total - k1 * q * mean);
    if (!(lo <= hi)) continue;
    if (!out.empty() && lo <= out.back().second) {
      out.back().second = std::max(out.back().second, hi);
    } else {
      out.emplace_back(lo, hi);
    }
  }
  return out;
}

bool in_ranges(const std::vector<std::pair<double, double>>& ranges, double a) {
  auto it = std::upper_bound(ranges.begin(), ranges.end(), a,
                             [](double x, const std::pair<double, double>& r) { return x < r.first; });
  return it != ranges.begin() && a <= std::prev(it)->second;
}

struct Pair {
  std::size_t i, j;
  double quality, length;
  bool good;  // quality >= good_quality
};

// Good chords first, the shortest first; then the others, the best balanced first.
bool better(const Pair& x, const Pair& y) {
  if (x.good != y.good) return x.good;
  const double kx = x.good ? x.length : -x.quality, ky = y.good ? y.length : -y.quality;
  if (kx != ky) return kx < ky;
  return x.i < y.i || (x.i == y.i && x.j < y.j);
}

// Every chord that balances better than min_quality and meets Phi0 at both
// ends, best first.
std::vector<Pair> balanced_pairs(const FaceDomain& fd, const Ring& ring, const ChordOptions& o) {
  const std::size_t n = ring.at.size();
  const double total = face_weight(ring, o);
  std::vector<Pair> out;
  if (!(total > 0.0)) return out;
  const std::vector<Cone> cone = cones(fd, ring, o.separator_angle_deg);
  const auto ranges = balanced_area_ranges(o.plan, total, o.min_quality);
  const auto& pts = fd.pslg.points;
  const bool graded = ring.columns > 0;  // samples or holes to place
  for (std::size_t i = 0; i < n; ++i) {
    if (cone[i].empty) continue;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours along the ring
      const std::uint32_t p = ring.at[i], r = ring.at[j];
      // Graded or with holes, the weight costs a pass over them: the end cones first.
      if (graded && (!inside_cone(cone[i], pts[r] - pts[p]) || !inside_cone(cone[j], pts[p] - pts[r]))) continue;
      const double a = side_weight(fd, ring, o, i, j);
      if (!(a > 0.0 && a < total) || !in_ranges(ranges, a)) continue;
      const double q = two_sided_quality(o.plan, a, total - a);
      if (!(q > o.min_quality)) continue;
      if (!graded && (!inside_cone(cone[i], pts[r] - pts[p]) || !inside_cone(cone[j], pts[p] - pts[r]))) continue;
      double len = distance(pts[p], pts[r]);
      if (o.end_bonus) len *= static_cast<double>(fd.links[p].bonus) * static_cast<double>(fd.links[r].bonus);
      out.push_back({i, j, q, len, q >= o.good_quality});
    }
  }
  std::sort(out.begin(), out.end(), better);
  return out;
}

}  // namespace

std::vector<ValuedPoint> merged_for_chords(std::span<const ValuedPoint> samples, std::size_t most) {
  if (samples.size() <= most) return {};
  const SampleGrid grid(samples, static_cast<int>(std::max(1.0, std::floor(std::sqrt(static_cast<double>(most))))));
  const std::vector<std::size_t> best = grid.nearest_to_centres(samples, [](std::size_t) { return false; });
  std::vector<ValuedPoint> out;
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    if (best[c] != samples.size()) out.push_back({samples[best[c]].at, grid.weight(c)});
  return out;
}

std::optional<Chord> best_chord(const FaceDomain& fd, const ChordOptions& given) {
  Ring ring = ring_of(fd);
  if (ring.at.empty() || ring.at.size() > max_ring_points) return std::nullopt;  // the search is quadratic
  const std::size_t columns = (given.sample_weight > 0.0 ? given.samples.size() : 0) + ring.holes.size();
  ChordOptions options = given;
  std::vector<ValuedPoint> merged;
  if (columns > 0) {
    // The table, and the pairs' passes over it (at most n^2 / 2 of `columns` each).
    const double n = static_cast<double>(ring.at.size());
    if (columns * (ring.at.size() + 1) > max_chord_sample_table ||
        static_cast<double>(columns) * n * n > max_chord_sample_work)
      return std::nullopt;
    // Within the bounds, many samples are merged (what is searched stays
    // what was searched before the merge: the bounds read them unmerged).
    if (options.sample_weight > 0.0) {
      merged = merged_for_chords(given.samples, max_chord_columns);
      if (!merged.empty()) options.samples = merged;
    }
    add_crossings(fd, options, ring);
  }
  const std::vector<Pair> pairs = balanced_pairs(fd, ring, options);
  const double min_angle = options.separator_angle_deg + angle_margin_deg;
  for (std::size_t k = 0; k < std::min(pairs.size(), max_exact_checks); ++k) {
    const Pair& c = pairs[k];
    const std::uint32_t p = ring.at[c.i], r = ring.at[c.j];
    if (end_angle(fd, p, r) < min_angle || end_angle(fd, r, p) < min_angle) continue;
    if (!chord_is_clear(fd, ring, c.i, c.j)) continue;
    // Side 0 is bounded by the ring from i to j and the chord j -> i, on its left.
    Chord out;
    out.quality = c.quality;
    SeparatorEdge e;
    e.a = fd.refs[ring.at[c.j]];
    e.b = fd.refs[ring.at[c.i]];
    e.left_side = 0;
    out.result.edges.push_back(e);
    out.result.ring_side.assign(1 + ring.holes.size(), 0);  // the outer ring is cut: its entry is not read
    for (std::size_t h = 0; h < ring.holes.size(); ++h)
      out.result.ring_side[1 + h] = inside_side0(ring, ring.samples + h, c.i, c.j) ? 0 : 1;
    const double a = side_weight(fd, ring, options, c.i, c.j);
    out.result.weight[0] = a;
    out.result.weight[1] = face_weight(ring, options) - a;
    out.result.interior[0] = interior_point(fd, ring, c.i, c.j, 0);
    out.result.interior[1] = interior_point(fd, ring, c.i, c.j, 1);
    place_by_chord(fd, ring, c.i, c.j, out.result);
    return out;
  }
  return std::nullopt;
}

}  // namespace madd::detail
