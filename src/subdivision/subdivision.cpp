// The global subdivision: initial rings, segment splitting and the commit of
// a split (Algorithm 3 applied to the shared structure).
#include "subdivision/subdivision.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "kernel/rings.hpp"
#include "pslg/validate_detail.hpp"
#include "madd/error.hpp"

namespace madd::detail {

Cycle make_cycle(const std::vector<Point>& points, const std::vector<HalfEdge>& half_edges,
                 const std::vector<std::uint32_t>& ids) {
  Cycle c;
  for (std::uint32_t h : ids) {
    c.vertices.push_back(half_edges[h].from);
    c.segments.push_back(half_edges[h].segment);
  }
  c.area = ring_signed_area(RingView(points, c.vertices));
  return c;
}

Subdivision Subdivision::from_domain(const Pslg& domain) {
  Subdivision s;
  s.points = domain.points;
  // Segments split at the vertices lying inside them (no new points), each
  // piece with the sides the domain lies on (docs/algorithm.md, "Interior segments").
  const DomainPieces dp = trace_domain_pieces(domain, has_vertex_inside_segment(domain));
  const Pslg& pieces = dp.resolved.pslg;
  const auto n = static_cast<std::uint32_t>(pieces.segments.size());
  std::vector<HalfEdge> half_edges;  // the boundary pieces, each run with the domain on its left
  Face face;
  for (std::uint32_t k = 0; k < n; ++k) {
    Segment seg = pieces.segments[k];
    if (!domain.has_segment_markers || seg.marker == 0) seg.marker = 1;
    s.segments.push_back(seg);
    const std::uint32_t source = dp.resolved.source_segment[k];
    s.origin.push_back(source);
    // Pieces of one segment are consecutive, in its direction.
    s.next_piece.push_back(k + 1 < n && dp.resolved.source_segment[k + 1] == source ? k + 1 : no_index);
    const unsigned sides = dp.domain_sides(k);
    if (sides == 3U) face.inner_segments.push_back(k);
    else if (sides == 1U) half_edges.push_back({seg.a, seg.b, k});
    else half_edges.push_back({seg.b, seg.a, k});
  }
  face.inner_points = dp.isolated;
  s.seg_faces.assign(n, {no_index, no_index});
  s.origin_hole.assign(domain.segments.size(), Point{});
  s.origin_has_hole.assign(domain.segments.size(), 0);
  std::vector<Cycle> cycles;
  for (const auto& ids : walk_faces(s.points, half_edges)) cycles.push_back(make_cycle(s.points, half_edges, ids));
  // With the domain on their left, its outer ring is the one counter-clockwise
  // cycle and every clockwise one bounds a hole: the face on its other side
  // holds the hole point that removed it.
  std::vector<std::uint32_t> hole_of_face(dp.faces.ring_count(), no_index);
  for (std::uint32_t h = static_cast<std::uint32_t>(dp.real_holes); h-- > 0;) {
    if (dp.faces.hole_face[h] != no_index) hole_of_face[dp.faces.hole_face[h]] = h;
  }
  std::size_t outer = no_index;
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    if (cycles[c].area > 0.0 && (outer == no_index || cycles[c].area > cycles[outer].area)) outer = c;
  }
  if (outer == no_index) throw DecompositionError("domain has no outer boundary");
  face.rings.push_back(cycles[outer].vertices);
  face.ring_segments.push_back(cycles[outer].segments);
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    if (c == outer) continue;
    if (cycles[c].area > 0.0) throw DecompositionError("the domain's boundary has two outer rings (internal error)");
    // The half-edge of the ring's first piece that runs away from the domain.
    const std::uint32_t k = cycles[c].segments[0];
    const bool forward = s.segments[k].a == cycles[c].vertices[0];
    const std::uint32_t outside = dp.faces.face_of_half_edge(2 * k + (forward ? 1 : 0));
    const std::uint32_t hole = outside == no_index ? no_index : hole_of_face[outside];
    if (hole == no_index) throw DecompositionError("a hole ring of the domain contains no hole point");
    for (std::uint32_t seg : cycles[c].segments) {
      s.origin_hole[s.origin[seg]] = domain.holes[hole];
      s.origin_has_hole[s.origin[seg]] = 1;
    }
    face.rings.push_back(cycles[c].vertices);
    face.ring_segments.push_back(cycles[c].segments);
  }
  for (const auto& ring : face.ring_segments) {
    for (std::uint32_t seg : ring) s.seg_faces[seg][0] = 0;
  }
  for (const std::uint32_t seg : face.inner_segments) s.seg_faces[seg] = {0, 0};
  s.faces.push_back(std::move(face));
  return s;
}

