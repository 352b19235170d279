// verify_triangulation: recomputes every invariant of a Triangulation from
// scratch, sharing no code with the builder, so a builder bug cannot hide.
#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/number_format.hpp"
#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "triangulation/exact_area.hpp"
#include "triangulation/kept_region.hpp"

namespace madd {

namespace {

struct DirectedEdge {
  std::uint32_t from, to, tri, edge;
  std::uint32_t lo() const noexcept { return std::min(from, to); }
  std::uint32_t hi() const noexcept { return std::max(from, to); }
  // By undirected edge, then the direction from lo to hi first: an edge's
  // twin sits next to it, so no search is needed.
  bool operator<(const DirectedEdge& o) const noexcept {
    if (lo() != o.lo()) return lo() < o.lo();
    if (hi() != o.hi()) return hi() < o.hi();
    if (from != o.from) return from < o.from;
    return tri < o.tri;
  }
};

constexpr std::size_t max_reported = 20;

void report(Verification& v, const std::string& problem) {
  if (v.problems.size() < max_reported) v.add(problem);
}

std::string tri_name(std::size_t t) { return "triangle " + std::to_string(t); }

bool check_shapes(const Triangulation& tri, Verification& v) {
  const std::size_t nt = tri.triangles.size();
  if (tri.neighbours.size() != nt || tri.segment_of.size() != nt ||
      (!tri.attributes.empty() && tri.attributes.size() != nt)) {
    v.add("triangles, neighbours, segment_of and attributes differ in size");
    return false;
  }
  bool ok = true;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& c = tri.triangles[t];
    for (int i = 0; i < 3; ++i) {
      if (c[i] >= tri.points.size()) {
        report(v, tri_name(t) + " has an out-of-range vertex");
        ok = false;
      }
      if (tri.neighbours[t][i] != no_index && tri.neighbours[t][i] >= nt) {
        report(v, tri_name(t) + " has an out-of-range neighbour");
        ok = false;
      }
    }
  }
  return ok;
}

void check_orientation(const Triangulation& tri, Verification& v) {
  for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& c = tri.triangles[t];
    if (!(orient2d(tri.points[c[0]], tri.points[c[1]], tri.points[c[2]]) > 0)) {
      report(v, tri_name(t) + " is not strictly counter-clockwise");
    }
  }
}

// Each directed edge appears once; an edge is shared by exactly the two
// triangles that name each other as neighbours, with equal segment_of.
void check_adjacency(const Triangulation& tri, Verification& v) {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * tri.triangles.size());
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& c = tri.triangles[t];
    for (std::uint32_t i = 0; i < 3; ++i) edges.push_back({c[(i + 1) % 3], c[(i + 2) % 3], t, i});
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t first = 0; first < edges.size();) {
    // [first, last): one undirected edge; [first, mid) runs lo -> hi, [mid, last) hi -> lo.
    std::size_t last = first, mid = first;
    while (last < edges.size() && edges[last].lo() == edges[first].lo() && edges[last].hi() == edges[first].hi()) {
      if (edges[last].from < edges[last].to) mid = last + 1;
      ++last;
    }
    if (mid - first > 1 || last - mid > 1) {
      const DirectedEdge& e = mid - first > 1 ? edges[first] : edges[mid];
      report(v, "edge " + std::to_string(e.from) + "-" + std::to_string(e.to) + " is used twice");
    }
    for (std::size_t k = first; k < last; ++k) {
      const DirectedEdge& e = edges[k];
      const bool forward = k < mid;
      const bool has_twin = forward ? mid < last : first < mid;
      const std::uint32_t nb = tri.neighbours[e.tri][e.edge];
      if (!has_twin) {
        if (nb != no_index) report(v, tri_name(e.tri) + " names a neighbour across an unshared edge");
        continue;
      }
      const DirectedEdge& twin = forward ? edges[mid] : edges[first];
      if (nb != twin.tri || tri.neighbours[twin.tri][twin.edge] != e.tri) {
        report(v, tri_name(e.tri) + " and " + tri_name(twin.tri) + " share an edge but are not mutual neighbours");
      } else if (tri.segment_of[e.tri][e.edge] != tri.segment_of[twin.tri][twin.edge]) {
        report(v, tri_name(e.tri) + " and " + tri_name(twin.tri) + " disagree on segment_of");
      }
    }
    first = last;
  }
}

