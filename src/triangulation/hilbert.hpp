#pragma once
// Locality-preserving insertion order for incremental Delaunay: a biased
// randomized insertion order (BRIO, Amenta-Choi-Rote 2003) whose rounds are
// each sorted along a Hilbert curve, so that walks stay short and the
// expected running time stays O(n log n) (as CGAL's spatial sort does).
#include <cstdint>
#include <span>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::detail {

// Index of cell (x, y) along the Hilbert curve filling a 2^bits x 2^bits grid
// (bits even, <= 16).
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) noexcept;

// A permutation of 0..points.size()-1: BRIO rounds (each about a quarter of
// the next), each in Hilbert order. Deterministic.
std::vector<std::uint32_t> insertion_order(std::span<const Point> points);

}  // namespace madd::detail
