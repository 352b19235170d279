// The background triangulation of the size field: quadtree Steiner points,
// split segments, one triangulation, the inside flood (background.hpp).
#include "sizing/background.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "kernel/threads.hpp"
#include "madd/triangulation.hpp"
#include "sizing/triangle_locator.hpp"

namespace madd::detail {

namespace {

struct Cell {
  Point lo;
  double size = 0.0;
  bool inside = false;  // known to lie wholly in the domain
};

struct Points {
  std::vector<Point> at;
  std::vector<RawSample> samples;
  void add(Point p, const RawSample& s) {
    at.push_back(p);
    samples.push_back(s);
  }
};

// The leaves of the graded quadtree, level by level (so that the budget,
// when it binds, leaves the background uniformly coarser rather than
// finished in one place and missing in another).
void quadtree_points(const Coast& coast, const RawField& raw, const BackgroundOptions& options, Points& out) {
  Point lo = coast.points[0], hi = lo;
  for (const Point p : coast.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double root = std::max(hi.x - lo.x, hi.y - lo.y) * (1.0 + 1e-9);
  const double smallest = root * 0x1p-30;
  std::set<std::pair<double, double>> isolated;  // never a Steiner point on top of one
  std::vector<bool> on_segment(coast.points.size(), false);
  for (const Segment& s : coast.pieces) on_segment[s.a] = on_segment[s.b] = true;
  for (std::size_t v = 0; v < coast.points.size(); ++v)
    if (!on_segment[v]) isolated.insert({coast.points[v].x, coast.points[v].y});
  const std::size_t first = out.at.size();
  // What a cell's centre tells, measured for a whole level on the threads
  // (the queries of the coast are most of the build); the cells are then
  // taken in order, as the budget wants.
  struct Measured {
    double clearance = 0.0;  // from every segment (a cell wholly inside is clear of them)
    bool outside = false;    // wholly outside: dropped
    bool inside = false;
    RawSample sample;
  };
  std::vector<Measured> measured;
  constexpr std::size_t cells_per_task = 256;
  std::vector<Cell> level{{lo, root, false}}, next;
  while (!level.empty()) {
    next.clear();
    measured.assign(level.size(), Measured{});
    for_each_on_threads((level.size() + cells_per_task - 1) / cells_per_task, options.threads, [&](std::size_t task) {
      for (std::size_t i = task * cells_per_task; i < std::min(level.size(), (task + 1) * cells_per_task); ++i) {
        const Cell& c = level[i];
        Measured& here = measured[i];
        const Point m{c.lo.x + 0.5 * c.size, c.lo.y + 0.5 * c.size};
        here.inside = c.inside;
        here.clearance = c.size;
        if (!here.inside) {
          here.clearance = coast.segment_distance(m);
          if (here.clearance > 0.7072 * c.size) {  // no segment meets the cell: wholly in or out
            here.outside = !coast.contains(m);
            here.inside = !here.outside;
          }
        }
        if (!here.outside) here.sample = raw.at(m);
      }
    });
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Cell& c = level[i];
      if (measured[i].outside) continue;
      const Point m{c.lo.x + 0.5 * c.size, c.lo.y + 0.5 * c.size};
      const bool inside = measured[i].inside;
      const double clearance = measured[i].clearance;
      const RawSample& sample = measured[i].sample;
      const bool split = c.size > options.cell_over_h * sample.edge && c.size > smallest &&
                         out.at.size() - first + next.size() + 4 <= options.budget;
      if (split) {
        const double half = 0.5 * c.size;
        for (const Point corner : {c.lo, Point{m.x, c.lo.y}, Point{c.lo.x, m.y}, m})
          next.push_back({corner, half, inside});
      } else if ((inside || (clearance >= options.keep_away * c.size && coast.contains(m))) &&
                 isolated.count({m.x, m.y}) == 0) {
        out.add(m, sample);
      }
    }
    std::swap(level, next);
  }
}

// Splits every piece by halving until each part is at most cell_over_h
// times the smaller h at its ends; returns the chains of segments.
std::vector<Segment> split_pieces(const Coast& coast, const RawField& raw, const BackgroundOptions& options,
                                  Points& out) {
  std::vector<Segment> chains;
  struct Part {
    double t0, t1;
    std::uint32_t a, b;
  };
  for (std::uint32_t k = 0; k < coast.pieces.size(); ++k) {
    const Segment& piece = coast.pieces[k];
    const Point a = coast.points[piece.a], b = coast.points[piece.b];
    const double len = distance(a, b);
    const Point inward = coast.coast[k] != 0 ? coast.piece_inward[k] : Point{};
    std::vector<Part> stack{{0.0, 1.0, piece.a, piece.b}};
    while (!stack.empty()) {
      const Part p = stack.back();
      stack.pop_back();
      const double h = std::min(out.samples[p.a].edge, out.samples[p.b].edge);
      if (!((p.t1 - p.t0) * len > options.cell_over_h * h) || p.t1 - p.t0 < 0x1p-30) {
        chains.push_back({p.a, p.b, piece.marker});
        continue;
      }
      const double t = 0.5 * (p.t0 + p.t1);
      const Point m = lerp(a, b, t);
      const auto mid = static_cast<std::uint32_t>(out.at.size());
      out.add(m, raw.at(m, inward));
      stack.push_back({t, p.t1, mid, p.b});  // the first half is done first: chains run a -> b
      stack.push_back({p.t0, t, p.a, mid});
    }
  }
  return chains;
}

// Flags the triangles of the domain: not reached from the hull or a hole
// point across an edge that is no segment.
std::vector<std::uint8_t> flood_inside(const Triangulation& tri, const std::vector<Point>& holes) {
  const auto n = static_cast<std::uint32_t>(tri.triangles.size());
  std::vector<std::uint8_t> inside(n, 1);
  std::vector<std::uint32_t> stack;
  const auto reach = [&](std::uint32_t t) {
    if (t != no_index && inside[t] != 0) inside[t] = 0, stack.push_back(t);
  };
  for (std::uint32_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i)
      if (tri.neighbours[t][i] == no_index && !tri.is_constrained(t, i)) reach(t);
  const TriangleView view{tri.points, tri.triangles, tri.neighbours};
  const TriangleLocator locator(view);
  for (const Point h : holes) {
    const Location at = locator.locate(view, h);
    if (at.inside) reach(at.triangle);
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i)
      if (!tri.is_constrained(t, i)) reach(tri.neighbours[t][i]);
  }
  return inside;
}

}  // namespace

