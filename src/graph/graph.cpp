// CSR graph construction and the small graph algorithms the bisector needs.
#include <algorithm>
#include <cassert>
#include <numeric>

#include "graph/graph_detail.hpp"
#include "madd/graph.hpp"

namespace madd {

Graph make_graph(std::vector<double> vertex_weights, const std::vector<WeightedEdge>& edges) {
  const auto n = static_cast<std::uint32_t>(vertex_weights.size());
  // Bucket both directions of every edge by source (counting sort), then merge
  // duplicates per vertex with a last-seen marker.
  std::vector<std::uint32_t> count(n + 1, 0);
  for (const auto& e : edges) {
    assert(e.u < n && e.v < n);
    if (e.u == e.v) continue;
    ++count[e.u + 1];
    ++count[e.v + 1];
  }
  std::partial_sum(count.begin(), count.end(), count.begin());
  std::vector<std::uint32_t> nbr(count[n]);
  std::vector<double> wgt(count[n]);
  std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
  for (const auto& e : edges) {
    if (e.u == e.v) continue;
    nbr[fill[e.u]] = e.v;
    wgt[fill[e.u]++] = e.weight;
    nbr[fill[e.v]] = e.u;
    wgt[fill[e.v]++] = e.weight;
  }
  Graph g;
  g.vertex_weights = std::move(vertex_weights);
  g.offsets.assign(n + 1, 0);
  g.adjacency.reserve(nbr.size());
  g.edge_weights.reserve(nbr.size());
  std::vector<std::uint32_t> slot(n, detail::no_vertex);
  for (std::uint32_t u = 0; u < n; ++u) {
    const auto begin = static_cast<std::uint32_t>(g.adjacency.size());
    for (std::uint32_t i = count[u]; i < count[u + 1]; ++i) {
      const std::uint32_t v = nbr[i];
      if (slot[v] != detail::no_vertex && slot[v] >= begin) {
        g.edge_weights[slot[v]] += wgt[i];
        continue;
      }
      slot[v] = static_cast<std::uint32_t>(g.adjacency.size());
      g.adjacency.push_back(v);
      g.edge_weights.push_back(wgt[i]);
    }
    g.offsets[u + 1] = static_cast<std::uint32_t>(g.adjacency.size());
  }
  return g;
}

namespace detail {

Components connected_components(const Graph& graph, const std::uint8_t* side) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  Components c;
  c.label.assign(n, no_vertex);
  std::vector<std::uint32_t> queue;
  queue.reserve(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (c.label[s] != no_vertex) continue;
    const std::uint32_t id = c.count++;
    c.label[s] = id;
    queue.clear();
    queue.push_back(s);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t u = queue[head];
      for (std::uint32_t i = graph.offsets[u]; i < graph.offsets[u + 1]; ++i) {
        const std::uint32_t v = graph.adjacency[i];
        if (c.label[v] != no_vertex || (side != nullptr && side[v] != side[u])) continue;
        c.label[v] = id;
        queue.push_back(v);
      }
    }
  }
  return c;
}

bool is_connected(const Graph& graph) { return connected_components(graph).count <= 1; }

double cut_weight(const Graph& graph, std::span<const std::uint8_t> side) {
  double cut = 0.0;
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  for (std::uint32_t u = 0; u < n; ++u) {
    for (std::uint32_t i = graph.offsets[u]; i < graph.offsets[u + 1]; ++i) {
      const std::uint32_t v = graph.adjacency[i];
      if (u < v && side[u] != side[v]) cut += graph.edge_weights[i];
    }
  }
  return cut;
}

