// Tests of the half-edge triangulation core (src/triangulation/half_edge_mesh.hpp,
// src/triangulation/cavity.hpp, src/triangulation/walk.hpp): the structure's
// invariants checked by brute force, the cavity's fan kept Delaunay through
// insertions, slot reuse, the walks, edge search, compaction, and splitting
// an edge of a constrained mesh.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "madd/predicates.hpp"
#include "triangulation/cavity.hpp"
#include "triangulation/cdt.hpp"
#include "triangulation/half_edge_mesh.hpp"
#include "triangulation/walk.hpp"
#include "random_points.hpp"

namespace {

using madd::no_index;
using madd::Point;
using madd::detail::Cavity;
using madd::detail::HalfEdgeMesh;

using madd::test::random_points;

bool is_real(const HalfEdgeMesh& m, std::uint32_t t) { return m.alive(t) && (m.ghost == no_index || !m.is_ghost(t)); }

// Twins are symmetric and reversed, every real triangle is strictly
// counter-clockwise, and every vertex in `used` is a corner of a live triangle.
void check_structure(const HalfEdgeMesh& m, const std::vector<Point>& P, const std::vector<std::uint32_t>& used) {
  std::vector<char> seen(P.size() + 1, 0);
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) {
    if (!m.alive(t)) continue;
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
      if (m.tv[h] != m.ghost) seen[m.tv[h]] = 1;
      const std::uint32_t g = m.tn[h];
      if (g == no_index) continue;
      REQUIRE(m.alive(g / 3));
      REQUIRE(m.tn[g] == h);
      REQUIRE(m.origin(g) == m.dest(h));
      REQUIRE(m.dest(g) == m.origin(h));
      if (m.constrained()) REQUIRE(m.seg[g] == m.seg[h]);
    }
    if (is_real(m, t)) REQUIRE(madd::orient2d(P[m.tv[3 * t]], P[m.tv[3 * t + 1]], P[m.tv[3 * t + 2]]) > 0);
  }
  for (const std::uint32_t v : used) REQUIRE(seen[v]);
}

// No vertex of `used` strictly inside the circumcircle of a real triangle.
void check_empty_circles(const HalfEdgeMesh& m, const std::vector<Point>& P, const std::vector<std::uint32_t>& used) {
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) {
    if (!is_real(m, t)) continue;
    const Point a = P[m.tv[3 * t]], b = P[m.tv[3 * t + 1]], c = P[m.tv[3 * t + 2]];
    for (const std::uint32_t v : used) REQUIRE(madd::incircle(a, b, c, P[v]) <= 0);
  }
}

std::uint32_t live_count(const HalfEdgeMesh& m) {
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) n += m.alive(t) ? 1 : 0;
  return n;
}

// p in the closure of real triangle t.
bool holds(const HalfEdgeMesh& m, const std::vector<Point>& P, std::uint32_t t, Point p) {
  for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h)
    if (madd::orient2d(P[m.origin(h)], P[m.dest(h)], p) < 0) return false;
  return true;
}

