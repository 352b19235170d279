// Exact pairwise segment disjointness through a uniform grid, for
// verify_decomposition(). Every sign comes from orient2d.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "madd/predicates.hpp"
#include "verify_decomposition_detail.hpp"

namespace madd::detail {

namespace {

bool in_box(Point a, Point b, Point p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// Why segments s and t conflict, or nullptr when they only share an endpoint or nothing.
const char* conflict(const std::vector<Point>& pts, const Segment& s, const Segment& t) {
  const bool aa = s.a == t.a, ab = s.a == t.b, ba = s.b == t.a, bb = s.b == t.b;
  const int shared = int{aa} + int{ab} + int{ba} + int{bb};
  if (shared >= 2) return "are the same segment";
  if (shared == 1) {
    // Two segments from one vertex meet again only when collinear and pointing the same way.
    const std::uint32_t p = (aa || ab) ? s.a : s.b;
    const Point q = pts[p == s.a ? s.b : s.a];
    const Point r = pts[p == t.a ? t.b : t.a];
    const Point o = pts[p];
    if (orient2d(o, q, r) == 0.0 && sign_of(q.x - o.x) == sign_of(r.x - o.x) &&
        sign_of(q.y - o.y) == sign_of(r.y - o.y))
      return "overlap";
    return nullptr;
  }
  const Point a = pts[s.a], b = pts[s.b], c = pts[t.a], d = pts[t.b];
  const int o1 = sign_of(orient2d(a, b, c)), o2 = sign_of(orient2d(a, b, d));
  const int o3 = sign_of(orient2d(c, d, a)), o4 = sign_of(orient2d(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return "cross";
  if ((o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) || (o3 == 0 && in_box(c, d, a)) ||
      (o4 == 0 && in_box(c, d, b)))
    return "touch away from a shared endpoint (T-junction or overlap)";
  return nullptr;
}

struct Grid {
  double x0 = 0, y0 = 0, cw = 1, ch = 1;
  std::int64_t cols = 1, rows = 1;

  std::int64_t col(double x) const { return std::clamp<std::int64_t>(std::int64_t(std::floor((x - x0) / cw)), 0, cols - 1); }
  std::int64_t row(double y) const { return std::clamp<std::int64_t>(std::int64_t(std::floor((y - y0) / ch)), 0, rows - 1); }

  // Calls f(cell) for every cell the segment may touch: per column slab, the
  // rows its y-range spans there, padded so rounding never drops a cell.
  template <class F>
  void cells_of(Point a, Point b, F&& f) const {
    if (a.x > b.x) std::swap(a, b);
    const double pad_x = 1e-7 * cw, pad_y = 1e-7 * ch;
    const std::int64_t c0 = col(a.x - pad_x), c1 = col(b.x + pad_x);
    for (std::int64_t c = c0; c <= c1; ++c) {
      double lo = std::max(a.x, x0 + double(c) * cw), hi = std::min(b.x, x0 + double(c + 1) * cw);
      if (lo > hi) lo = hi = (c == c0 ? a.x : b.x);
      double ya = a.y, yb = b.y;
      if (b.x > a.x) {
        ya = a.y + (b.y - a.y) * ((lo - a.x) / (b.x - a.x));
        yb = a.y + (b.y - a.y) * ((hi - a.x) / (b.x - a.x));
      }
      const std::int64_t r0 = row(std::min(ya, yb) - pad_y), r1 = row(std::max(ya, yb) + pad_y);
      for (std::int64_t r = r0; r <= r1; ++r) f(static_cast<std::size_t>(r * cols + c));
    }
  }
};

Grid make_grid(const std::vector<Point>& points, std::size_t segments) {
  Grid g;
  if (points.empty()) return g;
  double x1 = points[0].x, y1 = points[0].y;
  g.x0 = x1;
  g.y0 = y1;
  for (const Point& p : points) {
    g.x0 = std::min(g.x0, p.x); g.y0 = std::min(g.y0, p.y);
    x1 = std::max(x1, p.x); y1 = std::max(y1, p.y);
  }
  const double w = std::max(x1 - g.x0, 1e-300), h = std::max(y1 - g.y0, 1e-300);
  const double cells = std::max(1.0, double(segments));
  const double side = std::sqrt(w * h / cells);
  g.cols = std::clamp<std::int64_t>(std::int64_t(w / side), 1, 4096);
  g.rows = std::clamp<std::int64_t>(std::int64_t(h / side), 1, 4096);
  g.cw = w / double(g.cols);
  g.ch = h / double(g.rows);
  return g;
}

} // namespace

void check_segments_disjoint(const std::vector<Point>& points, const std::vector<Segment>& segments,
                             ProblemLog& log) {
  const Grid grid = make_grid(points, segments.size());
  const std::size_t cell_count = static_cast<std::size_t>(grid.cols * grid.rows);
  std::vector<std::uint32_t> start(cell_count + 1, 0);
  for (const Segment& s : segments) grid.cells_of(points[s.a], points[s.b], [&](std::size_t c) { ++start[c + 1]; });
  for (std::size_t c = 0; c < cell_count; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> items(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < segments.size(); ++i)
    grid.cells_of(points[segments[i].a], points[segments[i].b], [&](std::size_t c) { items[fill[c]++] = i; });

  std::vector<std::pair<std::uint32_t, std::uint32_t>> bad;
  for (std::size_t c = 0; c < cell_count; ++c)
    for (std::uint32_t u = start[c]; u < start[c + 1]; ++u)
      for (std::uint32_t v = u + 1; v < start[c + 1]; ++v)
        if (conflict(points, segments[items[u]], segments[items[v]]) != nullptr)
          bad.emplace_back(std::min(items[u], items[v]), std::max(items[u], items[v]));
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  for (const auto& [i, j] : bad) {
    const Segment& s = segments[i];
    const Segment& t = segments[j];
    log.add("segments " + std::to_string(i) + " " + point_text(points[s.a]) + "-" + point_text(points[s.b]) +
            " and " + std::to_string(j) + " " + point_text(points[t.a]) + "-" + point_text(points[t.b]) + " " +
            conflict(points, s, t));
  }
}

int locate_in_ring(const std::vector<Point>& points, const std::vector<std::uint32_t>& ring, Point p) {
  int winding = 0;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point u = points[ring[k]];
    const Point v = points[ring[(k + 1) % n]];
    if (in_box(u, v, p) && orient2d(u, v, p) == 0.0) return 0;
    if (u.y <= p.y) {
      if (v.y > p.y && orient2d(u, v, p) > 0.0) ++winding;
    } else if (v.y <= p.y && orient2d(u, v, p) < 0.0) {
      --winding;
    }
  }
  return winding != 0 ? 1 : -1;
}

std::string point_text(Point p) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g)", p.x, p.y);
  return buffer;
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

void ProblemLog::add(std::string problem) {
  if (count_++ < cap_) out_.add(std::move(problem));
}

void ProblemLog::finish() {
  if (count_ > cap_) out_.add("... and " + std::to_string(count_ - cap_) + " more problems");
}

} // namespace madd::detail