BackgroundBuild build_background(const Coast& coast, const RawField& raw, const BackgroundOptions& options) {
  Points points;
  points.at = coast.points;
  points.samples.resize(coast.points.size());
  for_each_on_threads((coast.points.size() + 255) / 256, options.threads, [&](std::size_t task) {
    for (std::size_t v = task * 256; v < std::min(coast.points.size(), (task + 1) * 256); ++v)
      points.samples[v] = raw.at(coast.points[v], coast.inward[v]);
  });
  Pslg pslg;
  pslg.segments = split_pieces(coast, raw, options, points);
  const std::size_t before = points.at.size();
  quadtree_points(coast, raw, options, points);
  pslg.points = points.at;
  TriangulateOptions how;
  how.convex_hull = true;
  Triangulation tri = triangulate(pslg, how);
  BackgroundBuild out;
  out.background.inside = flood_inside(tri, coast.holes);
  out.background.points = std::move(tri.points);
  out.background.triangles = std::move(tri.triangles);
  out.background.neighbours = std::move(tri.neighbours);
  out.background.edge.resize(points.samples.size());
  for (std::size_t v = 0; v < points.samples.size(); ++v) out.background.edge[v] = points.samples[v].edge;
  out.samples = std::move(points.samples);
  out.steiner_points = out.samples.size() - before;
  return out;
}

}  // namespace madd::detail
