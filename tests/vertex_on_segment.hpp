#pragma once
// A vertex lying exactly inside a segment it does not end (orient2d == 0,
// strictly between the ends) splits that segment, as Triangle does
// (docs/formats.md, "The domain"), whether or not it ends other segments.
// These checks find such vertices by brute force, independently of the
// library's search, and check that a decomposition, its pieces and a mesh keep
// each on its segment: never an isolated interior point.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "madd/predicates.hpp"

namespace madd::test {

struct VertexOnSegment {
  std::uint32_t vertex = 0;
  std::uint32_t segment = 0;  // input segment it lies strictly inside
};

// Every (vertex, segment) pair with the vertex strictly inside the segment.
inline std::vector<VertexOnSegment> vertices_on_segments(const Pslg& p) {
  std::vector<VertexOnSegment> out;
  for (std::uint32_t v = 0; v < p.points.size(); ++v)
    for (std::uint32_t s = 0; s < p.segments.size(); ++s) {
      const Point a = p.points[p.segments[s].a], b = p.points[p.segments[s].b], q = p.points[v];
      if (v == p.segments[s].a || v == p.segments[s].b || orient2d(a, b, q) != 0.0) continue;
      if (std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
          q.y <= std::max(a.y, b.y))
        out.push_back({v, s});
    }
  return out;
}

// The marker a piece of input segment s carries in a decomposition or mesh.
inline int piece_marker(const Pslg& p, std::uint32_t s) {
  const int m = p.segments[s].marker;
  return p.has_segment_markers && m != 0 ? m : 1;
}

// In `d`, each such vertex is no interior point of any subdomain and ends
// exactly two pieces of its segment, both with the segment's marker; on a
// boundary segment it is a ring vertex of the subdomain the pieces bound.
inline void check_kept_on_segments(const Decomposition& d, const Pslg& domain) {
  for (const VertexOnSegment& o : vertices_on_segments(domain)) {
    CAPTURE(o.vertex);
    CAPTURE(o.segment);
    REQUIRE(d.points[o.vertex] == domain.points[o.vertex]);
    for (const Subdomain& s : d.subdomains)
      CHECK(std::find(s.interior_points.begin(), s.interior_points.end(), o.vertex) == s.interior_points.end());
    std::vector<std::uint32_t> pieces;
    for (std::uint32_t g = 0; g < d.segments.size(); ++g)
      if (d.segment_origin[g] == o.segment && (d.segments[g].a == o.vertex || d.segments[g].b == o.vertex))
        pieces.push_back(g);
    REQUIRE(pieces.size() == 2);
    for (const std::uint32_t g : pieces) {
      CHECK(d.segments[g].marker == piece_marker(domain, o.segment));
      bool in_a_ring = false, interior = false;
      for (const Subdomain& s : d.subdomains) {
        for (std::size_t r = 0; r < s.rings.size(); ++r)
          for (std::size_t k = 0; k < s.rings[r].size(); ++k)
            if (s.ring_segments[r][k] == g)
              in_a_ring = in_a_ring || s.rings[r][k] == o.vertex || s.rings[r][(k + 1) % s.rings[r].size()] == o.vertex;
        interior = interior ||
                   std::find(s.interior_segments.begin(), s.interior_segments.end(), g) != s.interior_segments.end();
      }
      CHECK(in_a_ring != interior);  // a boundary piece, in a ring through the vertex; or an interior one
    }
  }
}

// Decomposes `domain` into n subdomains at Phi0 on one thread; the result
// must verify and keep every vertex on its segment.
inline Decomposition checked_on_segments(const Pslg& domain, std::uint32_t n, double separator_angle_deg) {
  CAPTURE(n);
  CAPTURE(separator_angle_deg);
  DecomposeOptions o;
  o.subdomains = n;
  o.separator_angle_deg = separator_angle_deg;
  o.threads = 1;
  const Decomposition d = decompose(domain, o);
  const Verification check = verify_decomposition(d, domain, n);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
  check_kept_on_segments(d, domain);
  return d;
}

// Meshes `domain` into n subdomains (q 30, the area bound 1/50 of the domain's
// area); the mesh must verify, and each vertex on a segment be a mesh vertex
// with the segment's marker, ending two mesh edges along that segment.
inline Mesh meshed_on_segments(const Pslg& domain, std::uint32_t n) {
  CAPTURE(n);
  MeshOptions o;
  o.decomposition.subdomains = n;
  o.decomposition.threads = 1;
  o.size.min_triangle_angle_deg = 30.0;
  o.size.max_triangle_area = domain_area(domain) / 50.0;
  const Mesh m = mesh(domain, o);
  const Verification check = verify_mesh(m, domain, o.size);
  INFO((check.ok() ? std::string() : check.problems.front()));
  CHECK(check.ok());
  for (const VertexOnSegment& on : vertices_on_segments(domain)) {
    CAPTURE(on.vertex);
    REQUIRE(m.points[on.vertex] == domain.points[on.vertex]);
    CHECK(m.point_markers[on.vertex] >= piece_marker(domain, on.segment));
    std::size_t edges = 0;
    for (const MeshSegment& s : m.segments)
      if ((s.a == on.vertex || s.b == on.vertex) && m.decomposition.segment_origin[s.piece] == on.segment) {
        ++edges;
        CHECK(s.marker == piece_marker(domain, on.segment));
      }
    CHECK(edges == 2);
  }
  return m;
}

}  // namespace madd::test