std::vector<std::uint32_t> iota(std::uint32_t n) {
  std::vector<std::uint32_t> v(n);
  for (std::uint32_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

// Inserts points[first..] one by one with the general dig/fill path of a
// cavity that reuses slots last found first (the refinement's order),
// locating each by a visibility walk. The ghost is vertex `first - 1`
// (build_delaunay's numbering: the input's size), which holds no point.
// Returns how many slots were added.
std::uint32_t insert_one_by_one(HalfEdgeMesh& m, const std::vector<Point>& P, std::uint32_t first) {
  Cavity cavity(Cavity::SlotOrder::last_found_first);
  madd::detail::WalkRandom random;
  const std::uint32_t slots = m.slot_count();
  std::uint32_t start = 0;
  for (std::uint32_t v = first; v < P.size(); ++v) {
    const std::uint32_t t = madd::detail::walk_visibly(m, P, P[v], start, random).triangle;
    REQUIRE(t != no_index);
    cavity.dig(m, P, t, P[v]);
    REQUIRE(cavity.star_shaped(P, P[v]));
    const std::size_t k = cavity.triangles().size();
    const auto fan = cavity.fill(m, v);
    CHECK(fan.size() == k + 2);  // k cavity triangles, k + 2 rim edges
    start = fan.front();
  }
  return m.slot_count() - slots;
}

}  // namespace

TEST_SUITE("half_edge") {
TEST_CASE("build_delaunay: symmetric twins and empty circles on random sets") {
  for (const unsigned seed : {1u, 2u, 3u, 4u}) {
    for (const std::size_t n : {3u, 10u, 100u, 400u}) {
      const std::vector<Point> P = random_points(n, seed);
      HalfEdgeMesh m;
      REQUIRE(madd::detail::build_delaunay(m, P));
      CHECK(m.ghost == n);
      CHECK(m.slot_count() == 2 * n - 2);  // ghosts included
      check_structure(m, P, iota(static_cast<std::uint32_t>(n)));
      check_empty_circles(m, P, iota(static_cast<std::uint32_t>(n)));
    }
  }
}

TEST_CASE("the general cavity keeps a triangulation Delaunay, inserting inside and outside the hull") {
  for (const unsigned seed : {5u, 6u, 7u}) {
    // The first 30 points in the unit square, the rest over a larger square,
    // so that many later ones land outside the hull (ghost cavities).
    std::vector<Point> P = random_points(30, seed);
    P.push_back({0, 0});  // vertex 30: the ghost's number, no point of the mesh
    for (const Point& q : random_points(200, seed + 100)) P.push_back({3 * q.x - 1, 3 * q.y - 1});
    HalfEdgeMesh m;
    REQUIRE(madd::detail::build_delaunay(m, std::span(P).first(30)));
    CHECK(insert_one_by_one(m, P, 31) == 2 * 200);  // no free slot: two new ones each time
    std::vector<std::uint32_t> used = iota(30);
    for (std::uint32_t v = 31; v < P.size(); ++v) used.push_back(v);
    check_structure(m, P, used);
    check_empty_circles(m, P, used);
  }
}

TEST_CASE("slot reuse: a freed slot is taken before the arrays grow") {
  std::vector<Point> P = random_points(50, 8);
  P.push_back({0, 0});  // the ghost's number
  P.push_back({0.5, 0.5});
  HalfEdgeMesh m;
  REQUIRE(madd::detail::build_delaunay(m, std::span(P).first(50)));
  const std::uint32_t spare = m.append_slots(1);
  m.free_slot(spare);
  CHECK(!m.alive(spare));
  // The fan of the one insertion needs two more slots than its cavity's:
  // the freed one, and one new.
  CHECK(insert_one_by_one(m, P, 51) == 1);
  CHECK(m.free_slots.empty());
  CHECK(m.alive(spare));
  check_structure(m, P, iota(50));
}

TEST_CASE("a visibility walk finds the triangle holding a point, or a ghost outside the hull") {
  const std::vector<Point> P = random_points(300, 9);
  HalfEdgeMesh m;
  REQUIRE(madd::detail::build_delaunay(m, P));
  madd::detail::WalkRandom random;
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int i = 0; i < 500; ++i) {
    const Point p{u(rng), u(rng)};
    const std::uint32_t start = static_cast<std::uint32_t>(rng() % m.slot_count());
    const std::uint32_t t = madd::detail::walk_visibly(m, P, p, start, random).triangle;
    REQUIRE(t != no_index);
    if (m.is_ghost(t)) {
      std::uint32_t h = 3 * t;
      while (m.tv[h] != m.ghost) ++h;
      CHECK(madd::detail::ghost_conflict(P[m.origin(h)], P[m.dest(h)], p));
    } else {
      CHECK(holds(m, P, t, p));
    }
  }
  // A point that is a vertex is held by a triangle at that vertex.
  const std::uint32_t t = madd::detail::walk_visibly(m, P, P[7], 0, random).triangle;
  CHECK(holds(m, P, t, P[7]));
}

TEST_CASE("a weighing walk gives p's exact-sign weights where it ends, or the hull edge p is beyond") {
  // A square of random points, closed by its four sides (no ghosts), as the
  // size field's background is.
  madd::Pslg pslg;
  pslg.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const Point p : random_points(200, 11)) pslg.points.push_back({0.01 + 0.98 * p.x, 0.01 + 0.98 * p.y});
  for (std::uint32_t i = 0; i < 4; ++i) pslg.segments.push_back({i, (i + 1) % 4, 1});
  HalfEdgeMesh m;
  REQUIRE(madd::detail::constrained_delaunay(m, pslg, {}));
  REQUIRE(m.ghost == no_index);
  const std::vector<Point>& P = pslg.points;
  madd::detail::WalkRandom random;
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  std::vector<Point> queries = {P[7], {0.5, 0.0}, {1.0, 1.0}, {0.0, 0.25}};
  for (int i = 0; i < 1000; ++i) queries.push_back({u(rng), u(rng)});
  for (const Point p : queries) {
    const std::uint32_t start = static_cast<std::uint32_t>(rng() % m.slot_count());
    std::array<double, 3> w{};
    const madd::detail::WalkResult end = madd::detail::walk_weighing(m, P, p, start, random, w);
    const bool in_square = p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1;
    if (!in_square) {
      REQUIRE(end.triangle == no_index);
      REQUIRE(end.blocked_by != no_index);
      CHECK(m.tn[end.blocked_by] == no_index);
      CHECK(madd::orient2d(P[m.origin(end.blocked_by)], P[m.dest(end.blocked_by)], p) < 0);
      continue;
    }
    REQUIRE(end.triangle != no_index);
    const std::uint32_t t = end.triangle;
    CHECK(holds(m, P, t, p));
    double sum = 0;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const double exact = madd::orient2d(P[m.origin(3 * t + i)], P[m.dest(3 * t + i)], p);
      CHECK((w[i] > 0) == (exact > 0));
      CHECK((w[i] == 0) == (exact == 0));
      sum += w[i];
    }
    const double twice_area = 2 * madd::signed_area(P[m.tv[3 * t]], P[m.tv[3 * t + 1]], P[m.tv[3 * t + 2]]);
    CHECK(sum == doctest::Approx(twice_area).epsilon(1e-9));
  }
}