Point Subdivision::hole_point(std::uint32_t face, std::size_t ring) const {
  const std::uint32_t seg = faces[face].ring_segments[ring][0];
  const auto& sf = seg_faces[seg];
  const std::uint32_t other = sf[0] == face ? sf[1] : sf[0];
  if (other != no_index) return faces[other].interior;
  const std::uint32_t o = origin[seg];
  if (o == no_index || !origin_has_hole[o]) {
    throw DecompositionError("hole ring without a hole point (internal error)", face);
  }
  return origin_hole[o];
}

double Subdivision::face_area(std::uint32_t face) const { return rings_area(points, faces[face].rings); }

std::size_t Subdivision::ring_vertex_count(std::uint32_t face) const {
  std::size_t n = 0;
  for (const auto& ring : faces[face].rings) n += ring.size();
  return n;
}

std::uint32_t Subdivision::split_segment(std::uint32_t piece, std::uint32_t w) {
  const Segment old = segments[piece];
  const auto s2 = static_cast<std::uint32_t>(segments.size());
  segments[piece].b = w;
  segments.push_back({w, old.b, old.marker});
  origin.push_back(origin[piece]);
  next_piece.push_back(next_piece[piece]);
  next_piece[piece] = s2;
  seg_faces.push_back(seg_faces[piece]);
  if (is_inner(piece)) {
    faces[seg_faces[piece][0]].inner_segments.push_back(s2);
    return w;
  }
  for (std::uint32_t f : seg_faces[piece]) {
    if (f == no_index) continue;
    Face& face = faces[f];
    for (std::size_t r = 0; r < face.rings.size(); ++r) {
      auto& segs = face.ring_segments[r];
      auto it = std::find(segs.begin(), segs.end(), piece);
      if (it == segs.end()) continue;
      const auto k = static_cast<std::size_t>(it - segs.begin());
      auto& ring = face.rings[r];
      const bool forward = ring[k] == old.a;
      ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(k + 1), w);
      segs.insert(segs.begin() + static_cast<std::ptrdiff_t>(k + 1), forward ? s2 : piece);
      segs[k] = forward ? piece : s2;
      break;
    }
  }
  return w;
}

std::uint32_t Subdivision::resolve(const EndRef& end, const SnapEdge* snap) {
  if (end.kind == EndRef::vertex) return end.id;
  if (end.kind == EndRef::centre) {
    points.push_back(end.p);
    return static_cast<std::uint32_t>(points.size() - 1);
  }
  // The piece of the snapshot segment may have been split by earlier commits:
  // walk the chain of pieces along the original direction.
  for (std::uint32_t q = end.id; q != no_index; q = next_piece[q]) {
    const Point a = points[segments[q].a];
    const Point b = points[segments[q].b];
    if (end.p == a) return segments[q].a;
    if (end.p == b) return segments[q].b;
    const double t = dot(end.p - a, b - a) / dot(b - a, b - a);
    if (t >= 1.0) continue;
    if (t <= 0.0) return segments[q].a;
    if (snap != nullptr) {
      // The nearer end of the piece first (ties: a).
      std::uint32_t near = segments[q].a, far = segments[q].b;
      if (distance(end.p, points[far]) < distance(end.p, points[near])) std::swap(near, far);
      for (const std::uint32_t v : {near, far}) {
        if (may_snap(v, end, *snap)) return v;
      }
    }
    points.push_back(end.p);
    return split_segment(q, static_cast<std::uint32_t>(points.size() - 1));
  }
  throw DecompositionError("separator end not found on its segment (internal error)");
}

