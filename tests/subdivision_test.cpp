// The global subdivision's merge (the inverse of a commit) and compaction,
// which the balance repair uses (decompose/rebalance.hpp): a merge must give
// back exactly the union (area, simple rings, segment ownership), refuse
// faces that share no separator without changing anything, and compact must
// leave no segment or point that no face uses.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "madd/decomposition.hpp"
#include "split/split.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {
void check_new_angles(const Subdivision& sub, double separator_angle_deg);  // subdivision/check.cpp
}

namespace {

using madd::Point;
using madd::Pslg;
using madd::detail::Subdivision;

Pslg rectangle(double w, double h) {
  Pslg p;
  p.first_index = 0;
  p.points = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (std::uint32_t i = 0; i < 4; ++i) p.segments.push_back({i, (i + 1) % 4, 0});
  return p;
}

// Splits face `face` of `sub` in two with the library's own split.
std::uint32_t split(Subdivision& sub, std::uint32_t face) {
  madd::detail::SplitOptions o;
  const madd::detail::SplitResult r = madd::detail::compute_split(sub, face, 2, o);
  return sub.commit(face, r);
}

double total_area(const Subdivision& sub) {
  double a = 0.0;
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) a += sub.face_area(f);
  return a;
}

// Every segment a face's ring names has that face in seg_faces, and every
// segment owned by a face is on one of its rings.
void check_ownership(const Subdivision& sub) {
  std::vector<std::set<std::uint32_t>> on_rings(sub.segments.size());
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    for (const auto& ring : sub.faces[f].ring_segments) {
      for (const std::uint32_t s : ring) on_rings[s].insert(f);
    }
  }
  for (std::uint32_t s = 0; s < sub.segments.size(); ++s) {
    std::set<std::uint32_t> owners;
    for (const std::uint32_t f : sub.seg_faces[s]) {
      if (f != madd::no_index) owners.insert(f);
    }
    CAPTURE(s);
    CHECK(owners == on_rings[s]);
  }
}

// Faces a and b share a separator.
bool adjacent(const Subdivision& sub, std::uint32_t a, std::uint32_t b) {
  for (const auto& sf : sub.seg_faces) {
    if ((sf[0] == a && sf[1] == b) || (sf[0] == b && sf[1] == a)) return true;
  }
  return false;
}

using madd::detail::EndRef;
using madd::detail::SplitResult;

EndRef on_segment(std::uint32_t segment, std::uint32_t local, Point p) {
  return EndRef{EndRef::inside_segment, segment, local, p};
}

// The segment of `sub` that contains p strictly inside (a piece of a straight segment).
std::uint32_t segment_through(const Subdivision& sub, Point p) {
  for (std::uint32_t s = 0; s < sub.segments.size(); ++s) {
    const Point a = sub.points[sub.segments[s].a], b = sub.points[sub.segments[s].b];
    if (std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) < 1e-12 && std::min(a.x, b.x) <= p.x &&
        p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y) && !(p == a) && !(p == b))
      return s;
  }
  return madd::no_index;
}

// One separator along `path` inside face `face` (side 0 on its left): its
// ends inside segments of `sub`, the points between them circumcentres.
SplitResult separator(const Subdivision& sub, std::uint32_t face, const std::vector<Point>& path, Point left,
                      Point right, double snap = 0.0) {
  SplitResult r;
  const auto ref = [&](std::size_t k) {
    const auto local = static_cast<std::uint32_t>(k);
    if (k == 0 || k + 1 == path.size()) return on_segment(segment_through(sub, path[k]), local, path[k]);
    return EndRef{EndRef::centre, madd::no_index, local, path[k]};
  };
  for (std::size_t k = 0; k + 1 < path.size(); ++k) r.edges.push_back({ref(k), ref(k + 1), 0});
  r.ring_side.assign(sub.faces[face].rings.size(), 0);
  r.interior[0] = left;
  r.interior[1] = right;
  r.snap = {snap, 60.0};
  return r;
}

// The vertices of `sub` on the line x = 1.
std::size_t vertices_on_x1(const Subdivision& sub) {
  std::set<std::uint32_t> on;
  for (const auto& s : sub.segments) {
    for (const std::uint32_t v : {s.a, s.b}) {
      if (sub.points[v].x == 1.0) on.insert(v);
    }
  }
  return on.size();
}

