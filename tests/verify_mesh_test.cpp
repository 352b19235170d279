// verify_mesh (src/quality/verify_mesh.cpp) and area_bound_at: valid meshes
// of the bundled domains pass; each kind of damage is found, one test per
// kind; the background-sample grid agrees with a scan, and the mesher's
// size bound is verify_mesh's.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/mesh.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "interior_fixture.hpp"
#include "mesh_fixtures.hpp"
#include "mesh/refine.hpp"
#include "quality/area_bound.hpp"
#include "quality/mesh_angle.hpp"
#include "quality/verify_mesh_bounded.hpp"

namespace {

using madd::Mesh;
using madd::MeshSizeOptions;
using madd::Point;
using madd::Pslg;
using madd::no_index;

Pslg domain_of(const std::string& name) { return madd::read_domain(std::string(MADD_DATA_DIR) + "/" + name); }

madd::Decomposition decomposition_of(const Pslg& domain, std::uint32_t n) {
  madd::DecomposeOptions o;
  o.subdomains = n;
  o.threads = 2;
  return madd::decompose(domain, o);
}

// The nearest sample as area_bound_at defines it, by a scan: the smallest
// (p.x - s.x)^2 + (p.y - s.y)^2, the first of equals; non-finite samples never.
std::uint32_t scan_nearest(std::span<const madd::ValuedPoint> samples, Point p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return no_index;
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t best_index = no_index;
  for (std::uint32_t i = 0; i < samples.size(); ++i) {
    const Point s = samples[i].at;
    if (!std::isfinite(s.x) || !std::isfinite(s.y)) continue;
    const double d = (p.x - s.x) * (p.x - s.x) + (p.y - s.y) * (p.y - s.y);
    if (d < best) best = d, best_index = i;
  }
  return best_index;
}

bool mentions(const madd::Verification& v, const std::string& what) {
  return std::any_of(v.problems.begin(), v.problems.end(),
                     [&](const std::string& p) { return p.find(what) != std::string::npos; });
}

void show(const madd::Verification& v) {
  for (const auto& p : v.problems) MESSAGE(p);
}

// The pipe at N = 8, made once.
struct Fixture {
  Pslg domain = domain_of("pipe.poly");
  Mesh mesh = madd::test::mesh_without_steiner_points(decomposition_of(domain, 8));
};

const Fixture& pipe8() {
  static const Fixture f;
  return f;
}

// Neighbours and subdomain offsets recomputed after a test changed the
// triangles (triangle_subdomain kept sorted).
void rebuild(Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_triangle;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) edge_triangle[{m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3]}] = t;
  m.neighbours.assign(m.triangles.size(), {no_index, no_index, no_index});
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const auto it = edge_triangle.find({m.triangles[t][(i + 2) % 3], m.triangles[t][(i + 1) % 3]});
      if (it != edge_triangle.end()) m.neighbours[t][i] = it->second;
    }
  const std::uint32_t n = m.subdomain_count();
  m.subdomain_first_triangle.assign(n + 1, 0);
  for (const std::uint32_t k : m.triangle_subdomain) ++m.subdomain_first_triangle[k + 1];
  for (std::uint32_t k = 0; k < n; ++k) m.subdomain_first_triangle[k + 1] += m.subdomain_first_triangle[k];
}

// An edge shared by two triangles of one subdomain that is no mesh segment:
// triangle t has it as edge i (v -> w, apex x), triangle u as edge j (w -> v, apex y).
struct InnerEdge {
  std::uint32_t t, i, u, j;
};

std::vector<InnerEdge> inner_edges(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> segment;
  for (const auto& s : m.segments) segment[{std::min(s.a, s.b), std::max(s.a, s.b)}] = 1;
  std::vector<InnerEdge> out;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t u = m.neighbours[t][i];
      if (u == no_index || u < t || m.triangle_subdomain[u] != m.triangle_subdomain[t]) continue;
      const std::uint32_t v = m.triangles[t][(i + 1) % 3], w = m.triangles[t][(i + 2) % 3];
      if (segment.count({std::min(v, w), std::max(v, w)}) != 0) continue;
      std::uint32_t j = 0;
      while (m.triangles[u][j] == v || m.triangles[u][j] == w) ++j;
      out.push_back({t, i, u, j});
    }
  return out;
}

double twice_area(const Mesh& m, std::uint32_t t) {
  const auto& c = m.triangles[t];
  return std::abs(madd::cross(m.points[c[1]] - m.points[c[0]], m.points[c[2]] - m.points[c[0]]));
}

// The smallest angle of every triangle, by brute force over all three corners.
std::vector<double> smallest_angles(const Mesh& m) {
  std::vector<double> out;
  for (const auto& c : m.triangles) {
    double least = 180.0;
    for (int k = 0; k < 3; ++k)
      least = std::min(
          least, madd::degrees(madd::angle_at(m.points[c[k]], m.points[c[(k + 1) % 3]], m.points[c[(k + 2) % 3]])));
    out.push_back(least);
  }
  return out;
}

// A k x k square of unit cells, each cut into two triangles, in `strips`
// vertical strips (the subdomains) of k / strips columns each; built
// directly, without the fixture's map, so that it can be large. Every point
// is exactly on its segment. Square cells are cocircular (every in-circle
// test is the exact, slow case); `sheared` moves lattice point (i, j) to
// (i - j / 2, j), cells become parallelograms cut along their short
// diagonal, strictly Delaunay, with smallest angles of 53.13 degrees.
struct GridMesh {
  Pslg domain;
  Mesh mesh;
};

