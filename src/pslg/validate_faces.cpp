// Faces of the segment graph, for the region checks of validate() and for
// domain_area(): which regions Triangle would keep after flooding from the
// outside and from every hole point (docs/formats.md, "Holes").
//
// Method: sort the half-edges around every vertex by exact angle, walk the
// boundary of the face left of every half-edge (a "ring"), then attach each
// connected component's outer ring to the face that contains the component,
// found by casting a ray from its lexicographically smallest vertex. Hole
// points are located the same way. All signs come from orient2d; ring areas
// (floating point) only pick the innermost of nested rings and sum areas.
#include <algorithm>
#include <numeric>

#include "kernel/rings.hpp"
#include "kernel/union_find.hpp"
#include "madd/predicates.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {
namespace {

std::uint32_t origin(const Pslg& p, std::uint32_t h) {
  const Segment& s = p.segments[h >> 1];
  return (h & 1U) ? s.b : s.a;
}
std::uint32_t dest(const Pslg& p, std::uint32_t h) { return origin(p, h ^ 1U); }

// Outgoing half-edges of every vertex in counter-clockwise order (CSR).
struct Star {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> out;
  std::vector<std::uint32_t> pos;  // position of each half-edge within its vertex's range
};

// Angle in [0, pi) is the upper half; ties within a half go to orient2d.
bool upper_half(Point v, Point q) noexcept { return q.y > v.y || (q.y == v.y && q.x > v.x); }

Star build_star(const Pslg& p) {
  Star st;
  const std::size_t n = p.points.size();
  const auto halves = static_cast<std::uint32_t>(2 * p.segments.size());
  st.start.assign(n + 1, 0);
  for (std::uint32_t h = 0; h < halves; ++h) ++st.start[origin(p, h) + 1];
  for (std::size_t v = 0; v < n; ++v) st.start[v + 1] += st.start[v];
  st.out.resize(halves);
  std::vector<std::uint32_t> fill(st.start.begin(), st.start.end() - 1);
  for (std::uint32_t h = 0; h < halves; ++h) st.out[fill[origin(p, h)]++] = h;
  st.pos.resize(halves);
  for (std::size_t v = 0; v < n; ++v) {
    const Point c = p.points[v];
    auto first = st.out.begin() + st.start[v], last = st.out.begin() + st.start[v + 1];
    if (last - first > 2) {
      std::sort(first, last, [&](std::uint32_t e, std::uint32_t f) {
        const Point qe = p.points[dest(p, e)], qf = p.points[dest(p, f)];
        const bool ue = upper_half(c, qe), uf = upper_half(c, qf);
        if (ue != uf) return ue;
        return orient2d(c, qe, qf) > 0.0;
      });
    }
    for (std::uint32_t k = st.start[v]; k < st.start[v + 1]; ++k) st.pos[st.out[k]] = k - st.start[v];
  }
  return st;
}

// The next half-edge along the face on the left: at the head of h, the edge
// just clockwise of the reverse of h.
std::uint32_t next_around_face(const Pslg& p, const Star& st, std::uint32_t h) {
  const std::uint32_t v = dest(p, h);
  const std::uint32_t deg = st.start[v + 1] - st.start[v];
  return st.out[st.start[v] + (st.pos[h ^ 1U] + deg - 1) % deg];
}

void walk_rings(const Pslg& p, const Star& st, FaceMap& fm) {
  const auto halves = static_cast<std::uint32_t>(2 * p.segments.size());
  fm.ring_of.assign(halves, no_index);
  std::vector<std::uint32_t> ring;
  for (std::uint32_t h0 = 0; h0 < halves; ++h0) {
    if (fm.ring_of[h0] != no_index) continue;
    const auto r = static_cast<std::uint32_t>(fm.ring_area.size());
    ring.clear();
    std::uint32_t h = h0;
    do {
      fm.ring_of[h] = r;
      ring.push_back(origin(p, h));
      h = next_around_face(p, st, h);
    } while (h != h0);
    fm.ring_area.push_back(ring_signed_area(RingView(p.points, ring)));
  }
}

// The lexicographically smallest vertex of every connected component.
std::vector<std::uint32_t> component_minima(const Pslg& p, const Star& st) {
  std::vector<std::uint32_t> parent(p.points.size());
  std::iota(parent.begin(), parent.end(), 0U);
  for (const Segment& s : p.segments) parent[find_root(parent, s.a)] = find_root(parent, s.b);
  std::vector<std::uint32_t> minimum(p.points.size(), no_index);
  for (std::uint32_t v = 0; v < p.points.size(); ++v) {
    if (st.start[v + 1] == st.start[v]) continue;
    const std::uint32_t r = find_root(parent, v);
    const Point q = p.points[v];
    const std::uint32_t m = minimum[r];
    if (m == no_index || q.x < p.points[m].x || (q.x == p.points[m].x && q.y < p.points[m].y)) minimum[r] = v;
  }
  std::vector<std::uint32_t> minima;
  for (std::uint32_t v = 0; v < p.points.size(); ++v)
    if (minimum[v] != no_index && parent[v] == v) minima.push_back(minimum[v]);
  std::sort(minima.begin(), minima.end());
  return minima;
}

// At the component's smallest vertex every edge points into the right half
// plane, so the face left of the counter-clockwise-most edge is the one
// outside the component: that ring is the component's outer ring.
std::uint32_t outer_ring(const Pslg& p, const Star& st, const FaceMap& fm, std::uint32_t v) {
  const Point c = p.points[v];
  std::uint32_t best = st.out[st.start[v]];
  for (std::uint32_t k = st.start[v] + 1; k < st.start[v + 1]; ++k) {
    const std::uint32_t h = st.out[k];
    if (orient2d(c, p.points[dest(p, best)], p.points[dest(p, h)]) > 0.0) best = h;
  }
  return fm.ring_of[best];
}

// Ray casting over the grid row of the query point; parity per ring tells
// which rings enclose the point, the smallest enclosing bounded-face ring is
// the face. The ray is the horizontal half-line, shifted up infinitesimally
// (half-open rule), so it never passes through a vertex.
class Locator {
public:
  Locator(const Pslg& p, const SegmentGrid& g, const FaceMap& fm, const std::vector<bool>& outer)
      : p_(p), g_(g), fm_(fm), outer_(outer), stamp_(p.segments.size(), 0), parity_(fm.ring_count(), 0) {}

