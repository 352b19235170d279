#include "gis/coast_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "gis/ring_cleaning.hpp"
#include "kernel/containment.hpp"
#include "kernel/exact_sum.hpp"
#include "kernel/rings.hpp"
#include "madd/error.hpp"
#include "madd/intersections.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "triangulation/boundary_loops.hpp"

namespace madd::detail {

namespace {

// The body's rings as a PSLG: equal points made one vertex, ring edges
// segments with their markers.
struct BodyPslg {
  Pslg pslg;
  std::vector<VertexOrigin> origins;  // per vertex
};

BodyPslg body_pslg(const MarkedPolygon& body) {
  std::vector<const MarkedRing*> rings{&body.outer};
  for (const MarkedRing& hole : body.holes) rings.push_back(&hole);
  struct Entry {
    Point p;
    std::uint32_t ring, k;
  };
  std::vector<Entry> all;
  for (std::uint32_t r = 0; r < rings.size(); ++r)
    for (std::uint32_t k = 0; k < rings[r]->size(); ++k) all.push_back({rings[r]->points[k], r, k});
  std::vector<std::uint32_t> order(all.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return all[a].p.x < all[b].p.x || (all[a].p.x == all[b].p.x && all[a].p.y < all[b].p.y);
  });
  BodyPslg out;
  std::vector<std::uint32_t> vertex_of(all.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Entry& e = all[order[i]];
    if (i == 0 || !(e.p == all[order[i - 1]].p)) {
      out.pslg.points.push_back(e.p);
      out.origins.push_back(rings[e.ring]->origins[e.k]);
    }
    vertex_of[order[i]] = static_cast<std::uint32_t>(out.pslg.points.size() - 1);
  }
  std::size_t first = 0;
  for (const MarkedRing* ring : rings) {
    for (std::size_t k = 0; k < ring->size(); ++k) {
      const std::uint32_t a = vertex_of[first + k], b = vertex_of[first + (k + 1) % ring->size()];
      if (a != b) out.pslg.segments.push_back({a, b, ring->markers[k]});
    }
    first += ring->size();
  }
  out.pslg.has_segment_markers = true;
  out.pslg.first_index = 0;
  return out;
}

// "feature K, polygon P, ring R, vertex V" of the input vertex nearest p.
std::string nearest_origin(const BodyPslg& body, const PolygonSet& set, Point p) {
  std::size_t best = body.origins.size();
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < body.origins.size(); ++v) {
    if (body.origins[v].vertex == no_index || body.origins[v].polygon >= set.polygons.size()) continue;
    const double d = distance(body.pslg.points[v], p);
    if (d < best_d) best_d = d, best = v;
  }
  if (best == body.origins.size()) return "on the clip box";
  const VertexOrigin& o = body.origins[best];
  const GisPolygon& g = set.polygons[o.polygon];
  const std::uint32_t ring = o.ring == 0 ? g.outer.source : g.holes[o.ring - 1].source;
  return "feature " + std::to_string(g.feature) + ", polygon " + std::to_string(g.polygon) + ", ring " +
         std::to_string(ring) + ", vertex " + std::to_string(o.vertex);
}

[[noreturn]] void refuse(const InvalidInputError& e, const BodyPslg& body, const PolygonSet& set,
                         const std::string& path) {
  const Point at = e.points().empty() ? Point{} : e.points().front();
  const std::string where = e.points().empty() ? std::string("somewhere") : nearest_origin(body, set, at);
  throw InvalidInputError(e.problem(),
                          (path.empty() ? std::string() : path + ": ") + where +
                              ": the water cannot be a domain there: " + e.what(),
                          e.ids(), e.points());
}

// Crossing or overlapping ring edges split where they meet.
void resolve_crossings(BodyPslg& body, const PolygonSet& set, const std::string& path, CoastReport& report) {
  try {
    validate_pslg(body.pslg);
    return;
  } catch (const InvalidInputError& e) {
    if (e.problem() != InputProblem::segments_intersect) refuse(e, body, set, path);
  }
  try {
    validate_pslg(body.pslg, {}, {.allow_intersections = true});
  } catch (const InvalidInputError& e) {
    refuse(e, body, set, path);
  }
  ResolvedPslg resolved = resolve_intersections(body.pslg);
  report.crossings_resolved += resolved.crossings + resolved.overlaps;
  body.origins.resize(resolved.pslg.points.size(), VertexOrigin{});
  body.pslg = std::move(resolved.pslg);
}

