// Segment recovery for the constrained Delaunay triangulation: the triangles
// a segment crosses are removed and the two pseudo-polygons on either side are
// re-triangulated by the Delaunay triangulation of a pseudo-polygon (Anglada
// 1997; Shewchuk's CDT notes), with an explicit task stack instead of recursion.
// A segment passing exactly through a vertex is split there.
#include <algorithm>
#include <string>

#include "triangulation/cdt.hpp"
#include "madd/error.hpp"
#include "madd/predicates.hpp"

namespace madd::detail {

namespace {

// c lies on the ray from a through b, given that a, b, c are collinear and
// distinct. Exact: compares coordinates on an axis where a and b differ.
bool same_direction(Point a, Point b, Point c) noexcept {
  if (a.x != b.x) return (b.x > a.x) == (c.x > a.x);
  return (b.y > a.y) == (c.y > a.y);
}

[[noreturn]] void throw_crossing(const Pslg& pslg, std::uint32_t s, std::uint32_t other) {
  const std::int64_t base = pslg.first_index;
  throw InvalidInputError(InputProblem::segments_intersect,
                          "segments " + std::to_string(s + base) + " and " + std::to_string(other + base) +
                              " intersect",
                          {s + base, other + base});
}

class SegmentInserter {
public:
  SegmentInserter(HalfEdgeMesh& mesh, const Pslg& pslg);
  void insert(std::uint32_t s);

private:
  struct Path {
    std::vector<std::uint32_t> verts;  // boundary vertices from u to v
    std::vector<std::uint32_t> ext;    // twin half-edge outside, per path edge
  };
  struct Task {
    std::uint32_t i, j, parent;
  };
  std::uint32_t find_exit(std::uint32_t a, std::uint32_t b, std::uint32_t& corner) const;
  std::uint32_t cross(std::uint32_t a, std::uint32_t b, std::uint32_t t0, std::uint32_t h, std::uint32_t s);
  std::uint32_t fill(const Path& path, std::size_t& next_slot);
  void mark(std::uint32_t h, std::uint32_t s);
  void attach(std::uint32_t inner, std::uint32_t outer);
  void find_slits(const Path& path);
  void close_slits();