TEST_CASE("compaction and edge search on a constrained triangulation") {
  // A square with a square hole and a diagonal from the outer ring inwards.
  madd::Pslg pslg;
  pslg.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {2, 0.5}};
  for (std::uint32_t i = 0; i < 4; ++i) pslg.segments.push_back({i, (i + 1) % 4, 1});
  for (std::uint32_t i = 0; i < 4; ++i) pslg.segments.push_back({4 + i, 4 + (i + 1) % 4, 2});
  pslg.segments.push_back({0, 4, 3});
  pslg.holes = {{2, 2}};
  HalfEdgeMesh m;
  REQUIRE(madd::detail::constrained_delaunay(m, pslg, {}));
  CHECK(m.ghost == no_index);
  CHECK(m.free_slots.empty());
  // The ring between the squares: area 12 in triangles of the 9 points.
  double area = 0;
  for (std::uint32_t t = 0; t < m.slot_count(); ++t)
    area += madd::signed_area(pslg.points[m.tv[3 * t]], pslg.points[m.tv[3 * t + 1]], pslg.points[m.tv[3 * t + 2]]);
  CHECK(area == doctest::Approx(12.0));
  check_structure(m, pslg.points, iota(9));
  // Every outside edge is a segment: the two rings, 4 edges each.
  std::size_t boundary = 0;
  for (std::uint32_t h = 0; h < 3 * m.slot_count(); ++h) {
    if (m.tn[h] != no_index) continue;
    ++boundary;
    CHECK(m.seg[h] != no_index);
  }
  CHECK(boundary == 8);
  // Edge search from every corner to every vertex finds the one half-edge
  // from the corner's vertex to it, or none.
  for (std::uint32_t c = 0; c < 3 * m.slot_count(); ++c) {
    for (std::uint32_t w = 0; w < pslg.points.size(); ++w) {
      std::uint32_t expected = no_index;
      for (std::uint32_t h = 0; h < 3 * m.slot_count(); ++h)
        if (m.origin(h) == m.tv[c] && m.dest(h) == w) expected = h;
      CHECK(m.find_half_edge(c, w) == expected);
    }
  }
}

