// The working triangulation of refinement: locating, inserting by
// Bowyer-Watson within the segments, and splitting subsegments.
#include "mesh/refinement_mesh.hpp"

#include <algorithm>

#include "madd/error.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

RefinementMesh::RefinementMesh(const Triangulation& tri, std::vector<RefinementSegment> segments,
                               const std::vector<std::uint32_t>& labels)
    : points_(tri.points), segments_(std::move(segments)) {
  const auto n = static_cast<std::uint32_t>(points_.size());
  input_vertices_ = n;
  vertex_segment_.assign(n, no_index);
  vertex_parameter_.assign(n, 0.0);
  vertex_triangle_.assign(n, no_index);
  const auto nt = static_cast<std::uint32_t>(tri.triangles.size());
  tv_.resize(3 * std::size_t{nt});
  tn_.assign(3 * std::size_t{nt}, no_index);
  seg_.resize(3 * std::size_t{nt});
  alive_.assign(nt, 1);
  label_.assign(nt, 0);
  if (labels.size() == nt) label_ = labels;
  for (std::uint32_t t = 0; t < nt; ++t) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      tv_[3 * t + i] = tri.triangles[t][i];
      seg_[3 * t + i] = tri.segment_of[t][i];
    }
    set_corner_home(t);
  }
  // Twins: edge i of t is the edge j of its neighbour u with the same ends reversed.
  for (std::uint32_t t = 0; t < nt; ++t) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u == no_index) continue;
      const std::uint32_t h = 3 * t + i;
      for (std::uint32_t j = 0; j < 3; ++j) {
        const std::uint32_t g = 3 * u + j;
        if (origin(g) == dest(h) && dest(g) == origin(h)) tn_[h] = g;
      }
      if (tn_[h] == no_index) throw InternalError("refinement: triangulation neighbours do not share an edge");
    }
  }
}

void RefinementMesh::reserve(std::size_t triangles) {
  tv_.reserve(3 * triangles);
  tn_.reserve(3 * triangles);
  seg_.reserve(3 * triangles);
  alive_.reserve(triangles);
  label_.reserve(triangles);
  const std::size_t vertices = triangles / 2 + 16;
  points_.reserve(vertices);
  vertex_segment_.reserve(vertices);
  vertex_parameter_.reserve(vertices);
  vertex_triangle_.reserve(vertices);
}

void RefinementMesh::set_corner_home(std::uint32_t t) {
  for (std::uint32_t i = 0; i < 3; ++i) vertex_triangle_[tv_[3 * t + i]] = t;
}

std::uint32_t RefinementMesh::find_half_edge(std::uint32_t a, std::uint32_t b) const noexcept {
  const std::uint32_t t0 = vertex_triangle_[a];
  if (t0 == no_index) return no_index;
  std::uint32_t i = 0;
  while (tv_[3 * t0 + i] != a) ++i;
  const std::uint32_t start = 3 * t0 + (i + 2) % 3;  // the half-edge leaving a in t0
  // Counter-clockwise around a: leaving a -> the edge entering a in the same
  // triangle -> its twin leaves a in the next triangle.
  std::uint32_t h = start;
  do {
    if (dest(h) == b) return h;
    const std::uint32_t back = tn_[prev_half_edge(h)];
    if (back == no_index) break;
    h = back;
  } while (h != start);
  // Clockwise from the start, for a vertex on the boundary.
  h = start;
  for (;;) {
    const std::uint32_t in = tn_[h];
    if (in == no_index) return no_index;
    h = next_half_edge(in);
    if (h == start) return no_index;
    if (dest(h) == b) return h;
  }
}

RefinementMesh::Walk RefinementMesh::walk(std::uint32_t from, Point p) const {
  const Point* P = points_.data();
  const Point o = triangle_centroid(P[tv_[3 * from]], P[tv_[3 * from + 1]], P[tv_[3 * from + 2]]);
  std::uint32_t t = from;
  const std::size_t max_steps = 4 * std::size_t{slot_count()} + 64;
  for (std::size_t step = 0; step < max_steps; ++step) {
    std::uint32_t exit = no_index, beyond = no_index;
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
      const Point u = P[origin(h)], v = P[dest(h)];
      if (orient2d(u, v, p) >= 0) continue;
      beyond = h;
      if (orient2d(o, p, u) <= 0 && orient2d(o, p, v) >= 0) {
        exit = h;
        break;
      }
    }
    if (beyond == no_index) return {t, no_index};
    if (exit == no_index) exit = beyond;  // the line grazes a vertex: any edge p is beyond moves closer
    if (seg_[exit] != no_index) return {no_index, exit};
    t = tn_[exit] / 3;
  }
  return {};
}