GridMesh grid_mesh(std::uint32_t k, std::uint32_t strips, bool sheared = false) {
  GridMesh g;
  const double K = k;
  g.domain.points = {{0, 0}, {K, 0}, {K, K}, {0, K}};
  g.domain.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  g.domain.first_index = 0;
  madd::Decomposition& d = g.mesh.decomposition;
  d.points = g.domain.points;
  std::vector<std::uint32_t> bottom{0}, top{3};  // decomposition point at strip boundary s, on y = 0 and y = k
  for (std::uint32_t s = 1; s < strips; ++s) {
    const double x = static_cast<double>(s * (k / strips));
    bottom.push_back(static_cast<std::uint32_t>(d.points.size()));
    d.points.push_back({x, 0});
    top.push_back(static_cast<std::uint32_t>(d.points.size()));
    d.points.push_back({x, K});
  }
  bottom.push_back(1);
  top.push_back(2);
  // Pieces: bottom (origin 0), right (1), top (2, right to left), left (3), separators.
  const auto add_segment = [&](std::uint32_t a, std::uint32_t b, std::uint32_t origin) {
    d.segments.push_back({a, b, origin == no_index ? 0 : 1});
    d.segment_origin.push_back(origin);
    return static_cast<std::uint32_t>(d.segments.size() - 1);
  };
  std::vector<std::uint32_t> bottom_piece, top_piece, separator(strips + 1, no_index);
  for (std::uint32_t s = 0; s < strips; ++s) bottom_piece.push_back(add_segment(bottom[s], bottom[s + 1], 0));
  const std::uint32_t right = add_segment(1, 2, 1);
  for (std::uint32_t s = 0; s < strips; ++s) top_piece.push_back(add_segment(top[s + 1], top[s], 2));
  const std::uint32_t left = add_segment(3, 0, 3);
  for (std::uint32_t s = 1; s < strips; ++s) separator[s] = add_segment(bottom[s], top[s], no_index);
  for (std::uint32_t s = 0; s < strips; ++s) {
    madd::Subdomain sub;
    sub.rings = {{bottom[s], bottom[s + 1], top[s + 1], top[s]}};
    sub.ring_segments = {
        {bottom_piece[s], s + 1 == strips ? right : separator[s + 1], top_piece[s], s == 0 ? left : separator[s]}};
    sub.area = K * static_cast<double>(k / strips);
    sub.interior_point = {static_cast<double>(s * (k / strips)) + 0.5, 0.5};
    d.subdomains.push_back(sub);
  }
  // Mesh points: the decomposition's, then the other grid points.
  Mesh& m = g.mesh;
  m.points = d.points;
  std::vector<std::uint32_t> id(std::size_t{k + 1} * (k + 1), no_index);
  const auto at = [&](std::uint32_t i, std::uint32_t j) -> std::uint32_t& { return id[std::size_t{j} * (k + 1) + i]; };
  for (std::uint32_t p = 0; p < d.points.size(); ++p)
    at(static_cast<std::uint32_t>(d.points[p].x), static_cast<std::uint32_t>(d.points[p].y)) = p;
  for (std::uint32_t j = 0; j <= k; ++j)
    for (std::uint32_t i = 0; i <= k; ++i)
      if (at(i, j) == no_index) {
        at(i, j) = static_cast<std::uint32_t>(m.points.size());
        m.points.push_back({static_cast<double>(i), static_cast<double>(j)});
      }
  m.point_markers.assign(m.points.size(), 0);
  for (std::uint32_t i = 0; i <= k; ++i) m.point_markers[at(i, 0)] = m.point_markers[at(i, k)] = 1;
  for (std::uint32_t j = 0; j <= k; ++j) m.point_markers[at(0, j)] = m.point_markers[at(k, j)] = 1;
  m.min_triangle_angle_deg = 45.0;
  m.subdomain_first_triangle.push_back(0);
  const std::uint32_t w = k / strips;
  for (std::uint32_t s = 0; s < strips; ++s) {
    const std::uint32_t i1 = s + 1 == strips ? k : (s + 1) * w;
    for (std::uint32_t j = 0; j < k; ++j)
      for (std::uint32_t i = s * w; i < i1; ++i) {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        m.triangle_subdomain.push_back(s);
        m.triangle_subdomain.push_back(s);
      }
    m.subdomain_first_triangle.push_back(static_cast<std::uint32_t>(m.triangles.size()));
  }
  // Neighbours from the grid's structure: lower triangle L = (i,j) (i+1,j) (i+1,j+1),
  // upper U = (i,j) (i+1,j+1) (i,j+1).
  std::vector<std::uint32_t> first_of_cell(std::size_t{k} * k);
  for (std::uint32_t t = 0; t < m.triangles.size(); t += 2) {
    const Point p = m.points[m.triangles[t][0]];
    first_of_cell[static_cast<std::size_t>(p.y) * k + static_cast<std::size_t>(p.x)] = t;
  }
  const auto cell = [&](std::int64_t i, std::int64_t j) -> std::uint32_t {
    if (i < 0 || j < 0 || i >= k || j >= k) return no_index;
    return first_of_cell[static_cast<std::size_t>(j) * k + static_cast<std::size_t>(i)];
  };
  m.neighbours.resize(m.triangles.size());
  for (std::uint32_t j = 0; j < k; ++j)
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t L = cell(i, j), U = L + 1;
      const std::uint32_t below = cell(i, std::int64_t{j} - 1), beside = cell(i + 1, j);
      const std::uint32_t above = cell(i, j + 1), before = cell(std::int64_t{i} - 1, j);
      m.neighbours[L] = {beside == no_index ? no_index : beside + 1, U, below == no_index ? no_index : below + 1};
      m.neighbours[U] = {above == no_index ? no_index : above, before == no_index ? no_index : before, L};
    }
  // Mesh segments, by piece, then along it.
  for (std::uint32_t p = 0; p < d.segments.size(); ++p) {
    const Point a = d.points[d.segments[p].a], b = d.points[d.segments[p].b];
    const std::uint32_t steps = static_cast<std::uint32_t>(std::abs(b.x - a.x) + std::abs(b.y - a.y));
    const int dx = b.x > a.x ? 1 : b.x < a.x ? -1 : 0, dy = b.y > a.y ? 1 : b.y < a.y ? -1 : 0;
    for (std::uint32_t q = 0; q < steps; ++q) {
      const auto x = static_cast<std::uint32_t>(a.x + dx * static_cast<double>(q));
      const auto y = static_cast<std::uint32_t>(a.y + dy * static_cast<double>(q));
      m.segments.push_back({at(x, y), at(static_cast<std::uint32_t>(x + dx), static_cast<std::uint32_t>(y + dy)),
                            d.segments[p].marker, p});
    }
  }
  if (sheared) {
    m.min_triangle_angle_deg = 53.0;
    for (auto* points : {&m.points, &d.points, &g.domain.points})
      for (Point& p : *points) p.x -= 0.5 * p.y;
  }
  return g;
}

