// libFuzzer target: a coastline as a domain (madd::coast_domain). The bytes
// are decoded straight into a small PolygonSet on a coarse grid (so that
// touching, collinear, duplicate, crossing, pinched rings and vertices on
// the clip box are common) and a few options. Any exception other than
// madd::Error, an InternalError, any crash or sanitizer report is a bug; so
// is a domain that breaks what coast_domain promises: valid, its area the
// report's, open segments only on the clip box's sides, land segments only
// on input ring edges, counts that add up, and (on small inputs) an area
// that agrees with an independent even-odd reading of the rings (slabs
// between every vertex and crossing abscissa).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include "madd/coast.hpp"
#include "madd/error.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"

namespace {

using madd::Point;

struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  bool empty() const { return at >= size; }
  std::uint8_t next() { return at < size ? data[at++] : 0; }
};

// How a grid index becomes a file coordinate.
struct Grid {
  int mode = 0;  // 0: nibbles 0..15 (one byte a vertex), 1: bytes 0..255, 2: nibbles scaled, 3: bytes offset
  bool lonlat = true;
  double origin_x = 0, origin_y = 0, step_x = 1, step_y = 1;
  int size() const { return mode == 0 || mode == 2 ? 16 : 256; }
  Point at(double i, double j) const {
    Point p{origin_x + step_x * i, origin_y + step_y * j};
    if (lonlat) p.x = std::clamp(p.x, -180.0, 180.0), p.y = std::clamp(p.y, -90.0, 90.0);
    return p;
  }
};

Grid grid_of(std::uint8_t flags) {
  Grid g;
  g.mode = (flags >> 4) & 3;
  g.lonlat = (flags & 1) == 0;
  if (g.lonlat) {
    const double steps[3] = {0.25, 1.0 / 64, 0.1};
    g.origin_x = -70.0, g.origin_y = 43.0;
    if (g.mode < 3) g.step_x = g.step_y = steps[g.mode];
    if (g.mode == 3)
      g.origin_x = -180.0, g.origin_y = -90.0, g.step_x = 360.0 / 255, g.step_y = 180.0 / 255;  // the world
  } else {
    if (g.mode == 2) g.step_x = g.step_y = 0.1;
    if (g.mode == 3) g.origin_x = 4.5e5, g.origin_y = 5.2e6;  // UTM-like: cancellation
  }
  return g;
}

Point vertex(Bytes& in, const Grid& g) {
  if (g.mode == 0 || g.mode == 2) {
    const std::uint8_t b = in.next();
    return g.at(b & 15, b >> 4);
  }
  const std::uint8_t i = in.next();
  return g.at(i, in.next());
}

madd::PolygonSet decode_polygons(Bytes& in, const Grid& g) {
  madd::PolygonSet set;
  set.coordinates = g.lonlat ? madd::Coordinates::lonlat : madd::Coordinates::projected;
  while (!in.empty() && set.polygons.size() < 4) {
    const std::uint8_t head = in.next();
    madd::GisPolygon polygon;
    polygon.marker = (head & 4) ? 3 : 1;
    polygon.feature = static_cast<std::uint32_t>(set.polygons.size());
    const int rings = 1 + (head & 3);
    for (int r = 0; r < rings && !in.empty(); ++r) {
      madd::GisRing ring;
      ring.source = static_cast<std::uint32_t>(r);
      const int n = 3 + in.next() % 22;
      for (int k = 0; k < n && !in.empty(); ++k) ring.points.push_back(vertex(in, g));
      if (ring.points.size() < 3) break;
      (r == 0 ? polygon.outer : polygon.holes.emplace_back()) = std::move(ring);
    }
    if (polygon.outer.points.size() < 3) break;
    set.polygons.push_back(std::move(polygon));
  }
  return set;
}

struct Input {
  madd::PolygonSet set;
  madd::CoastOptions options;
  Grid grid;
  bool merging = false;  // a merge distance that merges distinct vertices
};

Input decode(const std::uint8_t* data, std::size_t size) {
  Bytes in{data, std::min<std::size_t>(size, 1024)};
  Input out;
  const std::uint8_t flags = in.next();
  out.grid = grid_of(flags);
  const Grid& g = out.grid;
  const int n = g.size();
  if (flags & 2) {
    const int x0 = in.next() % (n + 2) - 1, y0 = in.next() % (n + 2) - 1;
    const int w = 1 + in.next() % n, h = 1 + in.next() % n;
    const Point a = g.at(x0, y0), b = g.at(x0 + w, y0 + h);
    out.options.clip = madd::ClipBox{a.x, a.y, b.x, b.y};
  }
  if (flags & 4) {
    const std::uint8_t i = in.next(), j = in.next();
    out.options.water_at = g.at(0.5 * (i % (2 * n)), 0.5 * (j % (2 * n)));
  }
  if (flags & 8) out.options.min_island_area = std::pow(in.next() / 16.0, 2) * (g.lonlat ? 1e8 : 1.0);
  if (flags & 64) out.options.merge_distance = g.lonlat ? 1e3 : g.step_x, out.merging = true;
  if (flags & 128) out.options.open_marker = 5;
  out.set = decode_polygons(in, g);
  return out;
}