std::uint32_t Subdivision::add_separators(std::uint32_t face, const SplitResult& split) {
  const auto new_id = static_cast<std::uint32_t>(faces.size());
  // Ends shared by several separator edges of this split resolve once.
  using Key = std::pair<int, std::uint32_t>;
  const auto key_of = [](const EndRef& e) { return Key{e.kind == EndRef::centre ? 1 : 0, e.local}; };
  // Per end: the edges of the split that meet there.
  std::map<Key, std::vector<std::size_t>> edges_at;
  for (std::size_t k = 0; k < split.edges.size(); ++k) {
    edges_at[key_of(split.edges[k].a)].push_back(k);
    edges_at[key_of(split.edges[k].b)].push_back(k);
  }
  std::map<Key, std::uint32_t> resolved;
  auto vertex_of = [&](const EndRef& e, const EndRef& other) {
    const Key key = key_of(e);
    auto it = resolved.find(key);
    if (it != resolved.end()) return it->second;
    std::uint32_t v = 0;
    const bool far_ok = other.kind == EndRef::centre || edges_at[key_of(other)].size() == 1;
    if (split.snap.distance > 0.0 && e.kind == EndRef::inside_segment && edges_at[key].size() == 1 && far_ok) {
      SnapEdge snap;
      snap.split = &split;
      snap.face = face;
      snap.far = other;
      for (const std::size_t k : edges_at[key_of(other)]) {
        const SeparatorEdge& s = split.edges[k];
        snap.far_ends.push_back(key_of(s.a) == key_of(other) ? s.b.p : s.a.p);
      }
      for (const auto& [k, w] : resolved) snap.taken.push_back(w);
      v = resolve(e, &snap);
    } else {
      v = resolve(e);
    }
    resolved.emplace(key, v);
    return v;
  };
  std::vector<Segment> seps;
  for (const SeparatorEdge& e : split.edges) {
    const std::uint32_t a = vertex_of(e.a, e.b);
    const std::uint32_t b = vertex_of(e.b, e.a);
    seps.push_back({a, b, 0});
  }
  const auto first = static_cast<std::uint32_t>(segments.size());
  for (const Segment& seg : seps) {
    segments.push_back(seg);
    origin.push_back(no_index);
    next_piece.push_back(no_index);
    seg_faces.push_back({face, new_id});
  }
  return first;
}