// The faces of the rings: the triangles of the whole convex hull in
// components joined across edges that are not segments. A face is water
// when the body's rings wind an odd number of times about it (even-odd, as
// Triangle reads rings: an edge two rings share parts land from land) and
// it does not reach the hull across an edge that is no segment (there lies
// the outside). The parity is read from the rings themselves, at one point
// of each face, not by flipping it across segments from the hull: where
// rings overlap, resolve_intersections keeps one segment for an edge drawn
// twice, and a flip across it would make one face both water and land.
struct Faces {
  std::vector<std::uint32_t> face_of;  // per triangle
  std::vector<std::vector<std::uint32_t>> triangles;
  std::vector<bool> water;
  std::vector<double> area;
};

std::vector<std::uint32_t> components(const Triangulation& t, const std::vector<bool>& wall_of_edge) {
  std::vector<std::uint32_t> of(t.triangle_count(), no_index);
  std::uint32_t count = 0;
  for (std::uint32_t seed = 0; seed < t.triangle_count(); ++seed) {
    if (of[seed] != no_index) continue;
    std::vector<std::uint32_t> stack{seed};
    of[seed] = count;
    while (!stack.empty()) {
      const std::uint32_t tri = stack.back();
      stack.pop_back();
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t n = t.neighbours[tri][i];
        if (n == no_index || wall_of_edge[3 * tri + i] || of[n] != no_index) continue;
        of[n] = count, stack.push_back(n);
      }
    }
    ++count;
  }
  return of;
}

// A point to read a face or region at: of its triangles, the largest whose
// rounded centroid is still strictly inside it (exact orient2d), so off
// every segment and far from them; in a sliver the rounded centroid can
// fall on or across an edge. Fed every triangle of the face or region.
struct Probe {
  std::uint32_t triangle = no_index;
  bool strictly = false;
  double area = -1.0;

  void offer(const Triangulation& t, std::uint32_t tri) {
    const Point a = t.points[t.triangles[tri][0]], b = t.points[t.triangles[tri][1]], c = t.points[t.triangles[tri][2]];
    const Point m = triangle_centroid(a, b, c);
    const bool inside = orient2d(a, b, m) > 0.0 && orient2d(b, c, m) > 0.0 && orient2d(c, a, m) > 0.0;
    const double size = triangle_area(a, b, c);
    if (inside != strictly ? inside : size > area) triangle = tri, strictly = inside, area = size;
  }
  Point point(const Triangulation& t) const {
    const auto& v = t.triangles[triangle];
    return triangle_centroid(t.points[v[0]], t.points[v[1]], t.points[v[2]]);
  }
};

// The winding of the body's rings, read at any point.
WindingIndex body_winding(const MarkedPolygon& body, std::vector<Point>& points) {
  std::vector<std::vector<std::uint32_t>> rings;
  const auto add = [&](const MarkedRing& ring) {
    std::vector<std::uint32_t>& cycle = rings.emplace_back();
    for (Point p : ring.points) cycle.push_back(static_cast<std::uint32_t>(points.size())), points.push_back(p);
  };
  add(body.outer);
  for (const MarkedRing& hole : body.holes) add(hole);
  return WindingIndex(points, rings);
}

Faces faces_of(const Triangulation& t, const MarkedPolygon& body) {
  std::vector<bool> segment(3 * t.triangle_count());
  for (std::uint32_t tri = 0; tri < t.triangle_count(); ++tri)
    for (int i = 0; i < 3; ++i) segment[3 * tri + i] = t.is_constrained(tri, i);
  Faces f;
  f.face_of = components(t, segment);
  std::uint32_t count = 0;
  for (std::uint32_t id : f.face_of) count = std::max(count, id + 1);
  f.triangles.resize(count), f.area.assign(count, 0.0);
  std::vector<bool> outside(count, false);
  std::vector<Probe> probe(count);
  for (std::uint32_t tri = 0; tri < t.triangle_count(); ++tri) {
    const std::uint32_t face = f.face_of[tri];
    f.triangles[face].push_back(tri);
    const auto& v = t.triangles[tri];
    f.area[face] += signed_area(t.points[v[0]], t.points[v[1]], t.points[v[2]]);
    probe[face].offer(t, tri);
    for (int i = 0; i < 3; ++i)
      if (t.neighbours[tri][i] == no_index && !t.is_constrained(tri, i)) outside[face] = true;
  }
  std::vector<Point> ring_points;
  const WindingIndex winding = body_winding(body, ring_points);
  for (std::uint32_t face = 0; face < count; ++face)
    f.water.push_back(!outside[face] && (winding.winding(probe[face].point(t)) & 1) != 0);
  return f;
}