// The same attribute value; a region's attribute may be NaN (the reader takes
// any real), which must still equal itself here.
bool same_attribute(double a, double b) noexcept { return a == b || (std::isnan(a) && std::isnan(b)); }

// A region ends only at segments: across an unconstrained edge the regional
// attribute is the same.
void check_attributes(const Triangulation& tri, Verification& v) {
  if (tri.attributes.empty()) return;
  for (std::size_t t = 0; t < tri.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u != no_index && tri.segment_of[t][i] == no_index && !same_attribute(tri.attributes[u], tri.attributes[t]))
        report(v,
               tri_name(t) + " and " + tri_name(u) + " share an unconstrained edge but not their regional attribute");
    }
}

// Empty circle: across every unconstrained interior edge the opposite vertex
// is not strictly inside the circumcircle.
void check_delaunay(const Triangulation& tri, Verification& v) {
  for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& c = tri.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tri.neighbours[t][i];
      if (u == no_index || tri.segment_of[t][i] != no_index) continue;
      const auto& d = tri.triangles[u];
      const std::uint32_t a = c[(i + 1) % 3], b = c[(i + 2) % 3];
      for (const std::uint32_t w : d) {
        if (w == a || w == b) continue;
        if (incircle(tri.points[c[0]], tri.points[c[1]], tri.points[c[2]], tri.points[w]) > 0) {
          report(v, "edge " + std::to_string(a) + "-" + std::to_string(b) + " of " + tri_name(t) +
                        " is not locally Delaunay");
        }
      }
    }
  }
}

// The triangles cover exactly the domain's area. Compared exactly: both are
// sums of products of input coordinates, which expansion arithmetic adds
// without rounding, so a correct triangulation (its triangles are the domain's
// faces cut along edges between input points) gives equal sums, and any
// missing or extra triangle (strictly counter-clockwise, checked above)
// changes the sum by its own area, however small. A tolerance would have to
// cover the rounding of both floating-point sums: summing fl(cross(b - a,
// c - a)) over the triangles of a needle 1e11 long and 0.02 wide near
// (1e9, 1e9) (docs/hostile.md) is off by 208 in 990159056, relative 2e-7, so
// the former fixed relative 1e-9 rejected a correct triangulation.
void check_area(const Triangulation& tri, const detail::KeptRegion& region, Verification& v) {
  if (!region.twice_area) return;
  const detail::ExactSum triangles = detail::triangles_twice_area_exact(tri);
  const detail::ExactSum& domain = *region.twice_area;
  detail::ExactSum difference = triangles;
  difference.subtract(domain);
  if (difference.is_zero()) return;
  v.add("total area " + detail::number_text(0.5 * triangles.approximate()) + " differs from the domain area " +
        detail::number_text(0.5 * domain.approximate()) + " (by " +
        detail::number_text(0.5 * difference.approximate()) + ", computed exactly)");
}

}  // namespace

namespace detail {
void check_segments(const Triangulation& tri, const Pslg& pslg, const KeptRegion& region, Verification& v);
}  // namespace detail

Verification verify_triangulation(const Triangulation& tri, const Pslg* pslg, const TriangulateOptions& options) {
  Verification v;
  if (!check_shapes(tri, v)) return v;
  check_orientation(tri, v);
  check_adjacency(tri, v);
  check_delaunay(tri, v);
  check_attributes(tri, v);
  if (pslg != nullptr) {
    if (pslg->points != tri.points) v.add("the triangulation's points differ from the PSLG's");
    const detail::KeptRegion region = detail::kept_region(*pslg, options);
    detail::check_segments(tri, *pslg, region, v);
    check_area(tri, region, v);
  }
  return v;
}

}  // namespace madd