// verify_mesh on one thread (the public function), and on 2, 3 and 7: the
// parallel checks split the vertices and triangles in parts, one per
// thread or more, and must find the same problems, in the same order.
madd::Verification verified(const Mesh& m, const Pslg& domain, const MeshSizeOptions& size) {
  const madd::Verification one = madd::verify_mesh(m, domain, size);
  const madd::detail::AreaBound bound(size, &domain);
  for (const unsigned threads : {2u, 3u, 7u}) {
    CAPTURE(threads);
    CHECK(madd::detail::verify_mesh(m, domain, bound, threads).problems == one.problems);
  }
  return one;
}

}  // namespace

TEST_SUITE("verify_mesh") {

TEST_CASE("verify_mesh: valid meshes of the bundled domains pass") {
  const std::vector<std::pair<std::string, std::vector<std::uint32_t>>> cases = {
      {"pipe.poly", {1, 2, 8, 64}}, {"key.poly", {1, 5, 32}},     {"l_shape.poly", {1, 3, 16}},
      {"spiral.poly", {2, 12}},     {"archipelago.poly", {1, 7}}, {"thin_annulus.poly", {4}}};
  for (const auto& c : cases) {
    const std::string& name = c.first;  // not a structured binding: clang 14 cannot CAPTURE one
    const std::vector<std::uint32_t>& counts = c.second;
    const Pslg domain = domain_of(name);
    for (const std::uint32_t n : counts) {
      CAPTURE(name);
      CAPTURE(n);
      const Mesh m = madd::test::mesh_without_steiner_points(decomposition_of(domain, n));
      const madd::Verification v = verified(m, domain, {});
      show(v);
      CHECK(v.ok());
    }
  }
}

TEST_CASE("verify_mesh: a synthetic grid mesh passes at its exact bounds") {
  const GridMesh g = grid_mesh(40, 4);
  MeshSizeOptions size;
  size.max_triangle_area = 0.5;  // every triangle's area exactly
  const madd::Verification v =
      verified(g.mesh, g.domain, size);  // min_triangle_angle_deg 45: every smallest angle exactly
  show(v);
  CHECK(v.ok());
  size.max_triangle_area = 0.4999;
  CHECK(mentions(verified(g.mesh, g.domain, size), "above the size bound"));
  GridMesh sheared = grid_mesh(40, 4, true);
  size.max_triangle_area = 0.5;
  CHECK(verified(sheared.mesh, sheared.domain, size).ok());
  sheared.mesh.min_triangle_angle_deg = 53.2;  // above 53.13: every triangle short
  CHECK(mentions(verified(sheared.mesh, sheared.domain, size), "3200 triangles have a smallest angle below"));
}

TEST_CASE("verify_mesh: a flipped triangle") {
  Mesh m = pipe8().mesh;
  std::swap(m.triangles[10][1], m.triangles[10][2]);
  std::swap(m.neighbours[10][1], m.neighbours[10][2]);
  const madd::Verification v = verified(m, pipe8().domain, {});
  CHECK(mentions(v, "triangle 10 (subdomain 0)"));
  CHECK(mentions(v, "is clockwise"));
  CHECK(mentions(v, "in the same direction"));
}

TEST_CASE("verify_mesh: a degenerate triangle") {
  Mesh m = pipe8().mesh;
  m.triangles[3][2] = m.triangles[3][1];
  CHECK(mentions(verified(m, pipe8().domain, {}), "is degenerate"));
}

TEST_CASE("verify_mesh: a broken neighbour link") {
  const Mesh& base = pipe8().mesh;
  const InnerEdge e = inner_edges(base).front();
  SUBCASE("pointing elsewhere") {
    Mesh m = base;
    m.neighbours[e.t][e.i] = e.u == 0 ? 1 : 0;
    CHECK(mentions(verified(m, pipe8().domain, {}), "as their neighbours across it"));
  }
  SUBCASE("no_index across a shared edge") {
    Mesh m = base;
    m.neighbours[e.t][e.i] = no_index;
    CHECK(mentions(verified(m, pipe8().domain, {}), "as their neighbours across it"));
  }
  SUBCASE("a neighbour across a boundary edge") {
    Mesh m = base;
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i)
        if (m.neighbours[t][i] == no_index) {
          m.neighbours[t][i] = t == 0 ? 1 : 0;
          const madd::Verification v = verified(m, pipe8().domain, {});
          CHECK(mentions(v, "which that triangle does not have the other way"));
          return;
        }
    FAIL("no boundary edge");
  }
}

TEST_CASE("verify_mesh: a dropped triangle leaves a gap") {
  Mesh m = pipe8().mesh;
  const auto last = static_cast<std::uint32_t>(m.triangles.size() - 1);
  m.triangles.pop_back();
  m.neighbours.pop_back();
  m.triangle_subdomain.pop_back();
  --m.subdomain_first_triangle.back();
  for (auto& n : m.neighbours)
    for (auto& u : n)
      if (u == last) u = no_index;
  const madd::Verification v = verified(m, pipe8().domain, {});
  CHECK(mentions(v, "a gap or an overlap"));
  CHECK(mentions(v, "a hole or a tear"));
}

TEST_CASE("verify_mesh: a doubled triangle is an overlap") {
  Mesh m = pipe8().mesh;
  // A second copy of triangle 0 in the last subdomain, with no neighbours:
  // its edges are free and no segment, and the area counts it twice.
  m.triangles.push_back(m.triangles[0]);
  m.neighbours.push_back({no_index, no_index, no_index});
  m.triangle_subdomain.push_back(m.subdomain_count() - 1);
  ++m.subdomain_first_triangle.back();
  const madd::Verification v = verified(m, pipe8().domain, {});
  CHECK(mentions(v, "a hole or a tear"));
  CHECK(mentions(v, "a gap or an overlap"));
}

