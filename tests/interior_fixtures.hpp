#pragma once
// A hand-made decomposition with interior constraints (issue 16), for the
// output tests: the unit square split at x = 0.5 by one separator; the left
// half holds a closed interior loop (a small square, marker 7), the right
// half a dangling interior segment (input marker 0, so 1 here) and one
// isolated point. Input regions: A inside the loop, B in the right half.
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::test {

struct InteriorFixture {
  Pslg domain;                  // the input: points 0-10, segments 0-8, regions A and B
  Decomposition decomposition;  // points 0-12 (11, 12: the separator's ends)
};

inline InteriorFixture interior_square() {
  InteriorFixture f;
  Pslg& p = f.domain;
  p.points = {{0, 0},      {1, 0},     {1, 1},     {0, 1},      // boundary
              {0.1, 0.4},  {0.3, 0.4}, {0.3, 0.6}, {0.1, 0.6},  // the loop
              {0.6, 0.5},  {0.9, 0.5},                          // the dangling segment
              {0.75, 0.25}};                                    // the isolated point
  p.segments = {{0, 1, 2}, {1, 2, 3}, {2, 3, 4}, {3, 0, 5}, {4, 5, 7}, {5, 6, 7}, {6, 7, 7}, {7, 4, 7}, {8, 9, 0}};
  p.has_segment_markers = true;
  p.regions = {{{0.2, 0.5}, 2.0, 0.01}, {{0.8, 0.8}, 3.0, 0.05}};

  Decomposition& d = f.decomposition;
  d.points = p.points;
  d.points.push_back({0.5, 0});                                                         // 11
  d.points.push_back({0.5, 1});                                                         // 12
  d.segments = {{0, 11, 2},  {11, 1, 2}, {1, 2, 3}, {2, 12, 4}, {12, 3, 4}, {3, 0, 5},  // boundary pieces 0-5
                {11, 12, 0},                                                            // the separator, 6
                {4, 5, 7},   {5, 6, 7},  {6, 7, 7}, {7, 4, 7},                          // the loop, 7-10
                {8, 9, 1}};                                                             // dangling, 11
  d.segment_origin = {0, 0, 1, 2, 2, 3, no_index, 4, 5, 6, 7, 8};
  d.regions = p.regions;
  Subdomain left;
  left.rings = {{0, 11, 12, 3}};
  left.ring_segments = {{0, 6, 4, 5}};
  left.area = left.weight = 0.5;
  left.interior_point = {0.25, 0.2};
  left.interior_segments = {7, 8, 9, 10};
  Subdomain right;
  right.rings = {{11, 1, 2, 12}};
  right.ring_segments = {{1, 2, 3, 6}};
  right.area = right.weight = 0.5;
  right.interior_point = {0.75, 0.75};
  right.interior_segments = {11};
  right.interior_points = {10};
  d.subdomains = {left, right};
  d.separator_angle_deg = 60.0;
  return f;
}

}  // namespace madd::test