std::uint32_t chosen_face(const Triangulation& t, const Faces& f, const std::optional<Point>& at) {
  if (at) {
    for (std::uint32_t tri = 0; tri < t.triangle_count(); ++tri) {
      const auto& v = t.triangles[tri];
      if (f.water[f.face_of[tri]] && in_closed_triangle(t.points[v[0]], t.points[v[1]], t.points[v[2]], *at))
        return f.face_of[tri];
    }
    throw OptionError("water_at", "must lie in the water of a body that is kept (not on land, not in a removed piece)");
  }
  std::uint32_t best = no_index;
  for (std::uint32_t face = 0; face < f.water.size(); ++face)
    if (f.water[face] && (best == no_index || f.area[face] > f.area[best])) best = face;
  return best;
}

// With only the kept water's boundary as segments, every region but the
// water and the outside (what touches the hull) is land enclosed by that
// boundary (an island, islands touching, a pocket cut off): one hole point
// each, at its Probe.
std::vector<Point> enclosed_land_points(const Triangulation& t, const Faces& f, std::uint32_t kept) {
  std::vector<bool> wall(3 * t.triangle_count(), false);
  for (std::uint32_t tri = 0; tri < t.triangle_count(); ++tri)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t n = t.neighbours[tri][i];
      wall[3 * tri + i] = n != no_index && (f.face_of[tri] == kept) != (f.face_of[n] == kept);
    }
  const std::vector<std::uint32_t> region = components(t, wall);
  std::uint32_t count = 0;
  for (std::uint32_t id : region) count = std::max(count, id + 1);
  std::vector<bool> open(count, false);
  std::vector<Probe> probe(count);
  for (std::uint32_t tri = 0; tri < t.triangle_count(); ++tri) {
    const std::uint32_t r = region[tri];
    if (f.face_of[tri] == kept) open[r] = true;
    for (int i = 0; i < 3; ++i)
      if (t.neighbours[tri][i] == no_index) open[r] = true;
    probe[r].offer(t, tri);
  }
  std::vector<Point> points;
  for (std::uint32_t r = 0; r < count; ++r)
    if (!open[r]) points.push_back(probe[r].point(t));
  return points;
}

// The piece's own triangles, neighbours cut where they leave it.
struct PieceMesh {
  std::vector<std::array<std::uint32_t, 3>> triangles, neighbours;
  std::vector<std::uint32_t> source;  // per triangle: its index in the triangulation
};

PieceMesh piece_mesh(const Triangulation& t, const std::vector<std::uint32_t>& piece) {
  std::vector<std::uint32_t> local(t.triangle_count(), no_index);
  for (std::uint32_t k = 0; k < piece.size(); ++k) local[piece[k]] = k;
  PieceMesh m;
  for (std::uint32_t tri : piece) {
    m.triangles.push_back(t.triangles[tri]);
    std::array<std::uint32_t, 3> n{};
    for (int i = 0; i < 3; ++i) n[i] = t.neighbours[tri][i] == no_index ? no_index : local[t.neighbours[tri][i]];
    m.neighbours.push_back(n);
    m.source.push_back(tri);
  }
  return m;
}

// The outer loop of the kept water (counter-clockwise, the holes' loops
// clockwise): of positive area, decided exactly, since a sliver's
// floating-point shoelace sum can have either sign; the largest one should
// the water's boundary ever have two.
std::size_t outer_loop(const Triangulation& t, const std::vector<BoundaryLoop>& loops) {
  std::size_t best = loops.size();
  double best_area = 0.0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const ExactSum twice = ring_twice_area_exact(RingView(t.points, loops[l].vertices));
    if (twice.sign() > 0 && (best == loops.size() || twice.approximate() > best_area))
      best = l, best_area = twice.approximate();
  }
  if (best == loops.size()) throw InternalError("coast: the kept water has no outer boundary loop");
  return best;
}

