// Boundary refinement of one face, adapted to that face's own size.
#include "split/refine.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace madd::detail {

namespace {
constexpr float existing_vertex_bonus = 0.8f;  // Sec. 5.1 type 1: ends on an existing vertex
constexpr float midpoint_bonus = 0.9f;         // Sec. 5.1 type 2: ends midway between them
}  // namespace

double face_perimeter(const Subdivision& sub, std::uint32_t face) {
  double total = 0.0;
  for (const auto& ring : sub.faces[face].rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      total += distance(sub.points[ring[k]], sub.points[ring[(k + 1) % ring.size()]]);
    }
  }
  return total;
}

namespace {

// Per-edge refinement factor from the boundary weights (1 without them).
double mean_vertex_weight(const Face& f, const std::vector<double>* w) {
  if (w == nullptr) return 0.0;
  double total = 0.0;
  std::size_t n = 0;
  for (const auto& ring : f.rings) {
    for (std::uint32_t v : ring) total += (*w)[v];
    n += ring.size();
  }
  return n == 0 ? 0.0 : total / static_cast<double>(n);
}

double weight_factor(const std::vector<double>* w, double mean, std::uint32_t a, std::uint32_t b, double level) {
  if (w == nullptr || !(mean > 0.0)) return 1.0;
  return std::clamp(0.5 * ((*w)[a] + (*w)[b]) / mean, 1.0, std::max(level, 1.0));
}

}  // namespace

namespace {

// The interior pieces and isolated points of face `f` as working points and
// constrained edges (docs/algorithm.md, "Interior segments"). A point inside
// a piece, or a vertex joining exactly two pieces, is two-sided: a separator
// may cross there; a loose end is a tip, which a separator may pass through
// (BoundaryLinks::tip). Where interior segments fork or meet the rings no
// separator may end (BoundaryLinks::no_end).
void add_interior(const Subdivision& sub, const Face& f, double spacing, bool pin_isolated,
                  std::unordered_map<std::uint32_t, std::uint32_t>& working_of, std::vector<std::uint8_t>& pinched,
                  FaceDomain& out) {
  const auto add_point = [&](Point p, EndRef ref) {
    const auto id = static_cast<std::uint32_t>(out.pslg.points.size());
    ref.local = id;
    out.pslg.points.push_back(p);
    out.refs.push_back(ref);
    out.ring_of.push_back(0);
    out.links.push_back({no_index, no_index, 1.0f, true});
    pinched.push_back(0);
    return id;
  };
  const std::size_t ring_points = out.pslg.points.size();
  std::vector<std::uint32_t> no_end;
  const auto vertex_point = [&](std::uint32_t v) {
    auto [it, fresh] = working_of.try_emplace(v, 0u);
    if (fresh) it->second = add_point(sub.points[v], EndRef{EndRef::vertex, v, 0, sub.points[v]});
    if (it->second < ring_points) no_end.push_back(it->second);  // an interior segment meets the ring here
    return it->second;
  };
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours;  // vertex working point -> along pieces
  for (std::uint32_t k = 0; k < f.inner_segments.size(); ++k) {
    const std::uint32_t seg = f.inner_segments[k];
    const Point a = sub.points[sub.segments[seg].a], b = sub.points[sub.segments[seg].b];
    const auto m = static_cast<std::uint32_t>(std::min(std::max(1.0, std::ceil(distance(a, b) / spacing)), 1e6));
    std::vector<std::uint32_t> chain{vertex_point(sub.segments[seg].a)};
    for (std::uint32_t j = 1; j < m; ++j) {
      const Point p = lerp(a, b, static_cast<double>(j) / static_cast<double>(m));
      chain.push_back(add_point(p, EndRef{EndRef::inside_segment, seg, 0, p}));
    }
    chain.push_back(vertex_point(sub.segments[seg].b));
    for (std::uint32_t j = 0; j < m; ++j) {
      out.pslg.segments.push_back({chain[j], chain[j + 1], 1});
      out.inner_edge.push_back({k, j});
    }
    out.inner_edges_of.push_back(m);
    for (std::uint32_t j = 1; j < m; ++j) {
      out.links[chain[j]].prev = chain[j - 1];
      out.links[chain[j]].next = chain[j + 1];
    }
    neighbours[chain.front()].push_back(chain[1]);
    neighbours[chain.back()].push_back(chain[m - 1]);
  }
  for (const auto& [w, along] : neighbours) {
    if (w < ring_points) continue;
    if (along.size() == 1) {
      out.links[w].prev = out.links[w].next = along[0];
      out.links[w].tip = true;
      continue;
    }
    if (along.size() != 2) {
      no_end.push_back(w);
      continue;
    }
    out.links[w].prev = along[0];
    out.links[w].next = along[1];
  }
  for (const std::uint32_t w : no_end) {
    if (pinched[w]) continue;  // a ring passing twice: no separator ends there either
    // A ring vertex keeps its ring neighbours (the chord fallback and the
    // smoothing walk the ring); the others have none.
    if (w >= ring_points) out.links[w] = {no_index, no_index, out.links[w].bonus, false, false};
    out.links[w].no_end = true;
  }
  for (const std::uint32_t v : f.inner_points) {
    if (!pin_isolated) {
      out.isolated.push_back(sub.points[v]);
      continue;
    }
    const std::uint32_t w = vertex_point(v);
    pinched[w] = 1;
    out.pinned.push_back(w);
  }
}

}  // namespace

