// Bowyer-Watson cavity and fan on the half-edge core.
#include "triangulation/cavity.hpp"

#include <algorithm>

#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

// p strictly inside segment ab, given that a, b, p are collinear. Exact: it
// only compares coordinates along an axis on which a and b differ.
bool strictly_between(Point a, Point b, Point p) noexcept {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

} // namespace

bool ghost_conflict(Point a, Point b, Point p) noexcept {
  const double o = orient2d(a, b, p);
  return o > 0 || (o == 0 && strictly_between(a, b, p));
}

void Cavity::reserve(std::size_t slots, std::size_t vertices) {
  if (in_cavity_.size() < slots) in_cavity_.resize(slots, 0);
  if (link_.size() < vertices) link_.resize(vertices, no_index);
}

bool Cavity::in_conflict(const HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t t, Point p) const noexcept {
  const std::uint32_t a = m.tv[3 * t], b = m.tv[3 * t + 1], c = m.tv[3 * t + 2];
  const std::uint32_t g = m.ghost;
  if (c == g) return ghost_conflict(P[a], P[b], p);
  if (a == g) return ghost_conflict(P[b], P[c], p);
  if (b == g) return ghost_conflict(P[c], P[a], p);
  return incircle(P[a], P[b], P[c], p) > 0;
}

void Cavity::start(const HalfEdgeMesh& m) {
  if (in_cavity_.size() < m.slot_count()) in_cavity_.resize(m.slot_count(), 0);
  triangles_.clear();
  rim_.clear();
  stack_.clear();
}

void Cavity::mark(std::uint32_t t) {
  in_cavity_[t] = 1;
  stack_.push_back(t);
  if (order_ == SlotOrder::last_found_first) triangles_.push_back(t);
}

// Grows the cavity from the marked triangles on the stack (an explicit
// stack: no recursion grows with the input), recording the rim as it meets it.
void Cavity::grow(const HalfEdgeMesh& m, std::span<const Point> P, Point p, bool stop_at_segments) {
  while (!stack_.empty()) {
    const std::uint32_t c = stack_.back();
    stack_.pop_back();
    if (order_ == SlotOrder::examined) triangles_.push_back(c);
    for (std::uint32_t h = 3 * c; h < 3 * c + 3; ++h) {
      const std::uint32_t out = m.tn[h];
      const bool blocked = stop_at_segments && m.seg[h] != no_index;
      if (!blocked && out != no_index) {
        const std::uint32_t u = out / 3;
        if (in_cavity_[u]) continue;
        if (in_conflict(m, P, u, p)) {
          mark(u);
          continue;
        }
      }
      if (h == skip_ || h == skip_twin_) continue;
      rim_.push_back({m.origin(h), m.dest(h), h, out, m.constrained() ? m.seg[h] : no_index});
    }
  }
}

void Cavity::dig(const HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t t, Point p, bool stop_at_segments) {
  start(m);
  skip_ = skip_twin_ = open_a_ = open_b_ = no_index;
  mark(t);
  grow(m, P, p, stop_at_segments);
}

// p, strictly inside the edge, is strictly inside the circumcircles of the
// triangles on both its sides: both belong to the cavity.
void Cavity::dig_on_edge(const HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t h, Point p) {
  start(m);
  skip_ = h;
  skip_twin_ = m.tn[h];
  open_a_ = skip_twin_ == no_index ? m.origin(h) : no_index;
  open_b_ = skip_twin_ == no_index ? m.dest(h) : no_index;
  mark(h / 3);
  if (skip_twin_ != no_index) mark(skip_twin_ / 3);
  grow(m, P, p, true);
}

bool Cavity::star_shaped(std::span<const Point> P, Point p) const noexcept {
  return std::all_of(rim_.begin(), rim_.end(), [&](const RimEdge& r) { return orient2d(P[r.a], P[r.b], p) > 0; });
}

std::uint32_t Cavity::slot_for(HalfEdgeMesh& m, std::size_t i) {
  const std::size_t k = triangles_.size();
  if (i >= k) return m.new_slot();
  return triangles_[order_ == SlotOrder::examined ? i : k - 1 - i];
}

const std::vector<std::uint32_t>& Cavity::fill(HalfEdgeMesh& m, std::uint32_t v) {
  const std::uint32_t top = m.ghost == no_index ? v : std::max(v, m.ghost);
  if (link_.size() <= top) link_.resize(top + top / 2 + 16, no_index);
  for (const std::uint32_t t : triangles_) in_cavity_[t] = 0;
  // A cavity never has more triangles than its fan (k triangles, k + 2 rim
  // edges, one fewer when open); should one have, its spare slots are freed.
  for (std::size_t i = rim_.size(); i < triangles_.size(); ++i) m.free_slot(slot_for(m, i));
  fan_.clear();
  const bool constrained = m.constrained();
  for (std::size_t i = 0; i < rim_.size(); ++i) {
    const RimEdge& r = rim_[i];
    const std::uint32_t s = slot_for(m, i);
    m.tv[3 * s] = v;
    m.tv[3 * s + 1] = r.a;
    m.tv[3 * s + 2] = r.b;
    m.tn[3 * s] = r.outer;
    if (r.outer != no_index) m.tn[r.outer] = 3 * s;
    if (constrained) {
      m.seg[3 * s] = r.segment;
      m.seg[3 * s + 1] = m.seg[3 * s + 2] = no_index;
    }
    link_[r.a] = s;
    fan_.push_back(s);
  }
  // Edge 1 (b->v) of the triangle over a->b meets edge 2 (v->b) of the one
  // over b->c. An open fan has no triangle over an edge from a0: its
  // neighbours there are the outside.
  if (open_a_ != no_index) link_[open_a_] = no_index;
  for (const std::uint32_t s : fan_) {
    const std::uint32_t next = link_[m.tv[3 * s + 2]];
    if (next == no_index) {
      m.tn[3 * s + 1] = no_index;
    } else {
      m.link(3 * s + 1, 3 * next + 2);
    }
  }
  if (open_b_ != no_index) m.tn[3 * link_[open_b_] + 2] = no_index;
  triangles_.clear();
  rim_.clear();
  skip_ = skip_twin_ = open_a_ = open_b_ = no_index;
  return fan_;
}

void Cavity::clear() noexcept {
  for (const std::uint32_t t : triangles_) in_cavity_[t] = 0;
  triangles_.clear();
  rim_.clear();
  skip_ = skip_twin_ = open_a_ = open_b_ = no_index;
}

} // namespace madd::detail