TEST_CASE("verify_mesh: a doubled triangle linked in place of the first") {
  // The copy takes the original's place in its neighbours' links: the links
  // are mutual, every free edge a segment, and only the original is left
  // unlinked (its edges free) and the area counts twice.
  Mesh m = pipe8().mesh;
  const auto copy = static_cast<std::uint32_t>(m.triangles.size());
  m.triangles.push_back(m.triangles[0]);
  m.neighbours.push_back(m.neighbours[0]);
  m.triangle_subdomain.push_back(m.subdomain_count() - 1);
  ++m.subdomain_first_triangle.back();
  for (auto& n : m.neighbours)
    for (auto& u : n)
      if (u == 0) u = copy;
  m.neighbours[0] = {no_index, no_index, no_index};
  const madd::Verification v = verified(m, pipe8().domain, {});
  CHECK(mentions(v, "a gap or an overlap"));
  CHECK_FALSE(v.ok());
}

TEST_CASE("verify_mesh: boundary vertices on their segments up to the derived bound") {
  // A vertex a separator put inside a sloping input segment (the pipe's
  // separators end at its own vertices).
  Fixture f{domain_of("key.poly"), {}};
  f.mesh = madd::test::mesh_without_steiner_points(decomposition_of(f.domain, 16));
  std::uint32_t p = no_index, piece = no_index;
  for (const auto& s : f.mesh.segments)
    for (const std::uint32_t end : {s.a, s.b})
      if (p == no_index && s.marker != 0 && end >= f.domain.points.size()) {
        const Point a = f.mesh.points[s.a], b = f.mesh.points[s.b];
        if (a.x == b.x || a.y == b.y) continue;
        p = end;
        piece = s.piece;
      }
  REQUIRE(p != no_index);
  const madd::Segment& input = f.domain.segments[f.mesh.decomposition.segment_origin[piece]];
  const Point a = f.domain.points[input.a], b = f.domain.points[input.b];
  const Point w = b - a;
  const Point normal = (1.0 / madd::length(w)) * Point{-w.y, w.x};
  const auto moved = [&](Point to) {
    Mesh m = f.mesh;
    m.points[p] = m.decomposition.points[p] = to;
    return verified(m, f.domain, {});
  };
  SUBCASE("an ulp off passes") {
    const Point q = f.mesh.points[p];
    const madd::Verification v = moved({std::nextafter(q.x, q.x + 1.0), std::nextafter(q.y, q.y - 1.0)});
    show(v);
    CHECK(v.ok());
  }
  SUBCASE("1e-7 of the segment's length off fails") {
    const madd::Verification v = moved(f.mesh.points[p] + (1e-7 * madd::length(w)) * normal);
    CHECK(mentions(v, "boundary vertex " + std::to_string(p)));
    CHECK(mentions(v, "leaves input segment"));
  }
}

TEST_CASE("verify_mesh: a hanging vertex") {
  const Fixture& f = pipe8();
  // An inner edge whose midpoint is exactly on it (else the split would not be a T-junction).
  for (const InnerEdge& e : inner_edges(f.mesh)) {
    Mesh m = f.mesh;
    const std::uint32_t v = m.triangles[e.u][(e.j + 1) % 3], w = m.triangles[e.u][(e.j + 2) % 3],
                        y = m.triangles[e.u][e.j];
    const Point mid = madd::midpoint(m.points[v], m.points[w]);
    if (madd::orient2d(m.points[v], m.points[w], mid) != 0.0 || mid == m.points[v] || mid == m.points[w]) continue;
    // Split triangle u (w -> v... its edge v -> w, apex y) at mid; triangle t keeps the whole edge.
    const auto mid_id = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back(mid);
    m.point_markers.push_back(0);
    m.triangles[e.u] = {y, v, mid_id};
    m.triangles.insert(m.triangles.begin() + e.u + 1, {y, mid_id, w});
    m.triangle_subdomain.insert(m.triangle_subdomain.begin() + e.u + 1, m.triangle_subdomain[e.u]);
    rebuild(m);
    const madd::Verification v_ = verified(m, f.domain, {});
    CHECK(mentions(v_, "vertex " + std::to_string(mid_id)));
    CHECK(mentions(v_, "(a hanging vertex)"));
    CHECK(mentions(v_, "a hole or a tear"));
    CHECK_FALSE(mentions(v_, "a gap or an overlap"));  // the area is still exact
    return;
  }
  FAIL("no inner edge with an exact midpoint");
}

TEST_CASE("verify_mesh: a flipped edge is found non-Delaunay exactly when it is") {
  // Brute force on a small mesh: every inner edge whose quadrilateral is
  // convex, flipped; the flipped mesh passes exactly when the four points
  // are cocircular (the fixture is constrained Delaunay).
  const Pslg domain = domain_of("key.poly");
  const Mesh base = madd::test::mesh_without_steiner_points(decomposition_of(domain, 4));
  int flipped = 0, cocircular = 0;
  for (const InnerEdge& e : inner_edges(base)) {
    const auto& T = base.triangles;
    const std::uint32_t v = T[e.t][(e.i + 1) % 3], w = T[e.t][(e.i + 2) % 3], x = T[e.t][e.i], y = T[e.u][e.j];
    const auto& P = base.points;
    if (!(madd::orient2d(P[x], P[v], P[y]) > 0.0 && madd::orient2d(P[y], P[w], P[x]) > 0.0)) continue;  // not convex
    Mesh m = base;
    m.triangles[e.t] = {x, v, y};
    m.triangles[e.u] = {y, w, x};
    rebuild(m);
    const madd::Verification check = verified(m, domain, {});
    const bool on_circle = madd::incircle(P[v], P[w], P[x], P[y]) == 0.0;
    CAPTURE(v);
    CAPTURE(w);
    CHECK(check.ok() == on_circle);
    if (!on_circle) CHECK(mentions(check, "is not locally Delaunay"));
    ++flipped;
    cocircular += on_circle ? 1 : 0;
  }
  CHECK(flipped > 10);
  MESSAGE(flipped << " flips, " << cocircular << " cocircular");
}

