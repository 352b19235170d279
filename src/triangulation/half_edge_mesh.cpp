// Slots, edge search and compaction of the half-edge core.
#include "triangulation/half_edge_mesh.hpp"

#include <algorithm>

namespace madd::detail {

void HalfEdgeMesh::reserve(std::size_t triangles) {
  tv.reserve(3 * triangles);
  tn.reserve(3 * triangles);
  if (constrained()) seg.reserve(3 * triangles);
}

// Room for the slots in use and up to 64 more, within the capacity when it
// holds them (a caller that reserved its final size gets arrays of exactly
// that size); past it the vectors double as usual.
void HalfEdgeMesh::grow_arrays() {
  const std::size_t need = 3 * std::size_t{slots};
  std::size_t size = need + 3 * 64;
  if (tv.capacity() >= need) size = std::min(size, tv.capacity());
  tv.resize(size);
  tn.resize(size);
  if (constrained()) seg.resize(size, no_index);
}

void HalfEdgeMesh::free_slot(std::uint32_t t) {
  tv[3 * t] = no_index;
  free_slots.push_back(t);
}

std::uint32_t HalfEdgeMesh::find_half_edge(std::uint32_t corner, std::uint32_t b) const noexcept {
  const std::uint32_t start = prev_half_edge(corner);  // leaves a = tv[corner]
  // Counter-clockwise around a: the edge entering a in the same triangle,
  // whose twin leaves a in the next one. A consistent mesh comes back to
  // start within the slot count; a broken one must not hang.
  std::uint32_t h = start;
  for (std::uint32_t turns = 0; turns <= slot_count(); ++turns) {
    if (dest(h) == b) return h;
    const std::uint32_t back = tn[prev_half_edge(h)];
    if (back == no_index) break;  // an open boundary: the rest lies clockwise
    h = back;
    if (h == start) return no_index;
  }
  h = start;
  for (std::uint32_t turns = 0; turns <= slot_count(); ++turns) {
    const std::uint32_t in = tn[h];
    if (in == no_index) return no_index;
    h = next_half_edge(in);
    if (h == start) return no_index;
    if (dest(h) == b) return h;
  }
  return no_index;
}

namespace {

// Moves each kept triangle t to index[t] <= t, so one forward pass never
// overwrites a triangle it has yet to read. A twin moves down with its
// triangle, from q to u <= q; one into a removed triangle becomes none.
// `Closed`: every half-edge has a twin (ghosts close the mesh).
template <bool Closed, bool Constrained>
void move_down(HalfEdgeMesh& m, const std::vector<std::uint32_t>& index) {
  std::uint32_t* tv = m.tv.data();
  std::uint32_t* tn = m.tn.data();
  std::uint32_t* seg = m.seg.data();
  for (std::uint32_t t = 0; t < index.size(); ++t) {
    const std::uint32_t to = index[t];
    if (to == no_index) continue;
    for (std::uint32_t i = 0; i < 3; ++i) {
      tv[3 * to + i] = tv[3 * t + i];
      if (Constrained) seg[3 * to + i] = seg[3 * t + i];
      const std::uint32_t twin = tn[3 * t + i];
      if (!Closed && twin == no_index) {
        tn[3 * to + i] = no_index;
        continue;
      }
      const std::uint32_t q = twin / 3, u = index[q];
      tn[3 * to + i] = u == no_index ? no_index : twin - 3 * (q - u);
    }
  }
}

}  // namespace

std::uint32_t HalfEdgeMesh::remove_triangles(std::vector<std::uint32_t>& dead) {
  std::uint32_t live = 0;
  for (std::uint32_t& d : dead) d = d ? no_index : live++;
  const bool closed = ghost != no_index;
  if (constrained()) {
    closed ? move_down<true, true>(*this, dead) : move_down<false, true>(*this, dead);
  } else {
    closed ? move_down<true, false>(*this, dead) : move_down<false, false>(*this, dead);
  }
  tv.resize(3 * std::size_t{live});
  tn.resize(3 * std::size_t{live});
  if (constrained()) seg.resize(3 * std::size_t{live});
  slots = live;
  free_slots.clear();
  ghost = no_index;
  return live;
}

}  // namespace madd::detail
