#pragma once
// The gradation limiter of the size field (--gradation G): lowers the point
// values of the background, never raises one, until the piecewise linear
// field has |grad h| <= G in every inside triangle, so that
// h(x) <= h(y) + G |x - y| along every straight path in the domain (the
// field is continuous and G-Lipschitz on each triangle it crosses).
//
// A label-correcting pass in the spirit of Persson's and Engwirda's
// limiters, our own: points leave a priority queue smallest value first;
// each lowers its neighbours to what an edge allows (h_u <= h_v + G |uv|,
// the Dijkstra step: afterwards no edge is steeper than G), and checks its
// inside triangles: one still steeper than G (an obtuse or skinny triangle
// can be, though its edges are not) has a corner whose lowering flattens it
// (the hat gradients of the three corners sum to zero, so one of them has a
// positive component along the gradient; lowering that corner removes it,
// and what is left, the slope along the opposite edge, is at most G); that
// corner is lowered exactly as far as needed and goes back into the queue.
// Two needles sharing a short edge can take turns lowering its ends by ever
// smaller amounts: a triangle flattened 4 times is instead held to the slope
// below (its edges' limit lowered for good, so that it is within the rate
// whatever its corners become). Values only decrease, so the pass ends;
// should it take more than a fixed
// number of steps, a Dijkstra pass with each edge's slope limited to
// G cos(alpha / 2), alpha the largest angle of its inside triangles, ends
// it (edges no steeper than that give a gradient of at most G in any
// triangle; provably, and only ever lower).
#include "sizing/size_background.hpp"

namespace madd::detail {

struct GradationReport {
  std::size_t pops = 0;  // queue pops of the label-correcting pass
  std::size_t triangle_fixes = 0;
  std::size_t held_triangles = 0;  // flattened too often: held to their safe slope
  bool fell_back = false;          // the edge-limited pass had to finish
};

// Limits background.edge (over the inside triangles) to gradation `rate`.
GradationReport limit_gradation(SizeBackground& background, double rate);

// The largest |grad h| over the inside triangles (0 when none; +infinity
// never: triangles with an infinite corner are left out).
double steepest_gradient(const SizeBackground& background);

}  // namespace madd::detail