// ---- independent readings ---------------------------------------------------

struct Edge {
  Point a, b;
  int marker;
};

std::vector<std::vector<Point>> rings_of(const madd::GisPolygon& p) {
  std::vector<std::vector<Point>> rings{p.outer.points};
  for (const madd::GisRing& h : p.holes) rings.push_back(h.points);
  return rings;
}

std::vector<Edge> edges_of(const std::vector<std::vector<Point>>& rings, int marker) {
  std::vector<Edge> edges;
  for (const auto& ring : rings)
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point a = ring[k], b = ring[(k + 1) % ring.size()];
      if (!(a == b)) edges.push_back({a, b, marker});
    }
  return edges;
}

bool within(double v, double a, double b) { return std::min(a, b) <= v && v <= std::max(a, b); }

bool on_segment(Point p, Point a, Point b) {
  return madd::orient2d(a, b, p) == 0.0 && within(p.x, a.x, b.x) && within(p.y, a.y, b.y);
}

// Two edges share more than a point (collinear and overlapping).
bool overlap(const Edge& e, const Edge& f) {
  if (madd::orient2d(e.a, e.b, f.a) != 0.0 || madd::orient2d(e.a, e.b, f.b) != 0.0) return false;
  const bool by_x = e.a.x != e.b.x;
  const auto c = [&](Point p) { return by_x ? p.x : p.y; };
  const double lo = std::max(std::min(c(e.a), c(e.b)), std::min(c(f.a), c(f.b)));
  const double hi = std::min(std::max(c(e.a), c(e.b)), std::max(c(f.a), c(f.b)));
  return lo < hi;
}

bool any_overlap(const std::vector<Edge>& edges) {
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (overlap(edges[i], edges[j])) return true;
  return false;
}

// The edges meet at a point other than a shared end (or overlap).
bool touch(const Edge& e, const Edge& f) {
  const double o1 = madd::orient2d(e.a, e.b, f.a), o2 = madd::orient2d(e.a, e.b, f.b);
  const double o3 = madd::orient2d(f.a, f.b, e.a), o4 = madd::orient2d(f.a, f.b, e.b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return on_segment(f.a, e.a, e.b) || on_segment(f.b, e.a, e.b) || on_segment(e.a, f.a, f.b) ||
         on_segment(e.b, f.a, f.b);
}

// Simple rings, pairwise disjoint, holes inside the outer ring and not in
// each other: then the water is outer minus holes, and clipping it to a box
// is intersecting it with the box.
bool proper(const madd::GisPolygon& p) {
  std::vector<std::vector<Point>> rings = rings_of(p);
  for (auto& ring : rings) {
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    if (ring.size() < 3) return false;
  }
  std::vector<Edge> edges;
  std::vector<std::size_t> ring_of, index;
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t k = 0; k < rings[r].size(); ++k) {
      edges.push_back({rings[r][k], rings[r][(k + 1) % rings[r].size()], 0});
      ring_of.push_back(r), index.push_back(k);
    }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const std::size_t n = rings[ring_of[i]].size();
      const bool adjacent =
          ring_of[i] == ring_of[j] && (index[j] == index[i] + 1 || (index[i] == 0 && index[j] == n - 1));
      if (adjacent ? overlap(edges[i], edges[j]) : touch(edges[i], edges[j])) return false;
    }
  const auto inside = [](const std::vector<Point>& ring, Point q) {
    bool in = false;
    for (std::size_t k = 0, m = ring.size() - 1; k < ring.size(); m = k++) {
      const Point a = ring[m], b = ring[k];
      if ((a.y > q.y) != (b.y > q.y) && (madd::orient2d(a, b, q) > 0) == (b.y > a.y)) in = !in;
    }
    return in;
  };
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (!inside(rings[0], rings[h][0])) return false;
    for (std::size_t o = 1; o < rings.size(); ++o)
      if (o != h && inside(rings[o], rings[h][0])) return false;
  }
  return true;
}

