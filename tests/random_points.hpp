#pragma once
// Uniform random points in the unit square, from a fixed seed: the point sets
// of the triangulation tests (the same seed gives the same points anywhere).
#include <cstddef>
#include <random>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::test {

inline std::vector<Point> random_points(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng)};
  return pts;
}

}  // namespace madd::test
