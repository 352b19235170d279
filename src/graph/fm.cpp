// Boundary FM (Fiduccia & Mattheyses 1982, as used by METIS's 2-way refiner).
#include "graph/fm.hpp"

#include <algorithm>
#include <cmath>

namespace madd::detail {

void GainHeap::reset(std::uint32_t vertex_count) {
  heap_.clear();
  key_.assign(vertex_count, 0.0);
  pos_.assign(vertex_count, no_vertex);
}

void GainHeap::push(std::uint32_t v, double key) {
  key_[v] = key;
  heap_.push_back(v);
  pos_[v] = static_cast<std::uint32_t>(heap_.size() - 1);
  sift_up(pos_[v]);
}

void GainHeap::update(std::uint32_t v, double key) {
  const double old = key_[v];
  key_[v] = key;
  if (key > old) sift_up(pos_[v]);
  else if (key < old) sift_down(pos_[v]);
}

void GainHeap::remove(std::uint32_t v) {
  const std::uint32_t i = pos_[v];
  const std::uint32_t last = heap_.back();
  heap_.pop_back();
  pos_[v] = no_vertex;
  if (last == v) return;
  place(i, last);
  sift_up(i);
  sift_down(pos_[last]);
}

void GainHeap::clear() {
  for (const std::uint32_t v : heap_) pos_[v] = no_vertex;
  heap_.clear();
}

void GainHeap::sift_up(std::uint32_t i) {
  const std::uint32_t v = heap_[i];
  while (i > 0) {
    const std::uint32_t parent = (i - 1) / 2;
    if (key_[heap_[parent]] >= key_[v]) break;
    place(i, heap_[parent]);
    i = parent;
  }
  place(i, v);
}

void GainHeap::sift_down(std::uint32_t i) {
  const std::uint32_t v = heap_[i];
  const auto size = static_cast<std::uint32_t>(heap_.size());
  for (;;) {
    std::uint32_t child = 2 * i + 1;
    if (child >= size) break;
    if (child + 1 < size && key_[heap_[child + 1]] > key_[heap_[child]]) ++child;
    if (key_[heap_[child]] <= key_[v]) break;
    place(i, heap_[child]);
    i = child;
  }
  place(i, v);
}

namespace {

// Incremental refinement state: internal/external degree per vertex and the
// boundary set (vertices with a neighbour on the other side).
class Refiner {
public:
  Refiner(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance, bool keep_connected)
      : g_(&graph), side_(&side), bal_(&balance), keep_connected_(keep_connected),
        guard_(keep_connected ? graph.vertex_count() : 0) {
    const auto n = static_cast<std::uint32_t>(graph.vertex_count());
    internal_.assign(n, 0.0);
    external_.assign(n, 0.0);
    ext_count_.assign(n, 0);
    bpos_.assign(n, no_vertex);
    locked_.assign(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
      weight_[side[v]] += graph.vertex_weights[v];
      for (std::uint32_t i = graph.offsets[v]; i < graph.offsets[v + 1]; ++i) {
        if (side[graph.adjacency[i]] == side[v]) {
          internal_[v] += graph.edge_weights[i];
        } else {
          external_[v] += graph.edge_weights[i];
          ++ext_count_[v];
        }
      }
      if (v < n && ext_count_[v] > 0) add_boundary(v);
      cut_ += external_[v];
    }
    cut_ *= 0.5;
    double total_edge = 0.0;
    for (const double w : graph.edge_weights) total_edge += w;
    cut_eps_ = 1e-12 * total_edge;
    heaps_[0].reset(n);
    heaps_[1].reset(n);
  }

  // One pass; returns true when it improved the (infeasibility, cut) order.
  bool pass();

private:
  double gain(std::uint32_t v) const noexcept { return external_[v] - internal_[v]; }
  void add_boundary(std::uint32_t v) {
    bpos_[v] = static_cast<std::uint32_t>(boundary_.size());
    boundary_.push_back(v);
  }
  void drop_boundary(std::uint32_t v) {
    const std::uint32_t last = boundary_.back();
    boundary_[bpos_[v]] = last;
    bpos_[last] = bpos_[v];
    boundary_.pop_back();
    bpos_[v] = no_vertex;
  }
  void sync_boundary(std::uint32_t v) {
    const bool on = ext_count_[v] > 0;
    if (on && bpos_[v] == no_vertex) add_boundary(v);
    else if (!on && bpos_[v] != no_vertex) drop_boundary(v);
  }
  void move(std::uint32_t v, bool update_heaps);
  std::uint32_t choose() const;
  bool better(double infeas, double cut, double dev, double best_infeas, double best_cut, double best_dev) const {
    if (infeas != best_infeas) return infeas < best_infeas;
    if (cut < best_cut - cut_eps_) return true;
    return cut <= best_cut + cut_eps_ && dev < best_dev;
  }