TEST_CASE("verify_mesh: separators") {
  const Fixture& f = pipe8();
  std::uint32_t sep = no_index;
  for (std::uint32_t s = 0; s < f.mesh.segments.size() && sep == no_index; ++s)
    if (f.mesh.segments[s].marker == 0) sep = s;
  REQUIRE(sep != no_index);
  SUBCASE("an edge between subdomains that is no separator segment") {
    Mesh m = f.mesh;
    m.segments.erase(m.segments.begin() + sep);
    const madd::Verification v = verified(m, f.domain, {});
    CHECK(mentions(v, "no separator segment"));
    CHECK(mentions(v, "separator " + std::to_string(f.mesh.segments[sep].piece) + " has no mesh segments"));
  }
  SUBCASE("a separator segment with a boundary marker") {
    Mesh m = f.mesh;
    m.segments[sep].marker = 1;
    CHECK(mentions(verified(m, f.domain, {}), "has marker 1, expected 0"));
  }
  SUBCASE("a triangle moved to another subdomain") {
    Mesh m = f.mesh;
    // The first triangle of subdomain 1 claims subdomain 0: the ranges break.
    m.triangle_subdomain[m.subdomain_first_triangle[1]] = 0;
    CHECK(mentions(verified(m, f.domain, {}), "but triangle_subdomain says 0"));
  }
}

TEST_CASE("verify_mesh: inconsistent subdomain ranges") {
  const Fixture& f = pipe8();
  SUBCASE("shifted") {
    Mesh m = f.mesh;
    ++m.subdomain_first_triangle[1];
    CHECK(mentions(verified(m, f.domain, {}), "triangle_subdomain says"));
  }
  SUBCASE("decreasing") {
    Mesh m = f.mesh;
    m.subdomain_first_triangle[2] = m.subdomain_first_triangle[1] - 1;
    CHECK(mentions(verified(m, f.domain, {}), "decreases at subdomain 1"));
  }
  SUBCASE("one offset short") {
    Mesh m = f.mesh;
    m.subdomain_first_triangle.pop_back();
    CHECK(mentions(verified(m, f.domain, {}), "offsets for 8 subdomains"));
  }
  SUBCASE("not ending at the triangle count") {
    Mesh m = f.mesh;
    --m.subdomain_first_triangle.back();
    CHECK(mentions(verified(m, f.domain, {}), "instead of 0 to the triangle count"));
  }
}

TEST_CASE("verify_mesh: malformed meshes are reported, never thrown") {
  const Fixture& f = pipe8();
  std::vector<Mesh> bad(7, f.mesh);
  bad[0].triangles[5][1] = static_cast<std::uint32_t>(f.mesh.points.size());
  bad[1].neighbours.pop_back();
  bad[2].neighbours[4][0] = static_cast<std::uint32_t>(f.mesh.triangles.size()) + 7;
  bad[3].point_markers.clear();
  bad[4].segments[0].piece = 1u << 30;
  bad[5].points[0].x = std::numeric_limits<double>::quiet_NaN();
  bad[6].decomposition.points.pop_back();
  for (const Mesh& m : bad) {
    madd::Verification v;
    CHECK_NOTHROW(v = verified(m, f.domain, {}));
    CHECK_FALSE(v.ok());
  }
  Mesh empty;
  CHECK_NOTHROW((void)verified(empty, f.domain, {}));
  CHECK_FALSE(verified(empty, f.domain, {}).ok());
}

TEST_CASE("verify_mesh: point markers by Triangle's rule") {
  GridMesh g = grid_mesh(6, 2);
  CHECK(verified(g.mesh, g.domain, {}).ok());
  const auto inner = std::find(g.mesh.point_markers.begin(), g.mesh.point_markers.end(), 0);
  REQUIRE(inner != g.mesh.point_markers.end());
  *inner = 3;
  CHECK(mentions(verified(g.mesh, g.domain, {}), "has marker 3, expected 0 (on no boundary segment)"));
  g.mesh.point_markers[0] = 2;
  CHECK(mentions(verified(g.mesh, g.domain, {}), "has marker 2, expected 1 (the largest"));
}

TEST_CASE("verify_mesh: the size bound") {
  const Fixture& f = pipe8();
  double largest = 0.0;
  for (std::uint32_t t = 0; t < f.mesh.triangles.size(); ++t) largest = std::max(largest, 0.5 * twice_area(f.mesh, t));
  MeshSizeOptions size;
  size.max_triangle_area = largest;
  CHECK(verified(f.mesh, f.domain, size).ok());
  size.max_triangle_area = largest * (1.0 - 1e-9);
  CHECK(mentions(verified(f.mesh, f.domain, size), "above the size bound"));
  // The same bound from the function, and from a background sample.
  MeshSizeOptions by_function;
  by_function.triangle_area_function = [&](double, double) { return largest * 0.9; };
  CHECK(mentions(verified(f.mesh, f.domain, by_function), "above the size bound"));
  MeshSizeOptions by_samples;
  by_samples.triangle_area_samples = {{{0.0, 0.0}, largest * 0.9}};
  CHECK(mentions(verified(f.mesh, f.domain, by_samples), "above the size bound"));
  by_samples.triangle_area_samples[0].value = largest;
  CHECK(verified(f.mesh, f.domain, by_samples).ok());
}

