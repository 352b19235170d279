// Merging two adjacent faces (the inverse of a commit) and dropping what the
// merges left unused. Used by the balance repair (decompose/rebalance.hpp).
#include <algorithm>
#include <exception>
#include <utility>

#include "madd/error.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

namespace {

bool separates(const std::array<std::uint32_t, 2>& faces, std::uint32_t a, std::uint32_t b) {
  return (faces[0] == a && faces[1] == b) || (faces[0] == b && faces[1] == a);
}

// A ring that passes twice through one vertex pinches its face there; a split
// assumes simple rings (split/refine.hpp), so such a union is not merged.
bool rings_are_simple(const Face& face) {
  std::vector<std::uint32_t> all;
  for (const auto& ring : face.rings) all.insert(all.end(), ring.begin(), ring.end());
  std::sort(all.begin(), all.end());
  return std::adjacent_find(all.begin(), all.end()) == all.end();
}

}  // namespace

bool Subdivision::merge(std::uint32_t a, std::uint32_t b) {
  if (a == b || a >= faces.size() || b >= faces.size()) return false;
  // The half-edges of both faces' rings, less the separators between them:
  // every vertex keeps as many edges in as out, so they close into cycles.
  std::vector<HalfEdge> half_edges;
  std::vector<std::uint32_t> shared;
  for (const std::uint32_t f : {a, b}) {
    for (std::size_t r = 0; r < faces[f].rings.size(); ++r) {
      const auto& ring = faces[f].rings[r];
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::uint32_t seg = faces[f].ring_segments[r][k];
        if (separates(seg_faces[seg], a, b)) {
          if (f == a) shared.push_back(seg);
          continue;
        }
        half_edges.push_back({ring[k], ring[(k + 1) % ring.size()], seg});
      }
    }
  }
  if (shared.empty()) return false;
  std::vector<Cycle> cycles;
  for (const auto& ids : walk_faces(points, half_edges)) cycles.push_back(make_cycle(points, half_edges, ids));
  Face merged;
  try {
    merged = assemble_face(cycles, faces[a].interior, a);
  } catch (const DecompositionError&) {
    return false;  // the union has no single outer ring
  }
  if (!rings_are_simple(merged)) return false;
  for (const std::uint32_t f : {a, b}) {
    merged.inner_segments.insert(merged.inner_segments.end(), faces[f].inner_segments.begin(),
                                 faces[f].inner_segments.end());
    merged.inner_points.insert(merged.inner_points.end(), faces[f].inner_points.begin(), faces[f].inner_points.end());
  }

  const std::uint32_t keep = std::min(a, b), gone = std::max(a, b);
  for (const std::uint32_t seg : shared) seg_faces[seg] = {no_index, no_index};
  for (const auto& ring : merged.ring_segments) {
    for (const std::uint32_t seg : ring) {
      for (std::uint32_t& f : seg_faces[seg]) {
        if (f == a || f == b) f = keep;
      }
    }
  }
  for (const std::uint32_t f : {a, b}) {  // siblings are mutual: only theirs can name a or b
    if (faces[f].sibling != no_index) faces[faces[f].sibling].sibling = no_index;
  }
  for (const std::uint32_t seg : merged.inner_segments) seg_faces[seg] = {keep, keep};
  faces[keep] = std::move(merged);
  const auto last = static_cast<std::uint32_t>(faces.size() - 1);
  if (gone != last) {
    for (const auto& ring : faces[last].ring_segments) {
      for (const std::uint32_t seg : ring) {
        for (std::uint32_t& f : seg_faces[seg]) {
          if (f == last) f = gone;
        }
      }
    }
    for (const std::uint32_t seg : faces[last].inner_segments) seg_faces[seg] = {gone, gone};
    if (faces[last].sibling != no_index) faces[faces[last].sibling].sibling = gone;
    faces[gone] = std::move(faces[last]);
  }
  faces.pop_back();
  return true;
}

void Subdivision::compact() {
  const auto segment_count = static_cast<std::uint32_t>(segments.size());
  std::vector<std::uint8_t> live_point(points.size(), 0), dead_point(points.size(), 0);
  std::vector<std::uint32_t> new_segment(segment_count, no_index);
  std::uint32_t kept = 0;
  for (std::uint32_t s = 0; s < segment_count; ++s) {
    const bool live = seg_faces[s][0] != no_index || seg_faces[s][1] != no_index;
    auto& mark = live ? live_point : dead_point;
    mark[segments[s].a] = mark[segments[s].b] = 1;
    if (live) new_segment[s] = kept++;
  }
  if (kept == segment_count) return;
  // Only points that a removed separator used and nothing else are dropped.
  std::vector<std::uint32_t> new_point(points.size(), no_index);
  std::uint32_t kept_points = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (live_point[p] || !dead_point[p]) {
      new_point[p] = kept_points;
      points[kept_points++] = points[p];
    }
  }
  points.resize(kept_points);
  for (std::uint32_t s = 0; s < segment_count; ++s) {
    const std::uint32_t to = new_segment[s];
    if (to == no_index) continue;
    Segment seg = segments[s];
    seg.a = new_point[seg.a];
    seg.b = new_point[seg.b];
    segments[to] = seg;
    origin[to] = origin[s];
    next_piece[to] = next_piece[s] == no_index ? no_index : new_segment[next_piece[s]];
    seg_faces[to] = seg_faces[s];
  }
  segments.resize(kept);
  origin.resize(kept);
  next_piece.resize(kept);
  seg_faces.resize(kept);
  for (Face& face : faces) {
    for (auto& ring : face.rings) {
      for (std::uint32_t& v : ring) v = new_point[v];
    }
    for (auto& ring : face.ring_segments) {
      for (std::uint32_t& s : ring) s = new_segment[s];
    }
    for (std::uint32_t& s : face.inner_segments) s = new_segment[s];
    for (std::uint32_t& v : face.inner_points) v = new_point[v];
  }
}

}  // namespace madd::detail
