// The working triangulation of refinement: what refinement adds to the
// half-edge core (labels, the place of a vertex on its segment, a corner at
// each vertex), inserting in two steps, and splitting subsegments.
#include "mesh/refinement_mesh.hpp"

namespace madd::detail {

RefinementMesh::RefinementMesh(HalfEdgeMesh mesh, std::vector<Point> points, std::vector<RefinementSegment> segments,
                               std::vector<std::uint32_t> labels)
    : mesh_(std::move(mesh)), points_(std::move(points)), segments_(std::move(segments)), label_(std::move(labels)) {
  const auto n = static_cast<std::uint32_t>(points_.size());
  input_vertices_ = n;
  vertex_segment_.assign(n, no_index);
  vertex_parameter_.assign(n, 0.0);
  vertex_triangle_.assign(n, no_index);
  if (label_.size() != mesh_.slot_count()) label_.assign(mesh_.slot_count(), 0);
  for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t) set_corner_home(t);
}

void RefinementMesh::reserve(std::size_t triangles) {
  mesh_.reserve(triangles);
  label_.reserve(triangles);
  const std::size_t vertices = triangles / 2 + 16;
  points_.reserve(vertices);
  vertex_segment_.reserve(vertices);
  vertex_parameter_.reserve(vertices);
  vertex_triangle_.reserve(vertices);
}

void RefinementMesh::set_corner_home(std::uint32_t t) {
  for (std::uint32_t i = 0; i < 3; ++i) vertex_triangle_[mesh_.tv[3 * t + i]] = t;
}

std::uint32_t RefinementMesh::find_half_edge(std::uint32_t a, std::uint32_t b) const noexcept {
  const std::uint32_t t = vertex_triangle_[a];
  if (t == no_index) return no_index;
  std::uint32_t c = 3 * t;
  while (mesh_.tv[c] != a) ++c;
  return mesh_.find_half_edge(c, b);
}

WalkResult RefinementMesh::walk(std::uint32_t from, Point p) const {
  const Point* P = points_.data();
  const std::uint32_t* v = &mesh_.tv[3 * from];
  return walk_straight(mesh_, points_, p, from, triangle_centroid(P[v[0]], P[v[1]], P[v[2]]));
}

bool RefinementMesh::prepare(std::uint32_t t, Point p) {
  pending_ = p;
  cavity_.dig(mesh_, points_, t, p);
  rim_segments_.clear();
  if (!cavity_.star_shaped(points_, p)) {
    cavity_.clear();
    return false;
  }
  for (const Cavity::RimSide& r : cavity_.rim_sides())
    if (r.segment != no_index) rim_segments_.push_back(r.inner);
  return true;
}

void RefinementMesh::abandon() {
  cavity_.clear();
  rim_segments_.clear();
}

std::uint32_t RefinementMesh::commit() { return add_vertex(pending_, no_index, 0.0); }

// Fills the dug cavity around a new vertex at p; each fan triangle takes the
// label of the cavity triangle its rim edge bounded.
std::uint32_t RefinementMesh::add_vertex(Point p, std::uint32_t vertex_segment, double parameter) {
  const auto v = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  vertex_segment_.push_back(vertex_segment);
  vertex_parameter_.push_back(parameter);
  vertex_triangle_.push_back(no_index);
  rim_labels_.clear();
  for (const Cavity::RimSide& r : cavity_.rim_sides()) rim_labels_.push_back(label_[r.inner / 3]);
  const std::span<const std::uint32_t> fan = cavity_.fill(mesh_, v);
  if (label_.size() < mesh_.slot_count()) label_.resize(mesh_.slot_count(), 0);
  fresh_.clear();
  for (std::size_t i = 0; i < fan.size(); ++i) {
    label_[fan[i]] = rim_labels_[i];
    set_corner_home(fan[i]);
    fresh_.push_back(fan[i]);
  }
  rim_segments_.clear();
  return v;
}

std::uint32_t RefinementMesh::split(std::uint32_t h, double parameter) {
  const std::uint32_t s = mesh_.seg[h];
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
  const bool interior = mesh_.tn[h] != no_index;  // split on both sides
  cavity_.dig_on_edge(mesh_, points_, h, p);
  if (!cavity_.star_shaped(points_, p)) {
    cavity_.clear();
    return no_index;
  }
  const std::uint32_t v = add_vertex(p, s, parameter);
  // The two halves of h become segment edges: an interior subsegment's fan
  // closes over it, and its halves are the fan edges from v to a and to b
  // (edge 1 of (v, x, y) is y->v, edge 2 is v->x); at the outside the fan
  // stays open, and the halves are the fan edges without a twin.
  for (const std::uint32_t t : fresh_) {
    const std::uint32_t x = mesh_.tv[3 * t + 1], y = mesh_.tv[3 * t + 2];
    if (interior ? (y == a || y == b) : mesh_.tn[3 * t + 1] == no_index) mesh_.seg[3 * t + 1] = s;
    if (interior ? (x == a || x == b) : mesh_.tn[3 * t + 2] == no_index) mesh_.seg[3 * t + 2] = s;
  }
  return v;
}

}  // namespace madd::detail