  HalfEdgeMesh& m_;
  const Pslg& pslg_;
  std::span<const Point> P_;        // the mesh's vertices are indices into it
  std::vector<std::uint32_t> v2c_;  // per vertex: a corner (3t+i) holding it
  std::vector<std::uint32_t> crossed_;
  Path upper_, lower_;
  std::vector<Task> tasks_;
  // A vertex can lie strictly inside the cavity, joined to the rest by an
  // uncrossed edge inside it (the segment crosses every triangle around it):
  // that edge then appears twice on a path, once per side, and its two new
  // half-edges must be linked to each other, not to the old slots.
  struct Slit {
    std::uint32_t old_edge, old_twin, seg, fresh;
  };
  std::vector<char> in_cavity_;  // per triangle
  std::vector<Slit> slits_;
};

SegmentInserter::SegmentInserter(HalfEdgeMesh& mesh, const Pslg& pslg) : m_(mesh), pslg_(pslg), P_(pslg.points) {
  v2c_.assign(P_.size(), no_index);
  for (std::uint32_t c = 0; c < 3 * mesh.slot_count(); ++c) {
    if (mesh.tv[c] != mesh.ghost) v2c_[mesh.tv[c]] = c;
  }
  m_.seg.assign(m_.tv.size(), no_index);
  in_cavity_.assign(m_.slot_count(), 0);
}

void SegmentInserter::find_slits(const Path& path) {
  for (const std::uint32_t e : path.ext) {
    if (in_cavity_[e / 3]) slits_.push_back({e, m_.tn[e], m_.seg[e], no_index});
  }
}

void SegmentInserter::close_slits() {
  for (const Slit& a : slits_) {
    const auto twin =
        std::find_if(slits_.begin(), slits_.end(), [&](const Slit& b) { return b.old_edge == a.old_twin; });
    if (twin == slits_.end() || a.fresh == no_index || twin->fresh == no_index) {
      throw InternalError("triangulate: internal error: unpaired edge inside a segment cavity");
    }
    m_.link(a.fresh, twin->fresh);
    m_.seg[a.fresh] = a.seg;
  }
  for (const std::uint32_t t : crossed_) in_cavity_[t] = 0;
}

void SegmentInserter::mark(std::uint32_t h, std::uint32_t s) {
  for (const std::uint32_t e : {h, m_.tn[h]}) {
    if (m_.seg[e] != no_index && m_.seg[e] != s) throw_crossing(pslg_, s, m_.seg[e]);
    m_.seg[e] = s;
  }
}

// Rotates around a to find where segment a->b leaves it. Returns the vertex
// reached along an existing edge (b itself or a vertex on the segment), with
// `corner` = that half-edge a->x; or no_index with `corner` = the corner of a
// in the triangle whose opposite edge the segment crosses.
std::uint32_t SegmentInserter::find_exit(std::uint32_t a, std::uint32_t b, std::uint32_t& corner) const {
  // Fast path, no geometry: most segments are already Delaunay edges.
  const std::uint32_t h = m_.find_half_edge(v2c_[a], b);
  if (h != no_index) {
    corner = h;
    return b;
  }
  std::uint32_t c = v2c_[a];
  const auto& P = P_;
  const Point pa = P[a], pb = P[b];
  for (std::size_t guard = 0; guard <= 3 * std::size_t{m_.slot_count()}; ++guard) {
    const std::uint32_t x = m_.tv[next_half_edge(c)], y = m_.tv[prev_half_edge(c)];
    if (x != m_.ghost && y != m_.ghost) {
      const double ox = orient2d(pa, pb, P[x]);
      if (ox == 0 && same_direction(pa, pb, P[x])) {
        corner = prev_half_edge(c);  // edge i+2 = a->x
        return x;
      }
      const double oy = orient2d(pa, pb, P[y]);
      if (oy == 0 && same_direction(pa, pb, P[y])) {
        corner = next_half_edge(c);  // edge i+1 = y->a
        return y;
      }
      if (ox < 0 && oy > 0) {
        corner = c;
        return no_index;
      }
    }
    // Next triangle counter-clockwise around a: across edge y->a (edge i+1).
    const std::uint32_t twin = m_.tn[next_half_edge(c)];
    c = next_half_edge(twin);
  }
  throw InternalError("triangulate: internal error: no exit around vertex " + std::to_string(a));
}

// Walks from corner t0 (a at corner t0, crossing half-edge h) through the
// triangles the segment crosses, collecting both boundary paths, then
// re-triangulates them. Returns the vertex where this piece ends (b, or a
// vertex lying exactly on the segment).
std::uint32_t SegmentInserter::cross(std::uint32_t a, std::uint32_t b, std::uint32_t t0, std::uint32_t h,
                                     std::uint32_t s) {
  const auto& P = P_;
  upper_.verts = {a, m_.tv[prev_half_edge(t0)]};
  upper_.ext = {m_.tn[next_half_edge(t0)]};
  lower_.verts = {a, m_.tv[next_half_edge(t0)]};
  lower_.ext = {m_.tn[prev_half_edge(t0)]};
  crossed_ = {t0 / 3};
  std::uint32_t end = no_index;
  while (end == no_index) {
    if (m_.seg[h] != no_index) throw_crossing(pslg_, s, m_.seg[h]);
    const std::uint32_t g = m_.tn[h];  // directed y->x in the next triangle
    crossed_.push_back(g / 3);
    const std::uint32_t e = m_.tv[g];
    if (e == m_.ghost) throw InternalError("triangulate: internal error: segment leaves the hull");
    const std::uint32_t xe = next_half_edge(g), ey = prev_half_edge(g);
    const double o = e == b ? 0.0 : orient2d(P[a], P[b], P[e]);
    if (o > 0) {
      upper_.verts.push_back(e);
      upper_.ext.push_back(m_.tn[ey]);
      h = xe;
    } else if (o < 0) {
      lower_.verts.push_back(e);
      lower_.ext.push_back(m_.tn[xe]);
      h = ey;
    } else {
      upper_.verts.push_back(e);
      upper_.ext.push_back(m_.tn[ey]);
      lower_.verts.push_back(e);
      lower_.ext.push_back(m_.tn[xe]);
      end = e;
    }
  }
  // The lower side is re-triangulated as a path from end back to a.
  std::reverse(lower_.verts.begin(), lower_.verts.end());
  std::reverse(lower_.ext.begin(), lower_.ext.end());
  for (const std::uint32_t t : crossed_) {
    if (in_cavity_[t]) throw InternalError("triangulate: internal error: segment walk revisits a triangle");
    in_cavity_[t] = 1;
  }
  slits_.clear();
  find_slits(upper_);
  find_slits(lower_);
  std::size_t next_slot = 0;
  const std::uint32_t top = fill(upper_, next_slot);
  const std::uint32_t bottom = fill(lower_, next_slot);
  close_slits();
  m_.link(top, bottom);
  m_.seg[top] = s;
  m_.seg[bottom] = s;
  return end;
}

// Links a new half-edge to an old one outside the cavity, copying its mark.
void SegmentInserter::attach(std::uint32_t inner, std::uint32_t outer) {
  m_.link(inner, outer);
  m_.seg[inner] = m_.seg[outer];
}

// Delaunay triangulation of the pseudo-polygon bounded by edge u->v and the
// path from u to v (on its left). Reuses crossed_ slots. Returns the
// half-edge u->v of the triangle on it.
std::uint32_t SegmentInserter::fill(const Path& path, std::size_t& next_slot) {
  const auto& P = P_;
  const auto& V = path.verts;
  std::uint32_t top = no_index;
  tasks_.clear();
  tasks_.push_back({0, static_cast<std::uint32_t>(V.size() - 1), no_index});
  while (!tasks_.empty()) {
    const Task task = tasks_.back();
    tasks_.pop_back();
    if (task.j == task.i + 1) {
      const std::uint32_t ext = path.ext[task.i];
      if (in_cavity_[ext / 3]) {
        for (Slit& slit : slits_) {
          if (slit.old_edge == ext) slit.fresh = task.parent;
        }
      } else {
        attach(task.parent, ext);
      }
      continue;
    }
    // The vertex whose circle through u, v holds no other path vertex.
    const Point pu = P[V[task.i]], pv = P[V[task.j]];
    std::uint32_t k = task.i + 1;
    for (std::uint32_t m = task.i + 2; m < task.j; ++m) {
      if (incircle(pu, pv, P[V[k]], P[V[m]]) > 0) k = m;
    }
    const std::uint32_t t = crossed_[next_slot++];
    m_.tv[3 * t] = V[task.i];
    m_.tv[3 * t + 1] = V[task.j];
    m_.tv[3 * t + 2] = V[k];
    for (std::uint32_t i = 0; i < 3; ++i) {
      m_.seg[3 * t + i] = no_index;
      v2c_[V[i == 0 ? task.i : i == 1 ? task.j : k]] = 3 * t + i;
    }
    if (task.parent == no_index) {
      top = 3 * t + 2;
    } else {
      m_.link(3 * t + 2, task.parent);
    }
    tasks_.push_back({k, task.j, 3 * t});
    tasks_.push_back({task.i, k, 3 * t + 1});
  }
  return top;
}

void SegmentInserter::insert(std::uint32_t s) {
  const std::uint32_t b = pslg_.segments[s].b;
  std::uint32_t a = pslg_.segments[s].a;
  for (std::size_t guard = 0; a != b; ++guard) {
    if (guard > P_.size()) throw InternalError("triangulate: internal error: segment walk did not end");
    std::uint32_t corner = 0;
    const std::uint32_t x = find_exit(a, b, corner);
    if (x != no_index) {
      mark(corner, s);
      a = x;
    } else {
      a = cross(a, b, corner, corner, s);
    }
  }
}

}  // namespace

void insert_segments(HalfEdgeMesh& mesh, const Pslg& pslg) {
  SegmentInserter inserter(mesh, pslg);
  for (std::uint32_t s = 0; s < pslg.segments.size(); ++s) inserter.insert(s);
}

}  // namespace madd::detail