std::uint32_t Subdivision::commit(std::uint32_t face, const SplitResult& split) {
  const auto new_id = static_cast<std::uint32_t>(faces.size());
  // The interior pieces as the split saw them, with their ends then: a
  // separator crossing one splits it (add_separators), and each part goes to
  // the side its working edges were on.
  const std::vector<std::uint32_t> inner_before = faces[face].inner_segments;
  std::vector<Segment> inner_span;
  for (const std::uint32_t seg : inner_before) inner_span.push_back(segments[seg]);
  const std::uint32_t first_separator = add_separators(face, split);
  // Half-edges: the face's rings in ring direction, separators both ways.
  // side_of: 0/1 for separators (the side on the left), 2 + ring for ring edges.
  std::vector<HalfEdge> half_edges;
  std::vector<std::uint32_t> side_of;
  const Face& old = faces[face];
  for (std::size_t r = 0; r < old.rings.size(); ++r) {
    const auto& ring = old.rings[r];
    for (std::size_t k = 0; k < ring.size(); ++k) {
      half_edges.push_back({ring[k], ring[(k + 1) % ring.size()], old.ring_segments[r][k]});
      side_of.push_back(static_cast<std::uint32_t>(2 + r));
    }
  }
  for (std::uint32_t seg = first_separator; seg < segments.size(); ++seg) {
    const std::uint8_t left = split.edges[seg - first_separator].left_side;
    half_edges.push_back({segments[seg].a, segments[seg].b, seg});
    side_of.push_back(left);
    half_edges.push_back({segments[seg].b, segments[seg].a, seg});
    side_of.push_back(1u - left);
  }
  std::vector<Cycle> cycles[2];
  for (const auto& ids : walk_faces(points, half_edges)) {
    // A cycle's side: that of any separator on it, else that of its ring.
    std::uint32_t side = split.ring_side[side_of[ids[0]] < 2 ? 0 : side_of[ids[0]] - 2];
    for (std::uint32_t h : ids) {
      if (side_of[h] < 2) {
        side = side_of[h];
        break;
      }
    }
    cycles[side].push_back(make_cycle(points, half_edges, ids));
  }
  Face sides[2];
  for (int s = 0; s < 2; ++s) sides[s] = assemble_face(cycles[s], split.interior[s], face);
  assign_inner(face, split, inner_before, inner_span, sides);
  for (const std::uint32_t seg : sides[1].inner_segments) seg_faces[seg] = {new_id, new_id};
  for (const auto& ring : sides[1].ring_segments) {
    for (std::uint32_t seg : ring) {
      if (seg >= first_separator) continue;  // new separators already name both faces
      auto& sf = seg_faces[seg];
      if (sf[0] == face) sf[0] = new_id;
      else if (sf[1] == face) sf[1] = new_id;
    }
  }
  // The other side of the split that made `face` loses its sibling (siblings are mutual).
  if (faces[face].sibling != no_index) faces[faces[face].sibling].sibling = no_index;
  sides[0].sibling = new_id;
  sides[1].sibling = face;
  faces[face] = std::move(sides[0]);
  faces.push_back(std::move(sides[1]));
  return new_id;
}

void Subdivision::assign_inner(std::uint32_t face, const SplitResult& split, const std::vector<std::uint32_t>& before,
                               const std::vector<Segment>& span, Face sides[2]) const {
  const Face& old = faces[face];
  if (split.inner_sides.size() != before.size() || split.point_sides.size() != old.inner_points.size())
    throw DecompositionError("split of subdomain " + std::to_string(face) +
                                 " does not place its interior constraints (internal error)",
                             face);
  for (std::size_t k = 0; k < before.size(); ++k) {
    const std::vector<std::uint8_t>& along = split.inner_sides[k];
    const Point a = points[span[k].a], b = points[span[k].b];
    const double length2 = dot(b - a, b - a);
    // The parts of the piece, in its direction: the piece itself, then those split off it.
    for (std::uint32_t q = before[k]; q != no_index; q = next_piece[q]) {
      std::uint8_t side = 0;
      if (!along.empty()) {
        const Point mid = lerp(points[segments[q].a], points[segments[q].b], 0.5);
        const double t = dot(mid - a, b - a) / length2;
        const auto m = static_cast<double>(along.size());
        side = along[static_cast<std::size_t>(std::clamp(std::floor(t * m), 0.0, m - 1.0))];
      }
      sides[side].inner_segments.push_back(q);
      if (segments[q].b == span[k].b) break;
    }
  }
  for (std::size_t k = 0; k < old.inner_points.size(); ++k)
    sides[split.point_sides[k]].inner_points.push_back(old.inner_points[k]);
}

Face Subdivision::assemble_face(std::vector<Cycle>& cycles, Point interior, std::uint32_t face) const {
  Face out;
  out.interior = interior;
  int outers = 0;
  for (Cycle& c : cycles) {
    if (c.area > 0.0) {
      ++outers;
      out.rings.insert(out.rings.begin(), std::move(c.vertices));
      out.ring_segments.insert(out.ring_segments.begin(), std::move(c.segments));
    } else {
      out.rings.push_back(std::move(c.vertices));
      out.ring_segments.push_back(std::move(c.segments));
    }
  }
  if (outers != 1) {
    throw DecompositionError(
        "split of subdomain " + std::to_string(face) + " did not give two connected faces (internal error)", face);
  }
  return out;
}

}  // namespace madd::detail
