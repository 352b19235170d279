// Bowyer-Watson cavity and fan on the half-edge core. This is the inner loop
// of both the triangulator and refinement: the arrays are read through local
// pointers, and the loops are templates on what the mesh has (ghosts,
// segments) and on the slot order, so that each kind of mesh gets its own
// tight loop.
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

// The triangle with corners t[0..2] in conflict with p, one of them perhaps
// the ghost.
inline bool in_conflict(const Point* P, const std::uint32_t* t, std::uint32_t ghost, Point p) noexcept {
  const std::uint32_t a = t[0], b = t[1], c = t[2];
  if (c == ghost) return ghost_conflict(P[a], P[b], p);
  if (a == ghost) return ghost_conflict(P[b], P[c], p);
  if (b == ghost) return ghost_conflict(P[c], P[a], p);
  return incircle(P[a], P[b], P[c], p) > 0;
}

}  // namespace

bool ghost_conflict(Point a, Point b, Point p) noexcept {
  const double o = orient2d(a, b, p);
  return o > 0 || (o == 0 && strictly_between(a, b, p));
}

void Cavity::reserve(std::size_t slots, std::size_t vertices) {
  if (in_cavity_.size() < slots) in_cavity_.resize(slots, Mark::out);
  if (link_.size() < vertices) link_.resize(vertices, no_index);
}

// A new cavity holding triangle t, to grow from.
[[gnu::always_inline]] inline void Cavity::start(const HalfEdgeMesh& m, std::uint32_t t) {
  if (in_cavity_.size() < m.slot_count()) in_cavity_.resize(m.slot_count(), Mark::out);
  ghost_ = m.ghost;
  triangles_.clear();
  rim_.clear();
  rim_sides_.clear();
  stack_.clear();
  skip_ = skip_twin_ = open_a_ = open_b_ = no_index;
  in_cavity_[t] = Mark::in;
  stack_.push_back(t);
  if (order_ == SlotOrder::last_found_first) triangles_.push_back(t);
}

// Grows the cavity from the marked triangles on the stack (an explicit
// stack: no recursion grows with the input), recording the rim as it meets
// it. `Constrained`: stop at segments, record the rim's half-edges and
// segments, and leave the split edge (dig_on_edge) off the rim.
// `FoundOrder`: record the triangles as they are found, not as examined.
// Inlined into its few callers: an insertion is then one function, and a
// call per step would cost more than a small cavity's own bookkeeping.
template <bool Constrained, bool FoundOrder>
[[gnu::always_inline]] inline void Cavity::grow_from_stack(const HalfEdgeMesh& m, const Point* P, Point p) {
  const std::uint32_t* tv = m.tv.data();
  const std::uint32_t* tn = m.tn.data();
  const std::uint32_t* seg = Constrained ? m.seg.data() : nullptr;
  const std::uint32_t ghost = m.ghost, skip = skip_, skip_twin = skip_twin_;
  Mark* in_cavity = in_cavity_.data();
  while (!stack_.empty()) {
    const std::uint32_t c = stack_.back();
    stack_.pop_back();
    if (!FoundOrder) triangles_.push_back(c);
    for (std::uint32_t h = 3 * c; h < 3 * c + 3; ++h) {
      const std::uint32_t out = tn[h];
      if (!Constrained || (seg[h] == no_index && out != no_index)) {
        const std::uint32_t u = out / 3;
        if (in_cavity[u] == Mark::in) continue;
        if (in_conflict(P, tv + 3 * u, ghost, p)) {
          in_cavity[u] = Mark::in;
          stack_.push_back(u);
          if (FoundOrder) triangles_.push_back(u);
          continue;
        }
      }
      if (Constrained && (h == skip || h == skip_twin)) continue;
      rim_.push_back({tv[next_half_edge(h)], tv[prev_half_edge(h)], out});
      if (Constrained) {
        rim_sides_.push_back({h, seg[h]});
      }
    }
  }
}

void Cavity::grow(const HalfEdgeMesh& m, std::span<const Point> P, Point p) {
  const bool found = order_ == SlotOrder::last_found_first;
  if (m.constrained()) {
    found ? grow_from_stack<true, true>(m, P.data(), p) : grow_from_stack<true, false>(m, P.data(), p);
  } else {
    found ? grow_from_stack<false, true>(m, P.data(), p) : grow_from_stack<false, false>(m, P.data(), p);
  }
}

void Cavity::dig(const HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t t, Point p) {
  start(m, t);
  grow(m, P, p);
}

// p, strictly inside the edge, is strictly inside the circumcircles of the
// triangles on both its sides: both belong to the cavity.
void Cavity::dig_on_edge(const HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t h, Point p) {
  const std::uint32_t twin = m.tn[h];
  start(m, h / 3);
  skip_ = h;
  skip_twin_ = twin;
  if (twin == no_index) {
    open_a_ = m.origin(h);
    open_b_ = m.dest(h);
  } else {
    in_cavity_[twin / 3] = Mark::in;
    stack_.push_back(twin / 3);
    if (order_ == SlotOrder::last_found_first) triangles_.push_back(twin / 3);
  }
  grow(m, P, p);
}

bool Cavity::star_shaped(std::span<const Point> P, Point p) const noexcept {
  return std::all_of(rim_.begin(), rim_.end(), [&](const RimEdge& r) {
    return r.a == ghost_ || r.b == ghost_ || orient2d(P[r.a], P[r.b], p) > 0;
  });
}

