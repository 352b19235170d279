// Exact, grid-accelerated search for segments that cross, overlap or touch
// other than at a shared endpoint (docs/formats.md, "Bad input").
#include <algorithm>
#include <string>
#include <unordered_set>

#include "madd/error.hpp"

#include "kernel/containment.hpp"
#include "madd/predicates.hpp"
#include "pslg/validate_detail.hpp"

namespace madd::detail {
namespace {

int sign(double v) noexcept { return (v > 0.0) - (v < 0.0); }
int compare(double a, double b) noexcept { return (a > b) - (a < b); }

// Lexicographic order; for collinear points it is the order along their line.
bool lex_less(Point a, Point b) noexcept { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// s = v-p and t = v-q share endpoint v: they conflict only when collinear and
// leaving v in the same direction; then the nearer of p, q lies on the other.
ContactResult shared_endpoint(Point v, Point p, Point q) {
  if (orient2d(v, p, q) != 0.0) return {};
  if (compare(p.x, v.x) != compare(q.x, v.x) || compare(p.y, v.y) != compare(q.y, v.y)) return {};
  const bool p_nearer = lex_less(v, p) ? !lex_less(q, p) : !lex_less(p, q);
  return {Contact::overlap, p_nearer ? p : q};
}

bool boxes_disjoint(Point a, Point b, Point c, Point d) noexcept {
  return std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
         std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y);
}

ContactResult disjoint_endpoints(Point a, Point b, Point c, Point d) {
  if (boxes_disjoint(a, b, c, d)) return {};
  const int o1 = sign(orient2d(a, b, c)), o2 = sign(orient2d(a, b, d));
  if (o1 != 0 && o1 == o2) return {};
  const int o3 = sign(orient2d(c, d, a)), o4 = sign(orient2d(c, d, b));
  if (o3 != 0 && o3 == o4) return {};
  if (o1 == 0 && o2 == 0) {
    // Collinear: the boxes intersect, so the lexicographic intervals overlap
    // (their endpoints are distinct points, so never in a single point).
    const Point s_min = lex_less(a, b) ? a : b, t_min = lex_less(c, d) ? c : d;
    return {Contact::overlap, lex_less(s_min, t_min) ? t_min : s_min};
  }
  if (o1 == 0) return {Contact::touch, c};
  if (o2 == 0) return {Contact::touch, d};
  if (o3 == 0) return {Contact::touch, a};
  if (o4 == 0) return {Contact::touch, b};
  const Point ab = b - a, cd = d - c;
  const double t = cross(c - a, cd) / cross(ab, cd);
  return {Contact::cross, lerp(a, b, t)};
}

}  // namespace

ContactResult classify_contact(const std::vector<Point>& pts, const Segment& s, const Segment& t) {
  if ((s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a)) return {Contact::overlap, pts[s.a]};
  if (s.a == t.a) return shared_endpoint(pts[s.a], pts[s.b], pts[t.b]);
  if (s.a == t.b) return shared_endpoint(pts[s.a], pts[s.b], pts[t.a]);
  if (s.b == t.a) return shared_endpoint(pts[s.b], pts[s.a], pts[t.b]);
  if (s.b == t.b) return shared_endpoint(pts[s.b], pts[s.a], pts[t.a]);
  return disjoint_endpoints(pts[s.a], pts[s.b], pts[t.a], pts[t.b]);
}

namespace {

// Keeps the conflict that comes first in file order: smallest later index,
// then smallest earlier index, so the report does not depend on cell order.
// Once a conflict is known, the search for an earlier one is capped at
// `budget` more pair tests, so that a hostile file where everything crosses
// everything fails fast instead of taking quadratic time (the report is then
// still deterministic, just not necessarily the first in file order).
struct BestConflict {
  std::optional<SegmentConflict> best;
  std::size_t budget = 0;
  bool done = false;
  bool touches = true;
  bool worth_testing(std::uint32_t i, std::uint32_t j) const noexcept {
    const std::uint32_t later = std::max(i, j), earlier = std::min(i, j);
    return !best || later < best->later || (later == best->later && earlier < best->earlier);
  }
  void offer(const Pslg& p, std::uint32_t i, std::uint32_t j) {
    if (best && --budget == 0) done = true;
    if (!worth_testing(i, j)) return;
    const ContactResult c = classify_contact(p.points, p.segments[i], p.segments[j]);
    if (c.kind != Contact::none && (touches || c.kind != Contact::touch))
      best = SegmentConflict{std::max(i, j), std::min(i, j), c};
  }
};

// All pairs of one cell, pruned by x-extent after sorting when the cell is
// crowded (many short segments next to much longer ones).
void test_cell(const Pslg& p, std::vector<std::uint32_t>& cell, BestConflict& found) {
  if (cell.size() <= 24) {
    for (std::size_t u = 0; u < cell.size() && !found.done; ++u)
      for (std::size_t w = u + 1; w < cell.size(); ++w) found.offer(p, cell[u], cell[w]);
    return;
  }
  const auto min_x = [&](std::uint32_t s) {
    return std::min(p.points[p.segments[s].a].x, p.points[p.segments[s].b].x);
  };
  const auto max_x = [&](std::uint32_t s) {
    return std::max(p.points[p.segments[s].a].x, p.points[p.segments[s].b].x);
  };
  std::sort(cell.begin(), cell.end(), [&](std::uint32_t s, std::uint32_t t) { return min_x(s) < min_x(t); });
  for (std::size_t u = 0; u < cell.size() && !found.done; ++u) {
    const double reach = max_x(cell[u]);
    for (std::size_t w = u + 1; w < cell.size() && min_x(cell[w]) <= reach; ++w) found.offer(p, cell[u], cell[w]);
  }
}

}  // namespace

std::optional<SegmentConflict> find_segment_conflict(const Pslg& pslg, const SegmentGrid& grid, bool touches) {
  BestConflict found;
  found.touches = touches;
  found.budget = 8 * pslg.segments.size() + 4096;
  std::vector<std::uint32_t> cell;
  for (std::uint32_t r = 0; r < grid.rows() && !found.done; ++r) {
    const auto row = grid.row_range(r, 0, grid.cols() - 1);
    for (std::size_t k = 0; k < row.size();) {
      cell.clear();
      const std::uint32_t col = row[k].col;
      for (; k < row.size() && row[k].col == col; ++k) cell.push_back(row[k].item);
      if (cell.size() > 1) test_cell(pslg, cell, found);
    }
  }
  return found.best;
}

namespace {

// Collects every contact once: a pair listed in several cells is classified
// in each, but recorded only the first time.
class ContactCollector {
public:
  ContactCollector(const Pslg& p, std::size_t limit) : p_(p), limit_(limit) {}
  void offer(std::uint32_t i, std::uint32_t j) {
    const std::uint32_t later = std::max(i, j), earlier = std::min(i, j);
    const std::uint64_t key = (std::uint64_t{later} << 32) | earlier;
    if (seen_.count(key) != 0) return;
    const ContactResult c = classify_contact(p_.points, p_.segments[later], p_.segments[earlier]);
    if (c.kind == Contact::none) return;
    seen_.insert(key);
    found_.push_back({later, earlier, c});
    if (found_.size() > limit_) {
      const std::int64_t base = p_.first_index;
      throw InvalidInputError(InputProblem::segments_intersect,
                              "more than " + std::to_string(limit_) +
                                  " pairs of segments intersect; too many to resolve",
                              {later + base, earlier + base}, {c.at});
    }
  }
  std::vector<SegmentConflict> take() {
    std::sort(found_.begin(), found_.end(), [](const SegmentConflict& a, const SegmentConflict& b) {
      return a.later < b.later || (a.later == b.later && a.earlier < b.earlier);
    });
    return std::move(found_);
  }

private:
  const Pslg& p_;
  std::size_t limit_;
  std::unordered_set<std::uint64_t> seen_;
  std::vector<SegmentConflict> found_;
};

}  // namespace

std::vector<SegmentConflict> all_segment_contacts(const Pslg& pslg, const SegmentGrid& grid, std::size_t limit) {
  ContactCollector collector(pslg, limit);
  std::vector<std::uint32_t> cell;
  const auto min_x = [&](std::uint32_t s) {
    return std::min(pslg.points[pslg.segments[s].a].x, pslg.points[pslg.segments[s].b].x);
  };
  const auto max_x = [&](std::uint32_t s) {
    return std::max(pslg.points[pslg.segments[s].a].x, pslg.points[pslg.segments[s].b].x);
  };
  for (std::uint32_t r = 0; r < grid.rows(); ++r) {
    const auto row = grid.row_range(r, 0, grid.cols() - 1);
    for (std::size_t k = 0; k < row.size();) {
      cell.clear();
      const std::uint32_t col = row[k].col;
      for (; k < row.size() && row[k].col == col; ++k) cell.push_back(row[k].item);
      // Pruned by x-extent after sorting, as test_cell() does.
      std::sort(cell.begin(), cell.end(), [&](std::uint32_t s, std::uint32_t t) { return min_x(s) < min_x(t); });
      for (std::size_t u = 0; u < cell.size(); ++u) {
        const double reach = max_x(cell[u]);
        for (std::size_t w = u + 1; w < cell.size() && min_x(cell[w]) <= reach; ++w) collector.offer(cell[u], cell[w]);
      }
    }
  }
  return collector.take();
}

std::optional<std::uint32_t> segment_under(const Pslg& pslg, const SegmentGrid& grid, Point p) {
  if (!grid.contains(p)) return std::nullopt;
  for (const auto& entry : grid.cell_at(p)) {
    const std::uint32_t s = entry.item;  // ascending within a cell: the first hit is the smallest
    if (on_segment(pslg.points[pslg.segments[s].a], pslg.points[pslg.segments[s].b], p)) return s;
  }
  return std::nullopt;
}

bool lone_vertex_on_segment(const Pslg& pslg, const SegmentGrid& grid) {
  std::vector<std::uint8_t> on_some(pslg.points.size(), 0);
  for (const Segment& s : pslg.segments) on_some[s.a] = on_some[s.b] = 1;
  for (std::uint32_t v = 0; v < pslg.points.size(); ++v)
    if (!on_some[v] && segment_under(pslg, grid, pslg.points[v])) return true;
  return false;
}

}  // namespace madd::detail