// The domain's segments: every loop edge, the outer loop first.
Pslg domain_from_loops(const std::vector<BoundaryLoop>& loops, const PieceMesh& mesh, const Triangulation& t,
                       const BodyPslg& whole, CoastReport& report) {
  std::vector<std::size_t> order(loops.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto outer = order.begin() + static_cast<std::ptrdiff_t>(outer_loop(t, loops));
  std::rotate(order.begin(), outer, outer + 1);
  Pslg domain;
  domain.has_segment_markers = true;
  std::vector<std::uint32_t> id(t.points.size(), no_index);
  std::vector<std::uint32_t> visits(t.points.size(), 0);
  for (std::size_t l : order) {
    const BoundaryLoop& loop = loops[l];
    for (std::uint32_t v : loop.vertices) {
      if (++visits[v] == 2) ++report.pinches;
      if (id[v] == no_index)
        id[v] = static_cast<std::uint32_t>(domain.points.size()), domain.points.push_back(t.points[v]);
    }
    for (std::size_t k = 0; k < loop.vertices.size(); ++k) {
      const std::uint32_t side = loop.sides[k];
      const std::uint32_t segment = t.segment_of[mesh.source[side / 3]][side % 3];
      if (segment == no_index) throw InternalError("coast: a boundary edge of the kept water is on no ring");
      const std::uint32_t a = loop.vertices[k], b = loop.vertices[(k + 1) % loop.vertices.size()];
      domain.segments.push_back({id[a], id[b], whole.pslg.segments[segment].marker});
    }
  }
  return domain;
}

// The domain rebuilt from the kept water's boundary is that water: the
// loops enclose exactly its triangles (exact areas, so equal to the last
// bit), and the domain as validate() reads it, hole points flooding, has
// its area up to the rounding of shoelace sums over rings of the domain's
// extent (a bound for any ring order: each of the n fan triangles adds at
// most 2 w h (n + 1) eps of error). A relative tolerance would not do: the
// area of a sliver is all cancellation.
void check_rebuilt(const Triangulation& t, const std::vector<std::uint32_t>& kept,
                   const std::vector<BoundaryLoop>& loops, const Pslg& domain, double area) {
  ExactSum water, bounded;
  for (std::uint32_t tri : kept) {
    const auto& v = t.triangles[tri];
    water.add(triangle_twice_area_exact(t.points[v[0]], t.points[v[1]], t.points[v[2]]));
  }
  for (const BoundaryLoop& loop : loops) bounded.add(ring_twice_area_exact(RingView(t.points, loop.vertices)));
  bounded.subtract(water);
  if (!bounded.is_zero()) throw InternalError("coast: the boundary loops of the kept water do not enclose it");
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (Point p : domain.points)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const auto n = static_cast<double>(domain.segments.size() + 2);
  const double bound = n * n * 0x1p-52 * (x1 - x0) * (y1 - y0);
  const double exact = 0.5 * water.approximate();
  if (!(std::abs(area - exact) <= bound + 4 * 0x1p-52 * std::abs(exact)))
    throw InternalError("coast: the domain rebuilt from the water's boundary has area " + std::to_string(area) +
                        ", the water " + std::to_string(exact));
}

}  // namespace

bool holds_water(const MarkedPolygon& body, Point p) {
  if (locate_in_ring(RingView(body.outer.points), p) != RingLocation::inside) return false;
  for (const MarkedRing& hole : body.holes)
    if (locate_in_ring(RingView(hole.points), p) != RingLocation::outside) return false;
  return true;
}

Pslg domain_of_body(const MarkedPolygon& body, const std::optional<Point>& water_at, const PolygonSet& set,
                    const std::string& path, CoastReport& report) {
  BodyPslg whole = body_pslg(body);
  resolve_crossings(whole, set, path, report);
  const Triangulation t = triangulate(whole.pslg, {.convex_hull = true});
  const Faces faces = faces_of(t, body);
  const std::uint32_t kept = chosen_face(t, faces, water_at);
  if (kept == no_index)
    throw InvalidInputError(InputProblem::empty_domain, (path.empty() ? std::string() : path + ": ") +
                                                            "the water body has no area left after cleaning");
  for (std::uint32_t face = 0; face < faces.water.size(); ++face)
    report.pockets_dropped += faces.water[face] && face != kept;
  const PieceMesh mesh = piece_mesh(t, faces.triangles[kept]);
  const std::vector<BoundaryLoop> loops = boundary_loops(mesh.triangles, mesh.neighbours);
  Pslg domain = domain_from_loops(loops, mesh, t, whole, report);
  domain.holes = enclosed_land_points(t, faces, kept);
  report.islands = domain.holes.size();
  try {
    validate(domain);
  } catch (const InvalidInputError& e) {
    refuse(e, whole, set, path);
  }
  report.area_m2 = domain_area(domain);
  check_rebuilt(t, faces.triangles[kept], loops, domain, report.area_m2);
  return domain;
}

}  // namespace madd::detail