// Puts the fan's slots first in triangles_: the cavity's own (as SlotOrder
// says), then freed ones (last freed first); new ones at the end follow. A
// cavity never has more triangles than its fan (k triangles, k + 2 rim
// edges, one fewer when open); should one have, its spare slots are freed.
void Cavity::order_slots(HalfEdgeMesh& m) {
  if (order_ == SlotOrder::last_found_first) std::reverse(triangles_.begin(), triangles_.end());
  const std::size_t n = rim_.size();
  while (triangles_.size() > n) {
    in_cavity_[triangles_.back()] = Mark::out;
    m.free_slot(triangles_.back());
    triangles_.pop_back();
  }
  while (triangles_.size() < n && !m.free_slots.empty()) {
    triangles_.push_back(m.free_slots.back());
    m.free_slots.pop_back();
  }
}

// The fan, specialised: in a mesh closed by ghosts every edge has a twin and
// no fan is open; an unconstrained one has no segments to copy. (The
// triangulator's mesh is both, and this is its inner loop.)
template <bool Closed, bool Constrained>
[[gnu::always_inline]] inline void Cavity::fill_fan(HalfEdgeMesh& m, std::uint32_t v) {
  const std::size_t n = rim_.size(), k = triangles_.size();
  std::uint32_t next_new = m.append_slots(static_cast<std::uint32_t>(n > k ? n - k : 0));
  std::uint32_t* slot = fan_.data();
  std::uint32_t* tv = m.tv.data();
  std::uint32_t* tn = m.tn.data();
  std::uint32_t* seg = m.seg.data();
  std::uint32_t* link = link_.data();
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t s;
    if (i < k) {
      s = triangles_[i];
      in_cavity_[s] = Mark::out;
    } else {
      s = next_new++;
    }
    slot[i] = s;
    const RimEdge& r = rim_[i];
    tv[3 * s] = v;
    tv[3 * s + 1] = r.a;
    tv[3 * s + 2] = r.b;
    tn[3 * s] = r.outer;
    if (Closed || r.outer != no_index) tn[r.outer] = 3 * s;
    if (Constrained) {
      seg[3 * s] = rim_sides_[i].segment;
      seg[3 * s + 1] = seg[3 * s + 2] = no_index;
    }
    link[r.a] = s;
  }
  // Edge 1 (b->v) of the triangle over a->b meets edge 2 (v->b) of the one
  // over b->c. An open fan has no triangle over an edge from a0: its
  // neighbours there are the outside.
  if (!Closed && open_a_ != no_index) link[open_a_] = no_index;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t s = slot[i];
    const std::uint32_t next = link[tv[3 * s + 2]];
    if (!Closed && next == no_index) {
      tn[3 * s + 1] = no_index;
    } else {
      tn[3 * s + 1] = 3 * next + 2;
      tn[3 * next + 2] = 3 * s + 1;
    }
  }
  if (!Closed && open_b_ != no_index) tn[3 * link[open_b_] + 2] = no_index;
}

// Forgets the cavity's lists; its marks are cleared already.
[[gnu::always_inline]] inline void Cavity::reset() noexcept {
  triangles_.clear();
  rim_.clear();
  rim_sides_.clear();
  skip_ = skip_twin_ = open_a_ = open_b_ = no_index;
}

// The fan just made; the cavity's marks were cleared as its slots were reused.
[[gnu::always_inline]] inline std::span<const std::uint32_t> Cavity::finish() noexcept {
  const std::size_t n = rim_.size();
  reset();
  return {fan_.data(), n};
}

// Scratch for a fan around vertex v, and the slots in order (order_slots).
[[gnu::always_inline]] inline void Cavity::ready_fill(HalfEdgeMesh& m, std::uint32_t v) {
  const std::uint32_t top = m.ghost == no_index ? v : std::max(v, m.ghost);
  if (link_.size() <= top) link_.resize(top + top / 2 + 16, no_index);
  const std::size_t n = rim_.size(), k = triangles_.size();
  if (fan_.size() < n) fan_.resize(n + 16);
  if (order_ == SlotOrder::last_found_first || k > n || (k < n && !m.free_slots.empty())) order_slots(m);
}

std::span<const std::uint32_t> Cavity::fill(HalfEdgeMesh& m, std::uint32_t v) {
  ready_fill(m, v);
  const bool closed = m.ghost != no_index;
  if (m.constrained()) {
    closed ? fill_fan<true, true>(m, v) : fill_fan<false, true>(m, v);
  } else {
    closed ? fill_fan<true, false>(m, v) : fill_fan<false, false>(m, v);
  }
  return finish();
}

std::span<const std::uint32_t> Cavity::insert(HalfEdgeMesh& m, std::span<const Point> P, std::uint32_t t, Point p,
                                              std::uint32_t v) {
  if (m.ghost == no_index || m.constrained() || order_ != SlotOrder::examined) {
    dig(m, P, t, p);
    return fill(m, v);
  }
  // The triangulator's case, once per point: one function, one loop each.
  start(m, t);
  grow_from_stack<false, false>(m, P.data(), p);
  ready_fill(m, v);
  fill_fan<true, false>(m, v);
  return finish();
}

void Cavity::clear() noexcept {
  for (const std::uint32_t t : triangles_) in_cavity_[t] = Mark::out;
  reset();
}

}  // namespace madd::detail