// Under a graded field the size check passes most triangles from a
// neighbour's query (the field's slope bounds it); it must still flag
// exactly the triangles a query at every centroid flags.
TEST_CASE(
    "verify_mesh: under a graded field the size check flags exactly the triangles above the bound at their centroid") {
  const Pslg domain = domain_of("archipelago.poly");
  madd::MeshOptions options;
  options.decomposition.subdomains = 6;
  options.size.min_edge_length = 0.06;
  options.size.max_edge_length = 0.5;
  options.size.distance_rate = 0.3;
  options.size.size_gradation = 0.3;
  const madd::Mesh graded = madd::mesh(domain, options);
  // A stricter field of the same kind: some triangles are now too large.
  MeshSizeOptions strict = options.size;
  strict.distance_rate = 0.2;
  const madd::detail::AreaBound bound(strict, &domain);
  REQUIRE(bound.edge_slope() > 0.0);
  std::size_t above = 0;
  for (const auto& t : graded.triangles) {
    const madd::Point a = graded.points[t[0]], b = graded.points[t[1]], c = graded.points[t[2]];
    const madd::Point ab = b - a, ac = c - a, bc = c - b;
    const double twice = std::abs(madd::cross(ab, ac));
    const double longest2 = std::max({madd::dot(ab, ab), madd::dot(ac, ac), madd::dot(bc, bc)});
    const double at = bound.area_at(madd::triangle_centroid(a, b, c));
    above += twice > 2.0 * at * (1.0 + 1e-12) + 32.0 * 0x1p-53 * longest2 ? 1 : 0;
  }
  REQUIRE(above > 50);
  REQUIRE(above < graded.triangles.size() / 2);
  for (const unsigned threads : {1u, 3u}) {
    CAPTURE(threads);
    const madd::Verification v = madd::detail::verify_mesh(graded, domain, bound, threads);
    std::size_t flagged = 0;
    for (const std::string& p : v.problems) {
      if (p.find("above the size bound") != std::string::npos) ++flagged;
      if (p.rfind("... and ", 0) == 0) flagged += std::stoul(p.substr(8));
    }
    CHECK(flagged == above);
  }
}

// The per-triangle checks run on threads (detail::verify_mesh's `threads`):
// the report is the same, problem for problem, for any count.
TEST_CASE("verify_mesh: the size and angle checks report the same on 1, 2 and 3 threads") {
  const Pslg domain = domain_of("pipe.poly");
  madd::MeshOptions options;
  options.decomposition.subdomains = 8;
  options.size.max_triangle_area = 0.02;
  madd::Mesh strict = madd::mesh(domain, options);
  REQUIRE(strict.triangles.size() > 8 * 2048);  // many chunks of the checks' work
  MeshSizeOptions size;
  size.triangle_area_function = [](double x, double) { return 0.02 * (0.6 + 0.05 * x); };  // some too large
  const madd::detail::AreaBound bound(size, &domain);
  strict.min_triangle_angle_deg = 40.0;  // more below than the shortfall counts
  const MeshSizeOptions unbounded;
  const madd::detail::AreaBound none(unbounded, &domain);  // keeps a reference to its options
  const madd::Verification one = madd::detail::verify_mesh(strict, domain, bound, 1);
  const madd::Verification angles = madd::detail::verify_mesh(strict, domain, none, 1);
  CHECK(mentions(one, "above the size bound"));
  // The count, against every triangle measured (the check skips the atan2
  // of triangles well above the bound).
  std::size_t below = 0;
  for (const auto& t : strict.triangles)
    below += madd::detail::smallest_angle_deg(strict.points[t[0]], strict.points[t[1]], strict.points[t[2]]) <
                     40.0 - madd::detail::mesh_angle_slack_deg
                 ? 1
                 : 0;
  REQUIRE(below > 100);
  CHECK(mentions(angles, std::to_string(below) + " triangles have a smallest angle below"));
  for (const unsigned threads : {2u, 3u}) {
    CHECK(madd::detail::verify_mesh(strict, domain, bound, threads).problems == one.problems);
    CHECK(madd::detail::verify_mesh(strict, domain, none, threads).problems == angles.problems);
  }
}

TEST_CASE("verify_mesh: the angle bound against the shortfall count") {
  Mesh m = pipe8().mesh;
  const std::vector<double> angles = smallest_angles(m);
  m.min_triangle_angle_deg = 25.0;
  const auto below =
      static_cast<std::size_t>(std::count_if(angles.begin(), angles.end(), [](double a) { return a < 25.0 - 1e-9; }));
  REQUIRE(below > 0);
  const madd::Verification v = verified(m, pipe8().domain, {});
  CHECK(mentions(v, std::to_string(below) +
                        " triangles have a smallest angle below the bound 25 deg, but the shortfall counts 0"));
  const auto worst = std::min_element(angles.begin(), angles.end()) - angles.begin();
  CHECK(mentions(v, "of triangle " + std::to_string(worst) + " "));
  m.shortfall.input_angle = below - 1;
  m.shortfall.limit = 1;
  CHECK(verified(m, pipe8().domain, {}).ok());
  m.shortfall.limit = 2;
  CHECK(mentions(verified(m, pipe8().domain, {}), "but the shortfall counts " + std::to_string(below + 1)));
  // No bound (0) and a claimed shortfall: a mismatch too.
  m.min_triangle_angle_deg = 0.0;
  CHECK(mentions(verified(m, pipe8().domain, {}), "0 triangles have a smallest angle below"));
}

TEST_CASE("area_bound_at: the smallest of the three bounds") {
  MeshSizeOptions size;
  CHECK(madd::area_bound_at(size, {0, 0}) == std::numeric_limits<double>::infinity());
  size.max_triangle_area = 2.0;
  CHECK(madd::area_bound_at(size, {0, 0}) == 2.0);
  size.triangle_area_function = [](double x, double) { return x; };
  CHECK(madd::area_bound_at(size, {1.5, 0}) == 1.5);
  CHECK(madd::area_bound_at(size, {3.0, 0}) == 2.0);
  CHECK(madd::area_bound_at(size, {-1.0, 0}) == 2.0);  // <= 0: ignored
  CHECK(madd::area_bound_at(size, {0.0, 0}) == 2.0);
  size.triangle_area_function = [](double, double) { return std::numeric_limits<double>::quiet_NaN(); };
  CHECK(madd::area_bound_at(size, {1.0, 0}) == 2.0);  // NaN: ignored
  size.triangle_area_function = nullptr;
  size.triangle_area_samples = {{{0, 0}, 5.0}, {{10, 0}, 0.5}};
  CHECK(madd::area_bound_at(size, {1, 0}) == 2.0);
  CHECK(madd::area_bound_at(size, {9, 0}) == 0.5);
  size.max_triangle_area = 0.0;
  CHECK(madd::area_bound_at(size, {1, 0}) == 5.0);
  // Ties: the lowest index.
  CHECK(madd::area_bound_at(size, {5, 3}) == 5.0);
  size.triangle_area_samples = {{{10, 0}, 0.5}, {{0, 0}, 5.0}};
  CHECK(madd::area_bound_at(size, {5, 3}) == 0.5);
  // The nearest sample decides even when a farther one is smaller.
  size.triangle_area_function = [](double, double) { return 0.25; };
  CHECK(madd::area_bound_at(size, {1, 0}) == 0.25);
}