// A 2 x 1 rectangle split by the vertical separator x = 1; then both halves
// split "in the same round" (from one snapshot) by separators ending on it:
// the left one at (1, 0.5), the right one along `right` (from a point just
// above). Returns the subdivision.
Subdivision two_ends_on_one_separator(const std::vector<Point>& right, double snap) {
  Subdivision sub = Subdivision::from_domain(rectangle(2.0, 1.0));
  sub.commit(0, separator(sub, 0, {{1, 0}, {1, 1}}, {0.5, 0.5}, {1.5, 0.5}));
  REQUIRE(sub.faces.size() == 2);
  const std::uint32_t left = sub.faces[0].interior.x < 1.0 ? 0u : 1u;
  const Subdivision snapshot = sub;
  // Left half: from its left side to (1, 0.5); side 0 (above) on the left going right.
  sub.commit(left, separator(snapshot, left, {{0, 0.5}, {1, 0.5}}, {0.5, 0.75}, {0.5, 0.25}, snap));
  // Right half, computed from the snapshot: from right[0] on x = 1 to the right side.
  sub.commit(1 - left, separator(snapshot, 1 - left, right, {1.9, 0.9}, {1.9, 0.1}, snap));
  return sub;
}

}  // namespace

TEST_SUITE("subdivision") {

TEST_CASE("EndSnap: an end a hair from a neighbour's end on the same separator moves onto it") {
  const std::vector<Point> horizontal{{1.0, 0.51}, {2.0, 0.51}};  // 90 degrees either way
  const Subdivision without = two_ends_on_one_separator(horizontal, 0.0);
  CHECK(vertices_on_x1(without) == 4);  // (1,0), (1,0.5), (1,0.51), (1,1): a 0.01 piece
  const Subdivision with = two_ends_on_one_separator(horizontal, 0.05);
  CHECK(vertices_on_x1(with) == 3);  // both separators end at (1, 0.5)
  CHECK(total_area(with) == doctest::Approx(2.0).epsilon(1e-14));
  check_ownership(with);
  CHECK_NOTHROW(madd::detail::check_new_angles(with, 60.0));
  // Farther than the snap distance: no move.
  CHECK(vertices_on_x1(two_ends_on_one_separator({{1.0, 0.56}, {2.0, 0.56}}, 0.05)) == 4);
}

TEST_CASE("EndSnap: no move that would bring an angle at the separator below Phi0") {
  // A bent separator: (1, 0.51) -> centre c -> (2, c.y). Its first piece
  // leaves x = 1 at 60.3 degrees; from (1, 0.5) it would leave at 57.9
  // degrees, while every other angle (at c, at the right side) would stay
  // above 60: only the angle at the separator refuses the move.
  const double a = 60.3 * M_PI / 180.0;
  const Point q{1.0, 0.51}, c{q.x + 0.2 * std::sin(a), q.y + 0.2 * std::cos(a)};
  const Subdivision sub = two_ends_on_one_separator({q, c, {2.0, c.y}}, 0.05);
  CHECK(vertices_on_x1(sub) == 4);
  CHECK_NOTHROW(madd::detail::check_new_angles(sub, 60.0));
  // The same separator leaving at 64 degrees moves: from (1, 0.5) it leaves at
  // 61.5 degrees, above Phi0.
  const double b = 64.0 * M_PI / 180.0;
  const Point d{q.x + 0.2 * std::sin(b), q.y + 0.2 * std::cos(b)};
  const Subdivision moved = two_ends_on_one_separator({q, d, {2.0, d.y}}, 0.05);
  CHECK(vertices_on_x1(moved) == 3);
  CHECK_NOTHROW(madd::detail::check_new_angles(moved, 60.0));
}

TEST_CASE("merging the two sides of a split gives back the domain; compact drops the separator") {
  const Pslg domain = rectangle(3.0, 1.0);
  Subdivision sub = Subdivision::from_domain(domain);
  const double area = sub.face_area(0);
  const std::uint32_t added = split(sub, 0);
  REQUIRE(sub.faces.size() == 2);
  const std::size_t separators_before =
      static_cast<std::size_t>(std::count(sub.origin.begin(), sub.origin.end(), madd::no_index));
  REQUIRE(separators_before > 0);
  REQUIRE(sub.merge(0, added));
  CHECK(sub.faces.size() == 1);
  CHECK(sub.faces[0].rings.size() == 1);
  CHECK(sub.face_area(0) == doctest::Approx(area).epsilon(1e-14));
  check_ownership(sub);
  sub.compact();
  // Only the input's pieces remain: the separator and its interior points are gone.
  CHECK(std::count(sub.origin.begin(), sub.origin.end(), madd::no_index) == 0);
  std::vector<int> used(sub.points.size(), 0);
  for (const auto& s : sub.segments) used[s.a] = used[s.b] = 1;
  CHECK(std::count(used.begin(), used.end(), 0) == 0);
  CHECK(sub.face_area(0) == doctest::Approx(area).epsilon(1e-14));
  check_ownership(sub);
  // The merged face splits again.
  split(sub, 0);
  CHECK(sub.faces.size() == 2);
  CHECK(total_area(sub) == doctest::Approx(area).epsilon(1e-12));
  check_ownership(sub);
}

TEST_CASE("merge keeps the lower id, moves the last face into the other one and keeps areas") {
  Subdivision sub = Subdivision::from_domain(rectangle(8.0, 1.0));
  const double area = total_area(sub);
  split(sub, 0);
  split(sub, 0);
  split(sub, 1);
  REQUIRE(sub.faces.size() == 4);
  // Find an adjacent pair (a < b) with b not the last face, so that the last one moves.
  std::uint32_t a = madd::no_index, b = madd::no_index;
  for (std::uint32_t x = 0; x < 4 && a == madd::no_index; ++x) {
    for (std::uint32_t y = x + 1; y < 3; ++y) {
      if (adjacent(sub, x, y)) {
        a = x;
        b = y;
        break;
      }
    }
  }
  REQUIRE(a != madd::no_index);
  const double union_area = sub.face_area(a) + sub.face_area(b);
  const double last_area = sub.face_area(3);
  const Point last_interior = sub.faces[3].interior;
  // Siblings: the two sides of the latest split of a face know each other.
  CHECK(sub.faces[1].sibling == 3);
  CHECK(sub.faces[3].sibling == 1);
  CHECK(sub.faces[0].sibling == 2);  // its first sibling (1) was split again
  CHECK(sub.faces[2].sibling == 0);
  const std::uint32_t last_sibling = sub.faces[3].sibling;
  REQUIRE(sub.merge(b, a));
  REQUIRE(sub.faces.size() == 3);
  if (last_sibling != a && last_sibling != b) CHECK(sub.faces[last_sibling].sibling == b);  // follows the move
  CHECK(sub.faces[a].sibling == madd::no_index);
  CHECK(sub.face_area(a) == doctest::Approx(union_area).epsilon(1e-13));
  CHECK(sub.face_area(b) == doctest::Approx(last_area).epsilon(1e-13));
  CHECK(sub.faces[b].interior == last_interior);
  CHECK(total_area(sub) == doctest::Approx(area).epsilon(1e-13));
  check_ownership(sub);
}

TEST_CASE("faces that share no separator are not merged, and nothing changes") {
  Subdivision sub = Subdivision::from_domain(rectangle(8.0, 1.0));
  split(sub, 0);
  split(sub, 0);
  split(sub, 1);
  std::uint32_t a = madd::no_index, b = madd::no_index;
  for (std::uint32_t x = 0; x < sub.faces.size(); ++x) {
    for (std::uint32_t y = x + 1; y < sub.faces.size(); ++y) {
      if (!adjacent(sub, x, y) && a == madd::no_index) {
        a = x;
        b = y;
      }
    }
  }
  REQUIRE(a != madd::no_index);  // four strips along a bar: the two ends never touch
  const auto faces = sub.faces.size();
  const auto seg_faces = sub.seg_faces;
  const auto rings = sub.faces[a].rings;
  CHECK_FALSE(sub.merge(a, b));
  CHECK_FALSE(sub.merge(a, a));
  CHECK_FALSE(sub.merge(a, 99));
  CHECK(sub.faces.size() == faces);
  CHECK(sub.seg_faces == seg_faces);
  CHECK(sub.faces[a].rings == rings);
}

}  // TEST_SUITE("subdivision")