FaceDomain refine_face(const Subdivision& sub, std::uint32_t face, double spacing,
                       const std::vector<double>* point_weights, double adaptive_level, bool pin_isolated) {
  FaceDomain out;
  out.pslg.first_index = 0;
  const Face& f = sub.faces[face];
  std::unordered_map<std::uint32_t, std::uint32_t> working_of;
  std::vector<std::uint8_t> pinched;
  const double mean_weight = mean_vertex_weight(f, point_weights);
  auto add_point = [&](Point p, EndRef ref, std::uint32_t ring, float bonus) {
    const auto id = static_cast<std::uint32_t>(out.pslg.points.size());
    ref.local = id;
    out.pslg.points.push_back(p);
    out.refs.push_back(ref);
    out.ring_of.push_back(ring);
    out.links.push_back({no_index, no_index, bonus});
    pinched.push_back(0);
    return id;
  };
  for (std::size_t r = 0; r < f.rings.size(); ++r) {
    const auto& ring = f.rings[r];
    std::vector<std::uint32_t> cycle;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::uint32_t v = ring[k];
      const Point a = sub.points[v];
      auto [it, fresh] = working_of.try_emplace(v, 0u);
      if (fresh) {
        const auto ring_id = static_cast<std::uint32_t>(r);
        it->second = add_point(a, EndRef{EndRef::vertex, v, 0, a}, ring_id, existing_vertex_bonus);
      } else {
        pinched[it->second] = 1;  // the boundary passes here twice: no separator may end here
      }
      cycle.push_back(it->second);
      const Point b = sub.points[ring[(k + 1) % ring.size()]];
      const std::uint32_t seg = f.ring_segments[r][k];
      const double factor = weight_factor(point_weights, mean_weight, v, ring[(k + 1) % ring.size()], adaptive_level);
      const double pieces = std::max(1.0, std::ceil(distance(a, b) * factor / spacing));
      const auto m = static_cast<std::uint32_t>(std::min(pieces, 1e6));
      // Interpolate in the segment's stored direction, so that two faces
      // sharing the segment compute bit-identical points where their
      // subdivisions coincide (no near-duplicate vertices on commit).
      const bool forward = sub.segments[seg].a == v;
      const Point s0 = forward ? a : b;
      const Point s1 = forward ? b : a;
      for (std::uint32_t j = 1; j < m; ++j) {
        const std::uint32_t along = forward ? j : m - j;
        const Point p = lerp(s0, s1, static_cast<double>(along) / static_cast<double>(m));
        const float bonus = (2 * j == m) ? midpoint_bonus : 1.0f;
        cycle.push_back(add_point(p, EndRef{EndRef::inside_segment, seg, 0, p}, static_cast<std::uint32_t>(r), bonus));
      }
    }
    const std::size_t n = cycle.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t w = cycle[k];
      out.links[w].prev = cycle[(k + n - 1) % n];
      out.links[w].next = cycle[(k + 1) % n];
      out.pslg.segments.push_back({w, cycle[(k + 1) % n], 1});
    }
    if (r > 0) out.pslg.holes.push_back(sub.hole_point(face, r));
  }
  out.ring_segments = out.pslg.segments.size();
  add_interior(sub, f, spacing, pin_isolated, working_of, pinched, out);
  for (std::size_t w = 0; w < pinched.size(); ++w) {
    if (pinched[w]) out.links[w].prev = out.links[w].next = no_index;
  }
  return out;
}

}  // namespace madd::detail
