#pragma once
// Hand-made decompositions with known answers, for metrics_test and output_test.
// A fixture is given by its points, the input domain's segments (indices into
// the same points) and each subdomain's rings; the segments of the
// decomposition, their markers and origins are derived from the rings.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/predicates.hpp"

namespace madd::test {

struct Fixture {
  Pslg domain;
  Decomposition decomposition;
};

struct SubdomainSpec {
  std::vector<std::vector<std::uint32_t>> rings;
  Point interior;
  std::vector<Point> hole_points;
};

inline bool on_input_segment(const Pslg& domain, std::uint32_t s, Point p) {
  const Point a = domain.points[domain.segments[s].a], b = domain.points[domain.segments[s].b];
  return orient2d(a, b, p) == 0.0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// `input_points` of `points` are the domain's; `input_segments` join them.
inline Fixture make_fixture(const std::vector<Point>& points, std::size_t input_points,
                            const std::vector<std::pair<std::uint32_t, std::uint32_t>>& input_segments,
                            const std::vector<Point>& holes, const std::vector<SubdomainSpec>& subs) {
  Fixture f;
  f.domain.points.assign(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(input_points));
  for (const auto& [a, b] : input_segments) f.domain.segments.push_back({a, b, 0});
  f.domain.holes = holes;
  Decomposition& d = f.decomposition;
  d.points = points;
  d.holes = holes;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> ids;
  for (const SubdomainSpec& spec : subs) {
    Subdomain sub;
    sub.rings = spec.rings;
    for (const auto& ring : spec.rings) {
      std::vector<std::uint32_t> segs;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::uint32_t p = ring[k], q = ring[(k + 1) % ring.size()];
        const auto key = std::minmax(p, q);
        auto it = ids.find(key);
        if (it == ids.end()) {
          std::uint32_t origin = no_index;
          for (std::uint32_t s = 0; s < f.domain.segments.size(); ++s)
            if (on_input_segment(f.domain, s, points[p]) && on_input_segment(f.domain, s, points[q])) origin = s;
          it = ids.emplace(key, static_cast<std::uint32_t>(d.segments.size())).first;
          d.segments.push_back({p, q, origin == no_index ? 0 : 1});
          d.segment_origin.push_back(origin);
        }
        segs.push_back(it->second);
      }
      sub.ring_segments.push_back(segs);
      double twice = 0.0;
      for (std::size_t k = 0; k < ring.size(); ++k)
        twice += cross(points[ring[k]], points[ring[(k + 1) % ring.size()]]);
      sub.area += 0.5 * twice;
    }
    sub.weight = sub.area;
    sub.interior_point = spec.interior;
    sub.hole_points = spec.hole_points;
    d.subdomains.push_back(sub);
  }
  return f;
}

// The unit square split by the vertical line x = 0.5.
inline Fixture square_halves() {
  return make_fixture({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {0.5, 1}}, 4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {},
                      {{{{0, 4, 5, 3}}, {0.25, 0.5}, {}}, {{{4, 1, 2, 5}}, {0.75, 0.5}, {}}});
}

// The unit square split into four quadrants meeting at the centre.
inline Fixture square_quadrants() {
  return make_fixture({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}, {0.5, 0.5}}, 4,
                      {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {},
                      {{{{0, 4, 8, 7}}, {0.25, 0.25}, {}},
                       {{{4, 1, 5, 8}}, {0.75, 0.25}, {}},
                       {{{8, 5, 2, 6}}, {0.75, 0.75}, {}},
                       {{{7, 8, 6, 3}}, {0.25, 0.75}, {}}});
}

// The square annulus [-2,2]^2 minus [-1,1]^2 split along y = 0 into two halves.
inline Fixture annulus_halves() {
  return make_fixture(
      {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {2, 0}, {1, 0}, {-1, 0}, {-2, 0}}, 8,
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}, {{0, 0}},
      {{{{0, 1, 8, 9, 5, 4, 10, 11}}, {0, -1.5}, {}}, {{{11, 10, 7, 6, 9, 8, 2, 3}}, {0, 1.5}, {}}});
}

// [0,2]x[0,1] with a square hole in the left half, split at x = 1.
inline Fixture rectangle_with_hole() {
  return make_fixture(
      {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}, {1, 0}, {1, 1}}, 8,
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}, {{0.5, 0.5}},
      {{{{0, 8, 9, 3}, {4, 7, 6, 5}}, {0.1, 0.5}, {{0.5, 0.5}}}, {{{8, 1, 2, 9}}, {1.5, 0.5}, {}}});
}

// [0,3]^2 with the subdomain [1,2]^2 completely surrounded by the other one.
inline Fixture surrounded() {
  return make_fixture({{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}}, 4,
                      {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {},
                      {{{{0, 1, 2, 3}, {4, 7, 6, 5}}, {0.5, 0.5}, {{1.5, 1.5}}}, {{{4, 5, 6, 7}}, {1.5, 1.5}, {}}});
}

inline std::vector<Fixture> all_fixtures() {
  return {square_halves(), square_quadrants(), annulus_halves(), rectangle_with_hole(), surrounded()};
}

}  // namespace madd::test