// Even-odd area of the edges within the box [x0, x1] x [y0, y1]: in every
// slab between consecutive breakpoints (vertices, crossings, where edges
// meet the box's lines) the edges are straight and uncrossed, so the area
// between the 1st and 2nd, 3rd and 4th... is a trapezoid.
double even_odd_area(const std::vector<Edge>& edges, double x0, double y0, double x1, double y1) {
  std::vector<double> xs{x0, x1};
  const auto add_x = [&](double x) {
    if (x0 <= x && x <= x1) xs.push_back(x);
  };
  for (const Edge& e : edges) {
    add_x(e.a.x);
    for (double y : {y0, y1})
      if ((e.a.y < y) != (e.b.y < y) && std::isfinite(y))
        add_x(e.a.x + (y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y));
  }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Point p = edges[i].a, r = edges[i].b - edges[i].a, q = edges[j].a, s = edges[j].b - edges[j].a;
      const double d = madd::cross(r, s);
      if (d == 0.0) continue;
      const double t = madd::cross(q - p, s) / d, u = madd::cross(q - p, r) / d;
      if (t > 0 && t < 1 && u > 0 && u < 1) add_x(p.x + t * r.x);
    }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  double area = 0.0;
  std::vector<std::array<double, 3>> at;  // y at the slab's middle, left, right
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double xa = xs[k], xb = xs[k + 1], xm = 0.5 * (xa + xb);
    at.clear();
    for (const Edge& e : edges) {
      if (!(std::min(e.a.x, e.b.x) <= xa && xb <= std::max(e.a.x, e.b.x)) || e.a.x == e.b.x) continue;
      const auto y = [&](double x) { return e.a.y + (x - e.a.x) * (e.b.y - e.a.y) / (e.b.x - e.a.x); };
      at.push_back({y(xm), y(xa), y(xb)});
    }
    std::sort(at.begin(), at.end());
    const auto clamp = [&](double y) { return std::clamp(y, y0, y1); };
    for (std::size_t i = 0; i + 1 < at.size(); i += 2)
      area += 0.5 * (xb - xa) * (clamp(at[i + 1][1]) - clamp(at[i][1]) + clamp(at[i + 1][2]) - clamp(at[i][2]));
  }
  return area;
}

// ---- the checks -------------------------------------------------------------

[[noreturn]] void bug(const char* what) {
  std::fprintf(stderr, "fuzz_coast: %s\n", what);
  std::abort();
}

std::vector<std::vector<Point>> projected_rings(const madd::GisPolygon& p, const madd::Projection& projection) {
  std::vector<std::vector<Point>> rings = rings_of(p);
  for (auto& ring : rings)
    for (Point& q : ring) q = projection.to_metres(q);
  return rings;
}

// Every open segment on a side of the (projected) box, every other one on an
// input edge of its marker.
void check_segments(const Input& input, const madd::CoastDomain& d, double rounding) {
  // Merges cascade: a kept vertex stands for a run of merged ones, each near the one before.
  const double merged = static_cast<double>(d.report.vertices_merged + 1);
  const double tolerance = rounding + (input.merging ? merged * input.options.merge_distance : 0.0);
  std::vector<Edge> edges;
  for (const madd::GisPolygon& p : input.set.polygons)
    for (const Edge& e : edges_of(projected_rings(p, d.projection), p.marker)) edges.push_back(e);
  std::optional<madd::ClipBox> box;
  if (input.options.clip) {
    const madd::ClipBox& c = *input.options.clip;
    const Point a = d.projection.to_metres({c.x0, c.y0}), b = d.projection.to_metres({c.x1, c.y1});
    box = madd::ClipBox{a.x, a.y, b.x, b.y};
  }
  const auto near = [&](double v, double side) { return std::abs(v - side) <= tolerance; };
  const auto near_line = [&](Point q, const Edge& e) {  // within tolerance of the edge
    const Point t = e.b - e.a;
    const double along = std::clamp(madd::dot(q - e.a, t) / madd::dot(t, t), 0.0, 1.0);
    return madd::distance(q, madd::lerp(e.a, e.b, along)) <= tolerance;
  };
  for (const madd::Segment& s : d.domain.segments) {
    const Point p = d.domain.points[s.a], q = d.domain.points[s.b];
    if (box) {
      if (!(p.x >= box->x0 - tolerance && p.x <= box->x1 + tolerance && p.y >= box->y0 - tolerance &&
            p.y <= box->y1 + tolerance))
        bug("a domain point outside the clip box");
    }
    if (s.marker == input.options.open_marker) {
      if (!box) bug("an open segment without a clip box");
      // (within the default merge distance: a vertex an ulp inside the moved box may stand for the box's;
      // a larger one may merge a box corner away)
      const auto on_box = [&](Point v) {
        return near(v.x, box->x0) || near(v.x, box->x1) || near(v.y, box->y0) || near(v.y, box->y1);
      };
      const bool on =
          input.merging ? on_box(p) && on_box(q)
                        : (near(p.x, box->x0) && near(q.x, box->x0)) || (near(p.x, box->x1) && near(q.x, box->x1)) ||
                              (near(p.y, box->y0) && near(q.y, box->y0)) || (near(p.y, box->y1) && near(q.y, box->y1));
      if (!on) bug("an open segment off the box's sides");
      continue;
    }
    bool found = false;
    for (const Edge& e : edges) found = found || (e.marker == s.marker && near_line(p, e) && near_line(q, e));
    if (!found) bug("a land segment on no input edge of its marker");
  }
}

