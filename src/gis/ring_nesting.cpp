// Ring nesting for the shapefile reader (ring_nesting.hpp): bounding boxes
// prune the candidates, exact point location decides.
#include "gis/ring_nesting.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "kernel/box.hpp"
#include "kernel/containment.hpp"
#include "kernel/rings.hpp"
#include "kernel/uniform_grid.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {
namespace {

// Rings of up to this many vertices are searched edge by edge; larger ones
// file their edges by rows first, as every ring of a record may query them.
constexpr std::size_t small_ring = 32;

// A box of more grid cells than this is not filed in the cells but kept in a
// list that every query meets (the ocean around a thousand islands).
constexpr std::uint64_t big_box_cells = 16;

// kernel/rings.cpp's crossing rule (its winding number): the ray from p
// towards +x, half-open in y, orient2d deciding the side.
int crossing(Point a, Point b, Point p) noexcept {
  if (a.y <= p.y) return b.y > p.y && orient2d(a, b, p) > 0.0 ? 1 : 0;
  return b.y <= p.y && orient2d(a, b, p) < 0.0 ? -1 : 0;
}

// A grid of one column and `rows` rows over [y0, y1]; one row when that span
// is empty or overflows.
UniformGrid row_grid(double y0, double y1, std::uint32_t rows) {
  const double h = (y1 - y0) / static_cast<double>(rows);
  if (!(h > 0.0) || !std::isfinite(h)) return UniformGrid({0.0, y0}, 1.0, 1.0, 1, 1);
  return UniformGrid({0.0, y0}, 1.0, h, 1, rows);
}

// One large ring's edges filed by rows of y: locate_in_ring's answer, from
// the edges whose y span holds the point.
class EdgeRows {
public:
  explicit EdgeRows(std::span<const Point> ring);
  RingLocation locate(Point p) const noexcept;

private:
  Point after(std::size_t k) const noexcept { return ring_[k + 1 == ring_.size() ? 0 : k + 1]; }
  std::span<const Point> ring_;
  double y0_ = 0.0, y1_ = 0.0;
  UniformGrid rows_;
};

EdgeRows::EdgeRows(std::span<const Point> ring) : ring_(ring) {
  const Box box = bounding_box(ring);
  y0_ = box.lo.y;
  y1_ = box.hi.y;
  const std::size_t m = ring.size();
  const auto each_edge = [&](auto&& f) {
    for (std::size_t k = 0; k < m; ++k) f(k, std::min(ring_[k].y, after(k).y), std::max(ring_[k].y, after(k).y));
  };
  // About two edges a row (as WindingIndex), but fewer rows while the edges
  // would be filed more than 4 times each on average (long edges spanning
  // many rows, a comb's teeth): the index stays linear in the ring's size.
  auto rows = static_cast<std::uint32_t>(std::clamp<std::size_t>(m / 2, 1, std::size_t{1} << 16));
  for (;;) {
    rows_ = row_grid(y0_, y1_, rows);
    std::uint64_t filed = 0;
    each_edge([&](std::size_t, double lo, double hi) { filed += rows_.row_of(hi) - rows_.row_of(lo) + 1; });
    if (filed <= 4 * std::uint64_t{m} || rows == 1) break;
    rows /= 2;
  }
  rows_.fill(static_cast<std::uint32_t>(m), UniformGrid::Index::by_cell, [&](std::uint32_t k, auto&& add) {
    rows_.box_cells({0.0, std::min(ring_[k].y, after(k).y)}, {0.0, std::max(ring_[k].y, after(k).y)}, add);
  });
}

RingLocation EdgeRows::locate(Point p) const noexcept {
  if (!(p.y >= y0_ && p.y <= y1_)) return RingLocation::outside;
  int winding = 0;
  for (const UniformGrid::Entry& e : rows_.cell_at({0.0, p.y})) {
    const Point a = ring_[e.item], b = after(e.item);
    if (on_segment(a, b, p)) return RingLocation::on_ring;
    winding += crossing(a, b, p);
  }
  return winding != 0 ? RingLocation::inside : RingLocation::outside;
}

// The rings whose boxes may hold a point: small boxes filed in every grid
// cell they cover, big ones in a list every query meets.
class HolderGrid {
public:
  explicit HolderGrid(std::span<const Box> boxes);
  template <class Visit>
  void candidates(Point p, Visit&& visit) const {
    for (const std::uint32_t j : big_) visit(j);
    for (const UniformGrid::Entry& e : grid_.cell_at(p)) visit(e.item);
  }

private:
  std::uint64_t cells(const Box& b) const noexcept {
    return std::uint64_t{grid_.col_of(b.hi.x) - grid_.col_of(b.lo.x) + 1} *
           (grid_.row_of(b.hi.y) - grid_.row_of(b.lo.y) + 1);
  }
  UniformGrid grid_;
  std::vector<std::uint32_t> big_;
};

HolderGrid::HolderGrid(std::span<const Box> boxes) {
  Box all;
  for (const Box& b : boxes) all.add(b.lo), all.add(b.hi);
  // About one cell a ring.
  const auto side = static_cast<std::uint32_t>(std::clamp(std::sqrt(static_cast<double>(boxes.size())), 1.0, 1024.0));
  std::uint32_t cols = side, rows = side;
  double w = all.width() / side, h = all.height() / side;
  if (!(w > 0.0) || !std::isfinite(w)) w = 1.0, cols = 1;
  if (!(h > 0.0) || !std::isfinite(h)) h = 1.0, rows = 1;
  grid_ = UniformGrid(all.lo, w, h, cols, rows);
  const auto count = static_cast<std::uint32_t>(boxes.size());
  grid_.fill(count, UniformGrid::Index::by_cell, [&](std::uint32_t i, auto&& add) {
    if (cells(boxes[i]) <= big_box_cells) grid_.box_cells(boxes[i].lo, boxes[i].hi, add);
  });
  for (std::uint32_t i = 0; i < count; ++i)
    if (cells(boxes[i]) > big_box_cells) big_.push_back(i);
}

bool box_holds(const Box& outer, const Box& inner) noexcept {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y;
}

// Whether `ring` lies in the ring that `locate` answers for (the header's
// rule: the first vertex off it decides, else the first edge midpoint off it).
template <class Locate>
bool lies_in(std::span<const Point> ring, Locate&& locate) {
  for (const Point p : ring) {
    const RingLocation at = locate(p);
    if (at != RingLocation::on_ring) return at == RingLocation::inside;
  }
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k], b = ring[k + 1 == ring.size() ? 0 : k + 1];
    const RingLocation at = locate(Point{0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y});
    if (at != RingLocation::on_ring) return at == RingLocation::inside;
  }
  return false;
}