Graph contract(const Graph& graph, std::span<const std::uint32_t> map, std::uint32_t coarse_count) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  // Members of each coarse vertex, by counting sort (keeps fine order).
  std::vector<std::uint32_t> start(coarse_count + 1, 0);
  for (std::uint32_t v = 0; v < n; ++v) ++start[map[v] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> members(n);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t v = 0; v < n; ++v) members[fill[map[v]]++] = v;
  }
  Graph coarse;
  coarse.offsets.assign(coarse_count + 1, 0);
  coarse.vertex_weights.assign(coarse_count, 0.0);
  coarse.adjacency.reserve(graph.adjacency.size());  // an upper bound: no regrowth copies
  coarse.edge_weights.reserve(graph.adjacency.size());
  std::vector<std::uint32_t> slot(coarse_count, no_vertex);
  for (std::uint32_t c = 0; c < coarse_count; ++c) {
    const auto begin = static_cast<std::uint32_t>(coarse.adjacency.size());
    for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
      const std::uint32_t v = members[k];
      coarse.vertex_weights[c] += graph.vertex_weights[v];
      append_merged_edges(graph, map, v, c, begin, slot, coarse);
    }
    coarse.offsets[c + 1] = static_cast<std::uint32_t>(coarse.adjacency.size());
  }
  return coarse;
}

Graph induced_subgraph(const Graph& graph, std::span<const std::uint32_t> vertices) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  std::vector<std::uint32_t> local(n, no_vertex);
  for (std::uint32_t i = 0; i < vertices.size(); ++i) local[vertices[i]] = i;
  Graph sub;
  sub.offsets.assign(vertices.size() + 1, 0);
  sub.vertex_weights.reserve(vertices.size());
  for (std::uint32_t i = 0; i < vertices.size(); ++i) {
    const std::uint32_t v = vertices[i];
    sub.vertex_weights.push_back(graph.vertex_weights[v]);
    for (std::uint32_t e = graph.offsets[v]; e < graph.offsets[v + 1]; ++e) {
      const std::uint32_t u = local[graph.adjacency[e]];
      if (u == no_vertex) continue;
      sub.adjacency.push_back(u);
      sub.edge_weights.push_back(graph.edge_weights[e]);
    }
    sub.offsets[i + 1] = static_cast<std::uint32_t>(sub.adjacency.size());
  }
  return sub;
}

bool RemovalGuard::removable(const Graph& g, std::span<const std::uint8_t> side, std::uint32_t v, std::size_t budget) {
  const std::uint8_t s = side[v];
  if (clock_ > 0xfffffff0u) {  // wrap-around: restart the stamps
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    clock_ = 0;
  }
  const std::uint32_t target = ++clock_;  // "a neighbour still to reach"
  std::uint32_t need = 0, start = no_vertex;
  for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
    const std::uint32_t u = g.adjacency[i];
    if (side[u] != s || stamp_[u] == target) continue;
    stamp_[u] = target;
    ++need;
    start = u;
  }
  if (need <= 1) return need == 1;
  const std::uint32_t seen = ++clock_;
  queue_.assign(1, start);
  std::uint32_t reached = 1;
  stamp_[start] = seen;
  stamp_[v] = seen;
  for (std::size_t head = 0; head < queue_.size() && head < budget; ++head) {
    const std::uint32_t x = queue_[head];
    for (std::uint32_t i = g.offsets[x]; i < g.offsets[x + 1]; ++i) {
      const std::uint32_t u = g.adjacency[i];
      if (side[u] != s || stamp_[u] == seen) continue;
      if (stamp_[u] == target && ++reached == need) return true;
      stamp_[u] = seen;
      queue_.push_back(u);
    }
  }
  return false;
}

bool sides_connected(const Graph& graph, std::span<const std::uint8_t> side) {
  const Components c = connected_components(graph, side.data());
  if (c.count != 2) return false;
  // Two components: connected sides unless both lie on one side.
  for (std::size_t v = 0; v < side.size(); ++v)
    if (side[v] != side[0]) return true;
  return false;
}

std::vector<std::uint32_t> random_permutation(std::uint32_t n, SplitMix64& rng) {
  std::vector<std::uint32_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0u);
  for (std::uint32_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  return perm;
}

}  // namespace detail
}  // namespace madd