  const Graph* g_;
  std::vector<std::uint8_t>* side_;
  const Balance* bal_;
  bool keep_connected_;
  RemovalGuard guard_;
  std::vector<std::uint32_t> skipped_;
  std::vector<double> internal_, external_;
  std::vector<std::uint32_t> ext_count_, boundary_, bpos_;
  std::vector<std::uint8_t> locked_;
  std::vector<std::uint32_t> moves_;
  GainHeap heaps_[2];
  double weight_[2] = {0.0, 0.0};
  double cut_ = 0.0;
  double cut_eps_ = 0.0;
};

void Refiner::move(std::uint32_t v, bool update_heaps) {
  const Graph& g = *g_;
  auto& side = *side_;
  const std::uint8_t from = side[v];
  const auto to = static_cast<std::uint8_t>(1 - from);
  cut_ -= gain(v);
  weight_[from] -= g.vertex_weights[v];
  weight_[to] += g.vertex_weights[v];
  side[v] = to;
  std::swap(internal_[v], external_[v]);
  ext_count_[v] = (g.offsets[v + 1] - g.offsets[v]) - ext_count_[v];
  sync_boundary(v);
  for (std::uint32_t i = g.offsets[v]; i < g.offsets[v + 1]; ++i) {
    const std::uint32_t u = g.adjacency[i];
    const double w = g.edge_weights[i];
    if (side[u] == to) {
      internal_[u] += w;
      external_[u] -= w;
      --ext_count_[u];
    } else {
      internal_[u] -= w;
      external_[u] += w;
      ++ext_count_[u];
    }
    sync_boundary(u);
    if (!update_heaps || locked_[u]) continue;
    GainHeap& heap = heaps_[side[u]];
    if (ext_count_[u] == 0) {
      if (heap.contains(u)) heap.remove(u);
    } else if (heap.contains(u)) {
      heap.update(u, gain(u));
    } else {
      heap.push(u, gain(u));
    }
  }
}

// Picks the next vertex to move: from an overweight side if there is one;
// otherwise the best-gain top whose move keeps the balance, else the top of
// the side that is heavier relative to its target.
std::uint32_t Refiner::choose() const {
  const Graph& g = *g_;
  const Balance& b = *bal_;
  for (int s = 0; s < 2; ++s) {
    if (weight_[s] > b.max[s] && weight_[s] - b.max[s] >= weight_[1 - s] - b.max[1 - s])
      return heaps_[s].empty() ? no_vertex : heaps_[s].top();
  }
  std::uint32_t best = no_vertex;
  double best_gain = 0.0;
  for (int s = 0; s < 2; ++s) {
    if (heaps_[s].empty()) continue;
    const std::uint32_t v = heaps_[s].top();
    if (weight_[1 - s] + g.vertex_weights[v] > b.max[1 - s]) continue;
    if (best == no_vertex || gain(v) > best_gain) {
      best = v;
      best_gain = gain(v);
    }
  }
  if (best != no_vertex) return best;
  const int heavier = weight_[0] * b.target[1] >= weight_[1] * b.target[0] ? 0 : 1;
  return heaps_[heavier].empty() ? no_vertex : heaps_[heavier].top();
}

bool Refiner::pass() {
  const auto n = static_cast<std::uint32_t>(g_->vertex_count());
  heaps_[0].clear();
  heaps_[1].clear();
  for (const std::uint32_t v : boundary_) heaps_[(*side_)[v]].push(v, gain(v));
  moves_.clear();
  const Balance& b = *bal_;
  double best_infeas = b.infeasibility(weight_);
  double best_cut = cut_;
  double best_dev = std::abs(weight_[0] - b.target[0]);
  std::size_t best_len = 0;
  const auto limit = static_cast<std::size_t>(std::clamp(0.01 * n, 15.0, 100.0));
  while (moves_.size() - best_len < limit) {
    const std::uint32_t v = choose();
    if (v == no_vertex) break;
    heaps_[(*side_)[v]].remove(v);
    locked_[v] = 1;
    if (keep_connected_ && !guard_.removable(*g_, *side_, v)) {
      skipped_.push_back(v);  // may become movable later; retried next pass
      continue;
    }
    move(v, true);
    moves_.push_back(v);
    const double infeas = b.infeasibility(weight_);
    const double dev = std::abs(weight_[0] - b.target[0]);
    if (better(infeas, cut_, dev, best_infeas, best_cut, best_dev)) {
      best_infeas = infeas;
      best_cut = cut_;
      best_dev = dev;
      best_len = moves_.size();
    }
  }
  for (const std::uint32_t v : moves_) locked_[v] = 0;
  for (const std::uint32_t v : skipped_) locked_[v] = 0;
  skipped_.clear();
  while (moves_.size() > best_len) {
    move(moves_.back(), false);
    moves_.pop_back();
  }
  return best_len > 0;
}

}  // namespace

void fm_refine(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance, int passes,
               bool keep_connected) {
  if (graph.vertex_count() < 2) return;
  Refiner refiner(graph, side, balance, keep_connected);
  for (int p = 0; p < passes; ++p) {
    if (!refiner.pass()) break;
  }
}

}  // namespace madd::detail
