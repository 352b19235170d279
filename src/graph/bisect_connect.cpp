// Connectivity repair after refinement. MADD needs each half of a split to be
// one connected piece of the domain (paper Sec. 4: a subdomain is a connected
// region), so when the input graph is connected, both sides must be too.
#include <algorithm>

#include "graph/bisect_detail.hpp"

namespace madd::detail {

namespace {

// One round: flips every stray component (not the heaviest of its side) that
// touches the other side's heaviest component; if none does, flips the
// lightest stray. Returns false when each side is already one component.
bool flip_strays(const Graph& g, std::vector<std::uint8_t>& side) {
  const Components comps = connected_components(g, side.data());
  if (comps.count <= 2) return false;
  const auto n = static_cast<std::uint32_t>(g.vertex_count());
  std::vector<double> weight(comps.count, 0.0);
  std::vector<std::uint8_t> comp_side(comps.count, 0);
  for (std::uint32_t v = 0; v < n; ++v) {
    weight[comps.label[v]] += g.vertex_weights[v];
    comp_side[comps.label[v]] = side[v];
  }
  std::uint32_t core[2] = {no_vertex, no_vertex};
  for (std::uint32_t c = 0; c < comps.count; ++c) {
    std::uint32_t& k = core[comp_side[c]];
    if (k == no_vertex || weight[c] > weight[k]) k = c;
  }
  if (core[0] == no_vertex || core[1] == no_vertex) return false;  // one side holds everything: nothing to merge into
  std::vector<std::uint8_t> flip(comps.count, 0);
  bool any = false;
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t c = comps.label[v];
    if (c == core[side[v]] || flip[c]) continue;
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
      if (comps.label[g.adjacency[i]] == core[1 - side[v]]) {
        flip[c] = 1;
        any = true;
        break;
      }
    }
  }
  if (!any) {
    std::uint32_t lightest = no_vertex;
    for (std::uint32_t c = 0; c < comps.count; ++c) {
      if (c == core[0] || c == core[1]) continue;
      if (lightest == no_vertex || weight[c] < weight[lightest]) lightest = c;
    }
    if (lightest == no_vertex) return false;  // unreachable: count > 2 leaves a stray
    flip[lightest] = 1;
  }
  for (std::uint32_t v = 0; v < n; ++v) {
    if (flip[comps.label[v]]) side[v] = static_cast<std::uint8_t>(1 - side[v]);
  }
  return true;
}

// Moves boundary vertices off an overweight side, best gain first, keeping
// both sides connected: the receiving side stays connected because the vertex
// touches it; the giving side because a bounded BFS inside it, avoiding the
// vertex, reaches all of the vertex's same-side neighbours.
class Rebalancer {
public:
  Rebalancer(const Graph& g, std::vector<std::uint8_t>& side) : g_(&g), side_(&side), guard_(g.vertex_count()) {
    heap_.reset(static_cast<std::uint32_t>(g.vertex_count()));
  }
  void run(const Balance& b);

private:
  double gain(std::uint32_t v) const;
  bool touches(std::uint32_t v, std::uint8_t s) const;
  const Graph* g_;
  std::vector<std::uint8_t>* side_;
  RemovalGuard guard_;
  GainHeap heap_;
};

double Rebalancer::gain(std::uint32_t v) const {
  const Graph& g = *g_;
  double gsum = 0.0;
  for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i)
    gsum += (*side_)[g.adjacency[i]] != (*side_)[v] ? g.edge_weights[i] : -g.edge_weights[i];
  return gsum;
}

bool Rebalancer::touches(std::uint32_t v, std::uint8_t s) const {
  const Graph& g = *g_;
  for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i)
    if ((*side_)[g.adjacency[i]] == s) return true;
  return false;
}

void Rebalancer::run(const Balance& b) {
  const Graph& g = *g_;
  auto& side = *side_;
  const auto n = static_cast<std::uint32_t>(g.vertex_count());
  double w[2] = {0.0, 0.0};
  std::uint32_t count[2] = {0, 0};
  for (std::uint32_t v = 0; v < n; ++v) {
    w[side[v]] += g.vertex_weights[v];
    ++count[side[v]];
  }
  const std::uint8_t s = w[0] > b.max[0] ? 0 : (w[1] > b.max[1] ? 1 : 2);
  if (s == 2) return;
  const auto t = static_cast<std::uint8_t>(1 - s);
  for (std::uint32_t v = 0; v < n; ++v)
    if (side[v] == s && touches(v, t)) heap_.push(v, gain(v));
  while (w[s] > b.max[s] && !heap_.empty() && count[s] > 1) {
    const std::uint32_t v = heap_.top();
    heap_.remove(v);
    const double vw = g.vertex_weights[v];
    // Never overshoot into making the other side worse than this one is.
    if (w[t] + vw > b.max[t] && w[t] + vw - b.max[t] >= w[s] - b.max[s]) continue;
    if (!guard_.removable(g, side, v)) continue;
    side[v] = t;
    w[s] -= vw;
    w[t] += vw;
    --count[s];
    for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
      const std::uint32_t u = g.adjacency[i];
      if (side[u] != s) continue;
      if (heap_.contains(u)) heap_.update(u, gain(u));
      else heap_.push(u, gain(u));
    }
  }
}

}  // namespace

void repair_connectivity(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  if (n < 2) return;
  const bool has[2] = {std::find(side.begin(), side.end(), 0) != side.end(),
                       std::find(side.begin(), side.end(), 1) != side.end()};
  if (!has[0] || !has[1]) {
    // Seed the empty side with the last vertex in BFS order: a leaf of the BFS
    // tree, so the rest stays connected.
    std::vector<std::uint8_t> seen(n, 0);
    std::vector<std::uint32_t> queue(1, 0);
    seen[0] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for (std::uint32_t i = graph.offsets[queue[head]]; i < graph.offsets[queue[head] + 1]; ++i) {
        const std::uint32_t u = graph.adjacency[i];
        if (!seen[u]) {
          seen[u] = 1;
          queue.push_back(u);
        }
      }
    }
    side[queue.back()] = has[0] ? 1 : 0;
  }
  // Each round removes at least one component, so this terminates.
  while (flip_strays(graph, side)) {}
  Rebalancer(graph, side).run(balance);
}

}  // namespace madd::detail
