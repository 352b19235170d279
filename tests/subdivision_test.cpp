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

} // namespace

TEST_SUITE("subdivision") {

TEST_CASE("merging the two sides of a split gives back the domain; compact drops the separator") {
  const Pslg domain = rectangle(3.0, 1.0);
  Subdivision sub = Subdivision::from_domain(domain);
  const double area = sub.face_area(0);
  const std::uint32_t added = split(sub, 0);
  REQUIRE(sub.faces.size() == 2);
  const std::size_t separators_before = static_cast<std::size_t>(
      std::count(sub.origin.begin(), sub.origin.end(), madd::no_index));
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
  REQUIRE(sub.merge(b, a));
  REQUIRE(sub.faces.size() == 3);
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

} // TEST_SUITE