TEST_CASE("a straight walk stops at the first segment in its way") {
  // A square cut by an interior segment from (1, 0.5) to (1, 3.5).
  madd::Pslg pslg;
  pslg.points = {{0, 0}, {2, 0}, {2, 4}, {0, 4}, {1, 0.5}, {1, 3.5}};
  for (std::uint32_t i = 0; i < 4; ++i) pslg.segments.push_back({i, (i + 1) % 4, 1});
  pslg.segments.push_back({4, 5, 2});
  HalfEdgeMesh m;
  REQUIRE(madd::detail::constrained_delaunay(m, pslg, {}));
  const auto& P = pslg.points;
  for (std::uint32_t t = 0; t < m.slot_count(); ++t) {
    const Point o = madd::triangle_centroid(P[m.tv[3 * t]], P[m.tv[3 * t + 1]], P[m.tv[3 * t + 2]]);
    for (const Point p : {Point{0.3, 2.0}, Point{1.7, 2.0}, Point{1.5, 0.2}, Point{0.5, 3.9}}) {
      const madd::detail::WalkResult w = madd::detail::walk_straight(m, P, p, t, o);
      // The segment x = 1 lies between o and p exactly when they are on
      // opposite sides of it and the line o-p crosses it within y 0.5..3.5.
      const bool across = (o.x - 1) * (p.x - 1) < 0;
      const double y = o.y + (p.y - o.y) * (1 - o.x) / (p.x - o.x);
      if (across && y > 0.5 && y < 3.5) {
        REQUIRE(w.blocked_by != no_index);
        CHECK(m.seg[w.blocked_by] == 4);
      } else {
        REQUIRE(w.triangle != no_index);
        CHECK(holds(m, P, w.triangle, p));
      }
    }
  }
}

TEST_CASE("splitting an edge of a constrained mesh: a closed fan inside, an open one at the boundary") {
  madd::Pslg pslg;
  pslg.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0.5, 1}, {1.5, 1}};
  for (std::uint32_t i = 0; i < 4; ++i) pslg.segments.push_back({i, (i + 1) % 4, 1});
  pslg.segments.push_back({4, 5, 2});
  HalfEdgeMesh m;
  REQUIRE(madd::detail::constrained_delaunay(m, pslg, {}));
  std::vector<Point> P = pslg.points;
  Cavity cavity(Cavity::SlotOrder::last_found_first);
  for (const std::uint32_t segment : {4u, 0u}) {  // the interior segment, then a boundary one
    std::uint32_t h = 0;
    while (m.seg[h] != segment) ++h;
    const std::uint32_t a = m.origin(h), b = m.dest(h);
    const bool inner = m.tn[h] != no_index;
    const Point p = madd::midpoint(P[a], P[b]);
    const auto v = static_cast<std::uint32_t>(P.size());
    P.push_back(p);
    cavity.dig_on_edge(m, P, h, p);
    REQUIRE(cavity.star_shaped(P, p));
    const std::uint32_t before = live_count(m);
    const auto fan = cavity.fill(m, v);
    CHECK(live_count(m) == before + (inner ? 2 : 1));
    // The halves of the split edge: in an inner fan both sides of a-v and
    // v-b are fan edges; at the boundary each half has no twin.
    std::size_t open = 0, to_ends = 0;
    for (const std::uint32_t t : fan) {
      CHECK(m.tv[3 * t] == v);
      for (std::uint32_t e : {3 * t + 1, 3 * t + 2}) {
        if (m.tn[e] == no_index) ++open;
        const std::uint32_t other = e == 3 * t + 1 ? m.tv[3 * t + 2] : m.tv[3 * t + 1];
        if (other == a || other == b) ++to_ends;
      }
    }
    CHECK(open == (inner ? 0u : 2u));
    CHECK(to_ends == (inner ? 4u : 2u));
    // Marking the halves as segment edges is for the caller (refinement).
    check_structure(m, P, iota(v + 1));
  }
}
}  // TEST_SUITE("half_edge")
