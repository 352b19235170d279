#pragma once
// Boundary Fiduccia-Mattheyses refinement of a bisection.
//
// Representation choice: weights stay doubles (areas and lengths are real),
// so gains are doubles kept in an indexed binary max-heap with update-key
// (O(log n) per move) rather than in integer bucket lists. Each pass is hill
// climbing with rollback to the best prefix of moves, so float round-off in
// the running cut can only mis-rank states, never corrupt the partition; the
// final cut is recomputed from scratch by the caller.
#include <cstdint>
#include <vector>

#include "graph/graph_detail.hpp"
#include "madd/graph.hpp"

namespace madd::detail {

// An indexed binary max-heap of vertices keyed by gain.
class GainHeap {
public:
  void reset(std::uint32_t vertex_count);
  bool empty() const noexcept { return heap_.empty(); }
  bool contains(std::uint32_t v) const noexcept { return pos_[v] != no_vertex; }
  std::uint32_t top() const noexcept { return heap_.front(); }
  void push(std::uint32_t v, double key);
  void update(std::uint32_t v, double key);
  void remove(std::uint32_t v);
  void clear();  // O(size), not O(vertex_count)

private:
  void sift_up(std::uint32_t i);
  void sift_down(std::uint32_t i);
  void place(std::uint32_t i, std::uint32_t v) {
    heap_[i] = v;
    pos_[v] = i;
  }
  std::vector<std::uint32_t> heap_;
  std::vector<double> key_;  // per vertex
  std::vector<std::uint32_t> pos_;
};

// The balance constraint: side s should weigh target[s] and may weigh at most max[s].
struct Balance {
  double target[2] = {0.0, 0.0};
  double max[2] = {0.0, 0.0};
  double infeasibility(const double w[2]) const noexcept {
    return (w[0] > max[0] ? w[0] - max[0] : 0.0) + (w[1] > max[1] ? w[1] - max[1] : 0.0);
  }
};

// Refines `side` in place with at most `passes` boundary-FM passes. The result
// is never worse than the input in (infeasibility, cut) order. With
// `keep_connected`, only moves that provably keep both sides connected are
// made (RemovalGuard), so connected sides stay connected.
void fm_refine(const Graph& graph, std::vector<std::uint8_t>& side, const Balance& balance, int passes,
               bool keep_connected = false);

}  // namespace madd::detail