  // Face containing q, which lies on no segment except possibly at segments
  // of its own component all to its right (then `leftward` must be true).
  std::uint32_t locate(Point q, bool leftward) {
    if (!g_.y_in_range(q.y)) return no_index;
    ++query_;
    const std::uint32_t row = g_.row_of(q.y), col = g_.col_of(q.x);
    const std::uint32_t c0 = leftward ? 0 : col, c1 = leftward ? col : g_.cols() - 1;
    for (const auto& entry : g_.row_range(row, c0, c1)) test(entry.item, q, leftward);
    std::uint32_t best = no_index;
    for (std::uint32_t r : touched_)
      if (parity_[r] && !outer_[r] && (best == no_index || fm_.ring_area[r] < fm_.ring_area[best])) best = r;
    for (std::uint32_t r : touched_) parity_[r] = 0;
    touched_.clear();
    return best;
  }

private:
  void test(std::uint32_t s, Point q, bool leftward) {
    if (stamp_[s] == query_) return;
    stamp_[s] = query_;
    Point lo = p_.points[p_.segments[s].a], hi = p_.points[p_.segments[s].b];
    if ((lo.y > q.y) == (hi.y > q.y)) return;
    if (lo.y > hi.y) std::swap(lo, hi);
    const double side = orient2d(lo, hi, q);  // < 0: q right of the upward segment
    if (leftward ? !(side < 0.0) : !(side > 0.0)) return;
    flip(fm_.ring_of[2 * s]);
    flip(fm_.ring_of[2 * s + 1]);
  }
  void flip(std::uint32_t r) {
    parity_[r] ^= 1U;
    touched_.push_back(r);
  }

  const Pslg& p_;
  const SegmentGrid& g_;
  const FaceMap& fm_;
  const std::vector<bool>& outer_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint8_t> parity_;
  std::vector<std::uint32_t> touched_;
  std::uint32_t query_ = 0;
};

}  // namespace

FaceMap build_face_map(const Pslg& p, const SegmentGrid& grid) {
  FaceMap fm;
  const Star st = build_star(p);
  walk_rings(p, st, fm);
  const std::vector<std::uint32_t> minima = component_minima(p, st);
  std::vector<bool> outer(fm.ring_count(), false);
  std::vector<std::uint32_t> component_ring;
  for (std::uint32_t v : minima) {
    component_ring.push_back(outer_ring(p, st, fm, v));
    outer[component_ring.back()] = true;
  }
  fm.face_of_ring.resize(fm.ring_count());
  std::iota(fm.face_of_ring.begin(), fm.face_of_ring.end(), 0U);
  Locator locator(p, grid, fm, outer);
  for (std::size_t c = 0; c < minima.size(); ++c)
    fm.face_of_ring[component_ring[c]] = locator.locate(p.points[minima[c]], true);
  // Hole points may cast either way: take the shorter walk along the row.
  for (const Point& h : p.holes) fm.hole_face.push_back(locator.locate(h, grid.col_of(h.x) <= grid.cols() / 2));
  return fm;
}

std::vector<bool> kept_faces(const FaceMap& fm) {
  std::vector<bool> kept(fm.ring_count(), false);
  for (std::uint32_t r = 0; r < fm.ring_count(); ++r) kept[r] = fm.face_of_ring[r] == r;
  for (std::uint32_t f : fm.hole_face)
    if (f != no_index) kept[f] = false;
  return kept;
}

}  // namespace madd::detail
