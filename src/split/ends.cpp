// Smoothing step 2 (paper Sec. 5.1), on the separator's ends: each cut
// partial separator c -> p with p on the boundary is compared with c -> x for
// the boundary points x next to p along the same straight ring edge (at most
// end_search_steps away), and the best by the optimality function (length x
// f0(minimum angle) x end-type bonus, as in step 1) is kept. A move is taken
// only when every angle stays >= Phi0, no point of the split lies in the
// swept triangle (c, p, x) (so nothing is crossed and the sides' interior
// points stay put), no other cut separator ends at x, and the balance stays
// within the acceptable imbalance, a separator is not shortened below
// EndSmoothing::min_length (short separators are the artifact smoothing is for),
// and the moved one keeps clear of the boundary (hugs_separator).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/angles.hpp"
#include "kernel/containment.hpp"
#include "madd/predicates.hpp"
#include "split/refine.hpp"
#include "split/split.hpp"

namespace madd::detail {

namespace {

constexpr int end_search_steps = 3;
constexpr double angle_margin_deg = 1e-6;

double deg_between(Point o, Point a, Point b) { return degrees(angle_at(o, a, b)); }

// Smallest angle at both ends of c -> x; -1 when it leaves the domain's wedge.
double end_angles(const MedialGraph& g, const FaceDomain& fd, const std::vector<CutEnd>& cut, std::size_t self,
                  std::uint32_t c, std::uint32_t x) {
  const std::size_t boundary = fd.refs.size();
  // Ends only move along the rings, and never onto a point where none may end.
  if (fd.links[x].prev == no_index || fd.links[x].two_sided || fd.links[x].no_end) return -1.0;
  double a = link_angle(g.points, fd.links, x, g.points[c]);
  if (a < 0.0) return -1.0;
  if (c < boundary) {
    const double at_c = link_angle(g.points, fd.links, c, g.points[x]);
    // At a crossing c the partial separator keeps to its side of the interior segment.
    const std::uint32_t p = cut[self].end[0] == c ? cut[self].end[1] : cut[self].end[0];
    if (at_c < 0.0 || link_side(g.points, fd.links, c, g.points[x]) != link_side(g.points, fd.links, c, g.points[p]))
      return -1.0;
    // Through a tip, the move must not sweep over the segment ending there.
    if (fd.links[c].tip) {
      const Point along = g.points[fd.links[c].next];
      const double ap = ccw_angle_deg(g.points[c], along, g.points[p]),
                   ax = ccw_angle_deg(g.points[c], along, g.points[x]);
      if (std::abs(ap - ax) >= 180.0) return -1.0;
    }
    a = std::min(a, at_c);
  }
  for (std::size_t k = 0; k < cut.size(); ++k) {
    if (k == self) continue;
    for (int e = 0; e < 2; ++e) {
      if (cut[k].end[e] == c) a = std::min(a, deg_between(g.points[c], g.points[x], g.points[cut[k].end[1 - e]]));
      if (cut[k].end[e] == x) return -1.0;  // another separator already ends there: would pinch
    }
  }
  return a;
}

// No point of the split (working points, circumcentres, interior and isolated points) in triangle (c, p, x)
// other than c and the boundary points from p to x.
bool swept_empty(const MedialGraph& g, const FaceDomain& fd, std::uint32_t c, const std::vector<std::uint32_t>& path,
                 const Point interior[2]) {
  const Point pc = g.points[c], pp = g.points[path.front()], px = g.points[path.back()];
  for (std::uint32_t v = 0; v < g.points.size(); ++v) {
    if (v == c || std::find(path.begin(), path.end(), v) != path.end()) continue;
    if (in_closed_triangle(pc, pp, px, g.points[v])) return false;
    // Nor may the moved separator run alongside the boundary a hair from it.
    const std::uint32_t next = v < fd.refs.size() ? fd.links[v].next : no_index;
    if (next != no_index && next != c && next != path.back() && hugs_separator(pc, px, g.points[v], g.points[next]))
      return false;
  }
  for (const Point& p : fd.isolated)  // a move must not carry an isolated point to the other side
    if (in_closed_triangle(pc, pp, px, p)) return false;
  return !in_closed_triangle(pc, pp, px, interior[0]) && !in_closed_triangle(pc, pp, px, interior[1]);
}

double score(const MedialGraph& g, const FaceDomain& fd, std::uint32_t c, std::uint32_t x, double angle, double phi0) {
  const double phi = std::min(angle, 90.0) * std::numbers::pi / 180.0;
  const double f0 = 1.0 / (phi - phi0 * std::numbers::pi / 180.0 + 1.0);
  return distance(g.points[c], g.points[x]) * f0 * static_cast<double>(fd.links[x].bonus);
}

struct Move {
  double score = 0.0;
  std::uint32_t to = no_index;
  double w[2] = {0.0, 0.0};
};

// Side weights after moving end p of separator k (fixed end c) to y: the swept
// triangle goes from the side left of c -> p to the other when y is on its left.
void moved_weights(const MedialGraph& g, const EndSmoothing& s, const CutEnd& sep, int e, std::uint32_t y,
                   const double w[2], double out[2]) {
  const std::uint32_t p = sep.end[e], c = sep.end[1 - e];
  const double area = triangle_area(g.points[c], g.points[p], g.points[y]);
  const int left_of_cp = e == 1 ? sep.left_side : 1 - sep.left_side;
  const int from = orient2d(g.points[c], g.points[p], g.points[y]) > 0.0 ? left_of_cp : 1 - left_of_cp;
  out[0] = w[0];
  out[1] = w[1];
  out[from] -= area * s.weight_per_area;
  out[1 - from] += area * s.weight_per_area;
}

// The best replacement for end e of separator k, or Move::to == no_index.
Move best_move(const MedialGraph& g, const FaceDomain& fd, const EndSmoothing& s, const std::vector<CutEnd>& cut,
               std::size_t k, int e, const double w[2], const Point interior[2]) {
  const std::uint32_t p = cut[k].end[e], c = cut[k].end[1 - e];
  Move best;
  best.score =
      score(g, fd, c, p, std::max(end_angles(g, fd, cut, k, c, p), s.separator_angle_deg), s.separator_angle_deg);
  best.score *= 1.0 - 1e-9;  // only a real improvement moves
  const double shortest = std::min(distance(g.points[c], g.points[p]), s.min_length);
  for (int dir = 0; dir < 2; ++dir) {
    std::vector<std::uint32_t> path{p};
    for (int step = 0; step < end_search_steps; ++step) {
      const std::uint32_t y = dir == 0 ? fd.links[path.back()].next : fd.links[path.back()].prev;
      if (y == no_index || y == c) break;
      path.push_back(y);
      const double angle = end_angles(g, fd, cut, k, c, y);
      double nw[2];
      moved_weights(g, s, cut[k], e, y, w, nw);
      // Shorter is better, but not down to a sliver of the final subdomains' size.
      const bool ok = angle >= s.separator_angle_deg + angle_margin_deg &&
                      distance(g.points[c], g.points[y]) >= shortest && nw[0] > 0.0 && nw[1] > 0.0 &&
                      balance_quality(s.plan, nw[0], nw[1]) >= s.min_quality;
      const double sc = ok ? score(g, fd, c, y, angle, s.separator_angle_deg) : INFINITY;
      if (sc < best.score && swept_empty(g, fd, c, path, interior)) {
        best.score = sc;
        best.to = y;
        best.w[0] = nw[0];
        best.w[1] = nw[1];
      }
      if (fd.refs[y].kind == EndRef::vertex) break;  // the ring edge ends here: no longer straight
    }
  }
  return best;
}

}  // namespace

void smooth_ends(const MedialGraph& g, const FaceDomain& fd, const EndSmoothing& s, std::vector<CutEnd>& cut,
                 double w[2], const Point interior[2]) {
  for (int it = 0; it < s.iterations; ++it) {
    bool moved = false;
    for (std::size_t k = 0; k < cut.size(); ++k) {
      for (int e = 0; e < 2; ++e) {
        const std::uint32_t p = cut[k].end[e];
        // An end on an interior segment is a crossing, shared with the partial
        // separator on its other side: it stays.
        if (p >= fd.refs.size() || fd.links[p].prev == no_index || fd.links[p].two_sided || fd.links[p].no_end ||
            fd.links[p].tip)
          continue;
        const Move m = best_move(g, fd, s, cut, k, e, w, interior);
        if (m.to == no_index) continue;
        cut[k].end[e] = m.to;
        w[0] = m.w[0];
        w[1] = m.w[1];
        moved = true;
      }
    }
    if (!moved) break;
  }
}

}  // namespace madd::detail