TEST_CASE("area_bound_at: the sample grid agrees with a scan") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Random samples, a lattice (many exact ties), a thin strip, duplicates, one sample.
  std::vector<std::vector<madd::ValuedPoint>> sets(5);
  for (int k = 0; k < 5000; ++k) sets[0].push_back({{unit(rng) * 100.0, unit(rng) * 30.0}, unit(rng)});
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) sets[1].push_back({{i * 0.5, j * 0.5}, static_cast<double>(i * 40 + j + 1)});
  for (int k = 0; k < 2000; ++k) sets[2].push_back({{unit(rng) * 1e6, 1e9 + unit(rng) * 1e-3}, unit(rng)});
  for (int k = 0; k < 300; ++k)
    sets[3].push_back({{std::floor(unit(rng) * 5.0), std::floor(unit(rng) * 5.0)}, k + 1.0});
  sets[4].push_back({{3, 4}, 1.0});
  sets[0].push_back({{std::numeric_limits<double>::infinity(), 0.0}, 0.1});  // never nearest
  for (const auto& samples : sets) {
    const madd::detail::NearestSample grid(samples);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& s : samples)
      if (std::isfinite(s.at.x)) {
        x0 = std::min(x0, s.at.x), x1 = std::max(x1, s.at.x), y0 = std::min(y0, s.at.y), y1 = std::max(y1, s.at.y);
      }
    for (int q = 0; q < 3000; ++q) {
      // Queries inside, on lattice points and midpoints, and far outside.
      Point p{x0 + (x1 - x0 + 1.0) * (3.0 * unit(rng) - 1.0), y0 + (y1 - y0 + 1.0) * (3.0 * unit(rng) - 1.0)};
      if (q % 3 == 0) p = {std::floor(p.x * 4.0) / 4.0, std::floor(p.y * 4.0) / 4.0};
      if (q == 1) p = {-1e30, 1e30};
      const std::uint32_t want = scan_nearest(samples, p);
      CAPTURE(p.x);
      CAPTURE(p.y);
      REQUIRE(grid.nearest(p) == want);
    }
  }
  MeshSizeOptions size;
  size.triangle_area_samples = sets[1];
  const madd::detail::AreaBound bound(size);
  for (int q = 0; q < 1000; ++q) {
    const Point p{unit(rng) * 20.0 - 0.5, unit(rng) * 20.0 - 0.5};
    CHECK(bound.area_at(p) == madd::area_bound_at(size, p));
  }
  CHECK(madd::detail::NearestSample(std::span<const madd::ValuedPoint>()).nearest({0, 0}) == no_index);
  const madd::detail::NearestSample one(sets[4]);
  CHECK(one.nearest({std::numeric_limits<double>::quiet_NaN(), 0.0}) == no_index);
  CHECK(one.nearest({-5.0, 1e6}) == 0);
}

// The refinement's "too large" and verify_mesh's size check read one bound:
// RefineSettings holds the AreaBound that verify_mesh builds too, and two of
// them built apart (as mesh() and verify_mesh() each build theirs) answer
// alike, bit for bit, and as the definition does: the smallest of max_area,
// the function where it is > 0 and the nearest sample's value.
TEST_CASE("one size bound: the mesher's refinement and verify_mesh ask the same AreaBound") {
  static_assert(std::is_same_v<decltype(madd::detail::RefineSettings::size), const madd::detail::AreaBound*>);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  MeshSizeOptions size;
  size.max_triangle_area = 0.05;
  // <= 0 below the line x + y = 1: no bound from the function there.
  size.triangle_area_function = [](double x, double y) { return 0.02 * (x + y - 1.0); };
  // Samples of a bound growing with x, 20% noise; and a lattice, whose cell
  // centres are as near to four samples.
  for (int k = 0; k < 2000; ++k) {
    const Point at{4.0 * unit(rng), 2.0 * unit(rng)};
    size.triangle_area_samples.push_back({at, 0.01 + 0.005 * at.x * (1.0 + 0.2 * unit(rng))});
  }
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 4; ++j) size.triangle_area_samples.push_back({{0.5 * i, 0.5 * j}, 0.01 + 0.0025 * i});
  size.sample_interpolation = madd::MeshSizeOptions::SampleInterpolation::nearest;  // the rule scan_nearest restates
  const madd::detail::AreaBound mesher(size), verifier(size);
  for (int q = 0; q < 20000; ++q) {
    Point p{5.0 * unit(rng) - 0.5, 3.0 * unit(rng) - 0.5};
    if (q % 4 == 0) p = {std::floor(p.x * 2.0) / 2.0 + 0.25, std::floor(p.y * 2.0) / 2.0 + 0.25};
    double want = size.max_triangle_area;
    if (size.triangle_area_function(p.x, p.y) > 0.0) want = std::min(want, size.triangle_area_function(p.x, p.y));
    want = std::min(want, size.triangle_area_samples[scan_nearest(size.triangle_area_samples, p)].value);
    CAPTURE(p.x);
    CAPTURE(p.y);
    REQUIRE(mesher.area_at(p) == want);
    REQUIRE(verifier.area_at(p) == want);
    REQUIRE(madd::area_bound_at(size, p) == want);
  }
  // And a mesh refined to that bound, with a region's own bound inside its
  // loop, passes verify_mesh's check against it.
  const madd::test::InteriorFixture f = madd::test::interior_fixture();
  madd::MeshOptions o = madd::test::options_for(2, 30, 0.0);
  o.size = size;
  o.size.min_triangle_angle_deg = 30;
  const Mesh m = madd::mesh_decomposition(f.decomposition, f.domain, o).mesh;
  const madd::Verification v = verified(m, f.domain, o.size);
  show(v);
  CHECK(v.ok());
  CHECK(m.triangles.size() > 8.0 / 0.05);
}