std::uint32_t RefinementMesh::new_slot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    return t;
  }
  const std::uint32_t t = slot_count();
  tv_.resize(tv_.size() + 3);
  tn_.resize(tn_.size() + 3);
  seg_.resize(seg_.size() + 3);
  alive_.push_back(0);
  label_.push_back(0);
  return t;
}

// Grows the cavity of p from t (always in it: p lies in its closure) across
// unconstrained edges into every triangle whose circumcircle strictly holds p,
// recording the rim. `skip`, a subsegment being split, is left off the rim;
// an interior subsegment's twin `skip_twin` too, and the cavity starts on
// both its sides (p, strictly inside the edge, is strictly inside both
// triangles' circumcircles).
bool RefinementMesh::collect_cavity(std::uint32_t t, Point p, std::uint32_t skip, std::uint32_t skip_twin) {
  if (in_cavity_.size() < slot_count()) in_cavity_.resize(slot_count(), 0);
  cavity_.clear();
  rim_.clear();
  rim_segments_.clear();
  stack_.clear();
  in_cavity_[t] = 1;
  cavity_.push_back(t);
  stack_.push_back(t);
  if (skip_twin != no_index) {
    in_cavity_[skip_twin / 3] = 1;
    cavity_.push_back(skip_twin / 3);
    stack_.push_back(skip_twin / 3);
  }
  const Point* P = points_.data();
  while (!stack_.empty()) {
    const std::uint32_t c = stack_.back();
    stack_.pop_back();
    for (std::uint32_t h = 3 * c; h < 3 * c + 3; ++h) {
      const std::uint32_t out = tn_[h];
      if (seg_[h] == no_index && out != no_index) {
        const std::uint32_t u = out / 3;
        if (in_cavity_[u]) continue;
        if (incircle(P[tv_[3 * u]], P[tv_[3 * u + 1]], P[tv_[3 * u + 2]], p) > 0) {
          in_cavity_[u] = 1;
          cavity_.push_back(u);
          stack_.push_back(u);
          continue;
        }
      }
      if (h == skip || h == skip_twin) continue;
      rim_.push_back({origin(h), dest(h), out, seg_[h], label_[c]});
      if (seg_[h] != no_index) rim_segments_.push_back(h);
    }
  }
  // Star-shaped from p, exactly: every fan triangle strictly counter-clockwise.
  for (const Rim& r : rim_) {
    if (orient2d(P[r.a], P[r.b], p) <= 0) return false;
  }
  return true;
}

void RefinementMesh::clear_cavity() {
  for (const std::uint32_t c : cavity_) in_cavity_[c] = 0;
  cavity_.clear();
  rim_.clear();
  rim_segments_.clear();
  skip_ = no_index;
  skip_twin_ = no_index;
}

bool RefinementMesh::prepare(std::uint32_t t, Point p) {
  pending_ = p;
  skip_ = no_index;
  skip_twin_ = no_index;
  if (collect_cavity(t, p, no_index, no_index)) return true;
  clear_cavity();
  return false;
}

void RefinementMesh::abandon() { clear_cavity(); }

std::uint32_t RefinementMesh::commit() { return fan(no_index, 0.0); }

