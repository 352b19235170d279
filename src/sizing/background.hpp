#pragma once
// The background triangulation the size field is piecewise linear on
// (size_field.hpp, SizeBackground), built once per run:
// - Steiner points at the centres of the leaves of a graded quadtree over
//   the domain's bounding square: a cell is split while it is larger than
//   `cell_over_h` times the raw field h at its centre (raw_field.hpp), so
//   that the background follows the field (fine at the coast, coarse
//   offshore); cells outside the domain are dropped, and a leaf's centre is
//   kept only in the domain and at least `keep_away` cell sizes from every
//   segment (no sliver against a segment);
// - the domain's segments split (by halving) until each piece is at most
//   `cell_over_h` times the smaller h at its two ends;
// - one constrained Delaunay triangulation of all of it (madd::triangulate,
//   the convex hull kept and no hole removed, so that a walk from anywhere
//   reaches any point), and `inside` flagged by a flood from the hull and
//   from the hole points across the edges that are no segment.
// The total of Steiner points is capped (`budget`): a field asking for more
// (hmin tiny against the domain) gets a coarser background, not an
// unbounded one; the safety bound (distance_bound.hpp) holds on any
// background, only less tightly.
#include <cstddef>
#include <vector>

#include "sizing/coast.hpp"
#include "sizing/raw_field.hpp"
#include "sizing/size_background.hpp"

namespace madd::detail {

struct BackgroundOptions {
  double cell_over_h = 4.0;
  double keep_away = 0.25;
  std::size_t budget = std::size_t{1} << 19;
  // The quadtree's cells of a level are measured on this many threads (0:
  // one per core); the points are the same for any count.
  unsigned threads = 1;
};

struct BackgroundBuild {
  SizeBackground background;       // edge: the raw field h at each point
  std::vector<RawSample> samples;  // per point: the raw terms there
  std::size_t steiner_points = 0;  // of the quadtree (the last points)
};

BackgroundBuild build_background(const Coast& coast, const RawField& raw, const BackgroundOptions& options = {});

}  // namespace madd::detail