// The hand-made domain with interior segments, isolated vertices and
// regions (tests/interior_fixture.hpp), meshed once (q 30, a 0.02).
struct InteriorMesh {
  madd::test::InteriorFixture f = madd::test::interior_fixture();
  MeshSizeOptions size = [] {
    MeshSizeOptions s;
    s.max_triangle_area = 0.02;
    return s;
  }();
  Mesh mesh = [this] {
    madd::MeshOptions o = madd::test::options_for(2, 30, 0.02);
    return madd::mesh_decomposition(f.decomposition, f.domain, o).mesh;
  }();
};

const InteriorMesh& interior_mesh() {
  static const InteriorMesh m;
  return m;
}

// A mesh segment on an interior piece, and the edge's two triangles.
struct InteriorEdge {
  std::uint32_t segment, t, u;
};

InteriorEdge an_interior_edge(const Mesh& m) {
  const std::vector<std::uint32_t> owner = madd::interior_segment_owners(m.decomposition);
  for (std::uint32_t s = 0; s < m.segments.size(); ++s) {
    if (owner[m.segments[s].piece] == no_index) continue;
    std::vector<std::uint32_t> users;
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
      const auto& c = m.triangles[t];
      const bool has_a = std::find(c.begin(), c.end(), m.segments[s].a) != c.end();
      const bool has_b = std::find(c.begin(), c.end(), m.segments[s].b) != c.end();
      if (has_a && has_b) users.push_back(t);
    }
    REQUIRE(users.size() == 2);
    return {s, users[0], users[1]};
  }
  FAIL("no interior segment");
  return {};
}

TEST_CASE("verify_mesh: interior segments, isolated vertices and regions") {
  const InteriorMesh& im = interior_mesh();
  const Mesh& good = im.mesh;
  const Pslg& domain = im.f.domain;
  {
    const madd::Verification v = verified(good, domain, im.size);
    show(v);
    REQUIRE(v.ok());
  }
  SUBCASE("an interior piece claimed by the other subdomain") {
    Mesh m = good;
    const InteriorEdge e = an_interior_edge(m);
    const std::uint32_t piece = m.segments[e.segment].piece;
    const std::uint32_t k = m.triangle_subdomain[e.t];
    auto& from = m.decomposition.subdomains[k].interior_segments;
    from.erase(std::find(from.begin(), from.end(), piece));
    auto& to = m.decomposition.subdomains[1 - k].interior_segments;
    to.insert(std::lower_bound(to.begin(), to.end(), piece), piece);
    const madd::Verification v = verified(m, domain, im.size);
    CHECK(mentions(v, "lies inside subdomain " + std::to_string(k)));
    CHECK(mentions(v, "its piece is interior to subdomain " + std::to_string(1 - k)));
  }
  SUBCASE("an interior segment with a triangle on one side only") {
    Mesh m = good;
    const InteriorEdge e = an_interior_edge(m);
    m.triangles.erase(m.triangles.begin() + e.u);
    m.triangle_subdomain.erase(m.triangle_subdomain.begin() + e.u);
    m.triangle_attribute.erase(m.triangle_attribute.begin() + e.u);
    rebuild(m);
    const madd::Verification v = verified(m, domain, im.size);
    CHECK(mentions(v, "interior segment "));
    CHECK(mentions(v, "is in one triangle only"));
  }
  SUBCASE("an interior piece's chain broken") {
    Mesh m = good;
    const InteriorEdge e = an_interior_edge(m);
    const std::uint32_t piece = m.segments[e.segment].piece;
    m.segments.erase(m.segments.begin() + e.segment);
    const madd::Verification v = verified(m, domain, im.size);
    CHECK(mentions(v, "interior piece " + std::to_string(piece) + " "));
  }
  SUBCASE("an isolated vertex that is no mesh vertex of its subdomain") {
    Mesh m = good;
    m.decomposition.subdomains[0].interior_points.push_back(15);  // a vertex of subdomain 1's triangles only
    CHECK(mentions(verified(m, domain, im.size),
                   "isolated input vertex 15 (3, 1.1000000000000001) is no vertex of subdomain 0"));
  }
  SUBCASE("a wrong region attribute") {
    Mesh m = good;
    const InteriorEdge e = an_interior_edge(m);
    m.triangle_attribute[e.t] += 1.0;
    CHECK(mentions(verified(m, domain, im.size), "triangle " + std::to_string(e.t) + " (subdomain"));
    CHECK(mentions(verified(m, domain, im.size), "has region attribute"));
  }
  SUBCASE("region attributes missing") {
    Mesh m = good;
    m.triangle_attribute.clear();
    CHECK(mentions(verified(m, domain, im.size), "triangle_attribute has 0 entries"));
  }
  SUBCASE("a regional area bound exceeded") {
    Mesh m = good;
    m.decomposition.regions[1].max_area = 0.0005;  // the loop's triangles were made for 0.002
    const madd::Verification v = verified(m, domain, im.size);
    CHECK(mentions(v, "above the size bound 0.0005"));
    // Only the loop's region is bounded so: every complaint is about a triangle inside it.
    for (const std::string& p : v.problems)
      if (p.rfind("triangle ", 0) == 0) CHECK(p.find("above the size bound 0.0005") != std::string::npos);
  }
}

TEST_CASE("verify_mesh: time on a large synthetic mesh") {
  // MADD_VERIFY_MESH_GRID=k times a k x k grid (2 k^2 triangles) in 8
  // strips; the default keeps the test quick.
  const char* env = std::getenv("MADD_VERIFY_MESH_GRID");
  const std::uint32_t k = env != nullptr ? static_cast<std::uint32_t>(std::atoi(env)) : 200;
  const GridMesh g = grid_mesh(k, 8, true);
  MeshSizeOptions size;
  size.max_triangle_area = 0.5;
  const auto start = std::chrono::steady_clock::now();
  const madd::Verification v = verified(g.mesh, g.domain, size);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  show(v);
  CHECK(v.ok());
  MESSAGE("verify_mesh: " << g.mesh.triangles.size() << " triangles in " << seconds << " s");
}

}  // TEST_SUITE("verify_mesh")