double extent_of(const Input& input, const madd::Projection& projection) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  const auto add = [&](Point p) {
    p = projection.to_metres(p);
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  };
  for (const madd::GisPolygon& p : input.set.polygons)
    for (const auto& ring : rings_of(p))
      for (Point q : ring) add(q);
  if (input.options.clip)
    add({input.options.clip->x0, input.options.clip->y0}), add({input.options.clip->x1, input.options.clip->y1});
  return std::max(x1 - x0, y1 - y0);
}

// The kept area against the even-odd area of each polygon (within the box):
// at most the largest, and equal to the only one when nothing was cut off.
void check_area(const Input& input, const madd::CoastDomain& d, double extent) {
  const madd::CoastReport& r = d.report;
  std::size_t edge_count = 0;
  for (const madd::GisPolygon& p : input.set.polygons) edge_count += edges_of(rings_of(p), 0).size();
  if (edge_count > 64 || input.merging || r.small_islands_removed > 0) return;
  double x0 = -INFINITY, y0 = -INFINITY, x1 = INFINITY, y1 = INFINITY;
  if (input.options.clip) {
    const madd::ClipBox& c = *input.options.clip;
    const Point a = d.projection.to_metres({c.x0, c.y0}), b = d.projection.to_metres({c.x1, c.y1});
    x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
    // The box as moved off the vertices: a few ulps larger.
    const double ulps_x = 8e-16 * std::max(std::abs(c.x0), std::abs(c.x1));
    const double ulps_y = 8e-16 * std::max(std::abs(c.y0), std::abs(c.y1));
    const Point grown =
        d.projection.to_metres({c.x1 + ulps_x, c.y1 + ulps_y}) - d.projection.to_metres({c.x0 - ulps_x, c.y0 - ulps_y});
    if (r.area_m2 > grown.x * grown.y * (1 + 1e-12)) bug("more area than the box");
  }
  double largest = 0.0;
  for (const madd::GisPolygon& p : input.set.polygons) {
    const std::vector<Edge> edges = edges_of(projected_rings(p, d.projection), 0);
    if (any_overlap(edges)) return;  // overlaps are merged, not counted twice: not even-odd
    if (input.options.clip && !proper(p)) return;
    largest = std::max(largest, even_odd_area(edges, x0, y0, x1, y1));
  }
  const double tolerance = 1e-7 * extent * extent;
  if (r.area_m2 > largest + tolerance) bug("more area than the even-odd reading");
  const bool whole =
      input.set.polygons.size() == 1 && r.bodies == 1 && r.pockets_dropped == 0 && r.rings_collapsed == 0;
  if (whole && std::abs(r.area_m2 - largest) > tolerance) bug("not the even-odd area");
}

void check(const Input& input, const madd::CoastDomain& d) {
  madd::validate(d.domain);  // throws a madd::Error: caught as a bug below
  const madd::CoastReport& r = d.report;
  // (a valid sliver's shoelace sum can round to 0)
  if (madd::domain_area(d.domain) != r.area_m2 || !(r.area_m2 >= 0.0)) bug("the report's area");
  if (r.open_segments + r.land_segments != d.domain.segments.size()) bug("segment counts");
  if (r.islands != d.domain.holes.size() || r.bodies_dropped + 1 != r.bodies) bug("island or body counts");
  if (r.polygons_read != input.set.polygons.size()) bug("polygon count");
  if (d.projection.geographic != (input.set.coordinates == madd::Coordinates::lonlat)) bug("projection");
  const double extent = extent_of(input, d.projection);
  check_segments(input, d, 1e-9 * extent);
  check_area(input, d, extent);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input input = decode(data, size);
  madd::CoastDomain domain;
  try {
    domain = madd::coast_domain(input.set, input.options, "fuzz");
  } catch (const madd::InternalError& e) {
    bug(e.what());
  } catch (const madd::Error&) {
    return 0;
  }
  try {
    check(input, domain);
  } catch (const madd::Error& e) {
    bug(e.what());  // the domain did not validate
  }
  return 0;
}