// Replaces the cavity by the fan of triangles (v, a, b), one per rim edge
// a->b, v the new vertex at pending_. With a split (skip_ set) the fan is
// open at the split subsegment a0->b0, whose halves a0->v and v->b0 become
// segment edges facing the outside. Splitting an interior subsegment the
// fan is closed (the cavity holds both sides), and the two fan edges from v
// to a0 and to b0 become the halves.
std::uint32_t RefinementMesh::fan(std::uint32_t vertex_segment, double parameter) {
  // Read before slots are reused.
  const std::uint32_t split_segment = skip_ == no_index ? no_index : seg_[skip_];
  const std::uint32_t a0 = skip_twin_ == no_index ? no_index : origin(skip_);
  const std::uint32_t b0 = skip_twin_ == no_index ? no_index : dest(skip_);
  const auto v = static_cast<std::uint32_t>(points_.size());
  points_.push_back(pending_);
  vertex_segment_.push_back(vertex_segment);
  vertex_parameter_.push_back(parameter);
  vertex_triangle_.push_back(no_index);
  if (link_.size() < points_.size()) link_.resize(points_.size() + points_.size() / 2 + 16, no_index);

  for (const std::uint32_t c : cavity_) {
    in_cavity_[c] = 0;
    alive_[c] = 0;
    free_.push_back(c);
  }
  fresh_.clear();
  for (const Rim& r : rim_) {
    const std::uint32_t t = new_slot();
    alive_[t] = 1;
    tv_[3 * t] = v;
    tv_[3 * t + 1] = r.a;
    tv_[3 * t + 2] = r.b;
    tn_[3 * t] = r.outer;
    seg_[3 * t] = r.segment;
    if (r.outer != no_index) tn_[r.outer] = 3 * t;
    tn_[3 * t + 1] = tn_[3 * t + 2] = no_index;
    seg_[3 * t + 1] = seg_[3 * t + 2] = no_index;
    label_[t] = r.label;
    link_[r.a] = t;
    set_corner_home(t);
    fresh_.push_back(t);
  }
  // Edge 1 of the triangle on rim a->b is b->v; its twin is edge 2 (v->b) of
  // the triangle whose rim starts at b. At an open fan (a split), the
  // triangle whose rim ends at a0 has no such partner: its b->v and the
  // partner-less v->b0 are the two halves of the split subsegment.
  for (const std::uint32_t t : fresh_) {
    const std::uint32_t b = tv_[3 * t + 2];
    const std::uint32_t next = link_[b];
    if (next != no_index && alive_[next] && tv_[3 * next] == v && tv_[3 * next + 1] == b) {
      tn_[3 * t + 1] = 3 * next + 2;
      tn_[3 * next + 2] = 3 * t + 1;
    } else {
      seg_[3 * t + 1] = split_segment;
    }
  }
  for (const std::uint32_t t : fresh_) {
    if (tn_[3 * t + 2] == no_index) seg_[3 * t + 2] = split_segment;
    link_[tv_[3 * t + 1]] = no_index;
  }
  if (a0 != no_index) {
    // Edge 1 of (v, a, b) is b->v, edge 2 is v->a.
    for (const std::uint32_t t : fresh_) {
      if (tv_[3 * t + 2] == a0 || tv_[3 * t + 2] == b0) seg_[3 * t + 1] = split_segment;
      if (tv_[3 * t + 1] == a0 || tv_[3 * t + 1] == b0) seg_[3 * t + 2] = split_segment;
    }
  }
  cavity_.clear();
  rim_.clear();
  rim_segments_.clear();
  skip_ = no_index;
  skip_twin_ = no_index;
  return v;
}

std::uint32_t RefinementMesh::split(std::uint32_t h, double parameter) {
  const std::uint32_t s = seg_[h];
  if (s == no_index) return no_index;  // only subsegments split
  const RefinementSegment& segment = segments_[s];
  const std::uint32_t a = origin(h), b = dest(h);
  const auto parameter_of = [&](std::uint32_t x) {
    if (x == segment.a) return 0.0;
    if (x == segment.b) return 1.0;
    return vertex_parameter_[x];
  };
  const double ta = parameter_of(a), tb = parameter_of(b);
  if (!((ta < parameter && parameter < tb) || (tb < parameter && parameter < ta))) return no_index;
  const Point p = lerp(points_[segment.a], points_[segment.b], parameter);
  if (p == points_[a] || p == points_[b]) return no_index;
  pending_ = p;
  const std::uint32_t twin = tn_[h];  // an interior subsegment: split on both sides
  if (!collect_cavity(h / 3, p, h, twin)) {
    clear_cavity();
    return no_index;
  }
  skip_ = h;
  skip_twin_ = twin;
  return fan(s, parameter);
}

} // namespace madd::detail
