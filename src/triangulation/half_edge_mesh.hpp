#pragma once
// The one triangulation core of madd: flat triangle arrays with half-edge
// adjacency. The Delaunay triangulator builds in it, segment recovery
// constrains it, and mesh refinement grows the same arrays further, so a
// triangulation never changes shape between those stages.
//
// Half-edge h = 3t + i is edge i of triangle t, the edge opposite corner i,
// directed counter-clockwise in t: from tv[3t + (i+1)%3] to tv[3t + (i+2)%3].
// tn[h] is the twin (the same edge seen from the neighbour), no_index where
// there is none (the outside of a mesh closed by its segments).
//
// While the triangulator builds, "ghost" triangles close the convex hull
// through one virtual vertex (`ghost`), so that hull insertion needs no
// special case; once the outside is removed there are none (ghost ==
// no_index).
//
// Vertices are indices into the caller's points: the core holds no copy, and
// every user passes the points alongside it.
#include <cstdint>
#include <cstddef>
#include <vector>

#include "madd/pslg.hpp"

namespace madd::detail {

inline std::uint32_t next_half_edge(std::uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
inline std::uint32_t prev_half_edge(std::uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }

struct HalfEdgeMesh {
  std::uint32_t ghost = no_index;  // the virtual vertex closing the hull, if any
  // Per triangle slot, its 3 vertex ids (tv) and per half-edge its twin (tn,
  // no_index: none) and its segment (seg, no_index: none; empty while the
  // mesh is unconstrained: a Delaunay triangulation of points does without).
  // The arrays may run past the slots in use (slot_count()): room to grow.
  std::vector<std::uint32_t> tv, tn, seg;
  // Slots of removed triangles, reused last-freed first. A free slot's first
  // corner is no_index.
  std::vector<std::uint32_t> free_slots;
  std::uint32_t slots = 0;  // slots in use (live or free)

  std::uint32_t slot_count() const noexcept { return slots; }
  bool alive(std::uint32_t t) const noexcept { return tv[3 * t] != no_index; }
  bool constrained() const noexcept { return !seg.empty(); }
  std::uint32_t origin(std::uint32_t h) const noexcept { return tv[next_half_edge(h)]; }
  std::uint32_t dest(std::uint32_t h) const noexcept { return tv[prev_half_edge(h)]; }
  bool is_ghost(std::uint32_t t) const noexcept {
    return tv[3 * t] == ghost || tv[3 * t + 1] == ghost || tv[3 * t + 2] == ghost;
  }
  void link(std::uint32_t a, std::uint32_t b) noexcept {
    tn[a] = b;
    tn[b] = a;
  }

  // Capacity for this many triangles, so that growing does not copy the
  // arrays again and again.
  void reserve(std::size_t triangles);
  // n new slots at the end; returns the first. Their corners, twins and
  // segments are for the caller to set. The arrays grow by a few dozen
  // slots at a time: the triangulator adds two slots per point, and a
  // resize per point would cost more than the insertion's own bookkeeping.
  std::uint32_t append_slots(std::uint32_t n) {
    const std::uint32_t first = slots;
    slots += n;
    if (tv.size() < 3 * std::size_t{slots}) grow_arrays();
    return first;
  }
  // Marks slot t free for reuse; the caller has unlinked it.
  void free_slot(std::uint32_t t);

  // The half-edge from vertex a = tv[corner] to b, or no_index when a and b
  // are not joined. Turns around a both ways, so that a vertex on an open
  // boundary (no ghosts) is handled as well as an inner one.
  std::uint32_t find_half_edge(std::uint32_t corner, std::uint32_t b) const noexcept;

  // Removes the triangles flagged nonzero in `dead` (every ghost among them,
  // and no free slot outside them) and numbers the rest in slot order; twins
  // into removed triangles become no_index. On return dead[t] is the new
  // index of triangle t (no_index if removed), so that the caller can move
  // its own per-triangle data the same way. The arrays are then exactly
  // the slots kept. Returns the triangles kept.
  std::uint32_t remove_triangles(std::vector<std::uint32_t>& dead);

private:
  void grow_arrays();
};

}  // namespace madd::detail