// Rings ordered by area (NaN, from an overflow, as infinite), then index: a
// ring's parent comes later in this order, so the parents form a tree.
std::vector<std::uint32_t> area_order(std::span<const std::vector<Point>> rings) {
  std::vector<double> key(rings.size());
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const double area = std::abs(ring_signed_area(RingView(rings[i])));
    key[i] = std::isnan(area) ? HUGE_VAL : area;
  }
  std::vector<std::uint32_t> order(rings.size());
  std::iota(order.begin(), order.end(), 0U);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
  return order;
}

}  // namespace

RingNesting nest_rings(std::span<const std::vector<Point>> rings) {
  const auto n = static_cast<std::uint32_t>(rings.size());
  RingNesting out{std::vector<std::uint32_t>(n, no_index), std::vector<std::uint32_t>(n, 0)};
  if (n < 2) return out;
  const std::vector<std::uint32_t> order = area_order(rings);
  std::vector<std::uint32_t> rank(n);
  for (std::uint32_t k = 0; k < n; ++k) rank[order[k]] = k;
  std::vector<Box> boxes(n);
  for (std::uint32_t i = 0; i < n; ++i) boxes[i] = bounding_box(rings[i]);
  const HolderGrid holders(boxes);
  std::vector<std::optional<EdgeRows>> indexed(n);  // built on a large ring's first query
  const auto locate = [&](std::uint32_t j, Point p) {
    if (rings[j].size() <= small_ring) return locate_in_ring(RingView(rings[j]), p);
    if (!indexed[j]) indexed[j].emplace(rings[j]);
    return indexed[j]->locate(p);
  };
  std::vector<std::uint32_t> candidates;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (rings[i].empty()) continue;
    candidates.clear();
    holders.candidates(rings[i][0], [&](std::uint32_t j) {
      if (rank[j] > rank[i] && box_holds(boxes[j], boxes[i])) candidates.push_back(j);
    });
    std::sort(candidates.begin(), candidates.end(),
              [&](std::uint32_t a, std::uint32_t b) { return rank[a] < rank[b]; });
    for (const std::uint32_t j : candidates) {
      if (!lies_in(rings[i], [&](Point p) { return locate(j, p); })) continue;
      out.parent[i] = j;
      break;
    }
  }
  // Parents come later in the area order: deepest last, each after its parent.
  for (std::uint32_t k = n; k-- > 0;) {
    const std::uint32_t i = order[k];
    if (out.parent[i] != no_index) out.depth[i] = out.depth[out.parent[i]] + 1;
  }
  return out;
}

}  // namespace madd::detail
