// Smoothing step 2 (paper Sec. 5.1): after the bisection, look at the
// separators next to the chosen ones and keep the better. Moving one G'_D
// vertex next to the cut to the other side replaces the partial separators
// around it by their neighbours, whose ends are the neighbouring boundary
// points; the optimality function is the cut's smoothed cost (the G_D edge
// weights of step 1: length x f0(minimum angle) x end-type bonuses). Every
// G'_D edge is an acceptable partial separator, so no move can break Phi0;
// pinches (Sec. 4.3) and disconnected sides are rejected explicitly.
#include <vector>

#include "split.hpp"

namespace madd::detail {

namespace {

// Whether the vertices of side `s` form one connected piece of G'_D (explicit stack, no recursion).
bool side_connected(const Graph& g, const std::vector<std::uint8_t>& side, std::uint8_t s) {
  const auto n = static_cast<std::uint32_t>(g.vertex_count());
  std::uint32_t start = n, total = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (side[v] != s) continue;
    ++total;
    if (start == n) start = v;
  }
  if (total == 0) return false;
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<std::uint32_t> stack{start};
  seen[start] = 1;
  std::uint32_t reached = 1;
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    for (std::uint32_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k) {
      const std::uint32_t u = g.adjacency[k];
      if (side[u] != s || seen[u]) continue;
      seen[u] = 1;
      ++reached;
      stack.push_back(u);
    }
  }
  return reached == total;
}

// Change of the cut cost if v moved to the other side; `on_cut` tells whether v touches the cut.
double move_gain(const Graph& g, const std::vector<std::uint8_t>& side, std::uint32_t v, bool& on_cut) {
  double gain = 0.0;
  on_cut = false;
  for (std::uint32_t k = g.offsets[v]; k < g.offsets[v + 1]; ++k) {
    if (side[g.adjacency[k]] != side[v]) {
      gain += g.edge_weights[k];
      on_cut = true;
    } else {
      gain -= g.edge_weights[k];
    }
  }
  return gain;
}

} // namespace

void smooth_bisection(const MedialGraph& g, std::size_t boundary_points, std::uint32_t plan, double min_quality,
                      int iterations, std::vector<std::uint8_t>& side, double w[2]) {
  const Graph& cg = g.contracted;
  const auto n = static_cast<std::uint32_t>(cg.vertex_count());
  double scale = 0.0;
  for (double x : cg.edge_weights) scale += x;
  const double eps = 1e-12 * scale;
  for (int it = 0; it < iterations; ++it) {
    bool moved = false;
    for (std::uint32_t v = 0; v < n; ++v) {
      bool on_cut = false;
      if (!(move_gain(cg, side, v, on_cut) > eps) || !on_cut) continue;
      const std::uint8_t s = side[v];
      double nw[2] = {w[0], w[1]};
      nw[s] -= cg.vertex_weights[v];
      nw[1 - s] += cg.vertex_weights[v];
      if (!(nw[s] > 0.0) || balance_quality(plan, nw[0], nw[1]) < min_quality) continue;
      side[v] = static_cast<std::uint8_t>(1 - s);
      // v joins the other side next to one of its vertices, so only side s can come apart.
      if (!side_connected(cg, side, s) || !pinch_conflicts(g, boundary_points, side).empty()) {
        side[v] = s;
        continue;
      }
      w[0] = nw[0];
      w[1] = nw[1];
      moved = true;
    }
    if (!moved) break;
  }
}

} // namespace madd::detail
