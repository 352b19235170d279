// Micro-benchmark of the adaptive predicates: nanoseconds per call on random
// input (stage A nearly always decides) and on near-degenerate input (the
// adaptive stages run). Usage: madd_bench predicates [calls_per_case]
#include "bench.hpp"

#include "madd/predicates.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

using madd::Point;

double nudge(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

// Times fn over the point list (cycled) and prints ns per call; the sum of
// signs keeps the calls from being optimised away.
template <typename Fn>
void time_case(const char* name, std::size_t calls, std::size_t pts, Fn fn) {
  long long signs = 0;
  const double t0 = madd::bench::now_seconds();
  for (std::size_t i = 0; i < calls; ++i) {
    const double v = fn(i % pts);
    signs += (v > 0.0) - (v < 0.0);
  }
  const double t1 = madd::bench::now_seconds();
  std::printf("%-34s %8.2f ns/call  (sign sum %lld)\n", name, (t1 - t0) * 1e9 / double(calls), signs);
}

int run_predicates(int argc, char** argv) {
  const std::size_t calls = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2000000;
  constexpr std::size_t kPoints = 4096;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> k(-16, 16);
  std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);

  std::vector<Point> rnd(kPoints + 3);
  for (auto& p : rnd) p = {u(rng), u(rng)};
  // Shewchuk's grid: points within 16 ulps of (0.5, 0.5) against y = x.
  std::vector<Point> grid(kPoints);
  for (auto& p : grid) p = {nudge(0.5, k(rng)), nudge(0.5, k(rng))};
  // Near-cocircular: rounded points on the unit circle around (0.1, 0.3), so
  // the coordinate differences are often inexact.
  std::vector<Point> circ(kPoints + 3);
  for (auto& p : circ) {
    const double t = ang(rng);
    p = {nudge(0.1 + std::cos(t), k(rng) / 8), nudge(0.3 + std::sin(t), k(rng) / 8)};
  }

  const Point b{12.0, 12.0};
  const Point c{24.0, 24.0};
  time_case("orient2d random", calls, kPoints,
            [&](std::size_t i) { return madd::orient2d(rnd[i], rnd[i + 1], rnd[i + 2]); });
  time_case("orient2d near-degenerate (grid)", calls, kPoints,
            [&](std::size_t i) { return madd::orient2d(grid[i], b, c); });
  time_case("incircle random", calls, kPoints,
            [&](std::size_t i) { return madd::incircle(rnd[i], rnd[i + 1], rnd[i + 2], rnd[i + 3]); });
  time_case("incircle near-cocircular", calls, kPoints,
            [&](std::size_t i) { return madd::incircle(circ[i], circ[i + 1], circ[i + 2], circ[i + 3]); });
  return 0;
}

const madd::bench::Registration reg("predicates", run_predicates);

}  // namespace
