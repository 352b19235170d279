// verify_mesh, hanging vertices: no triangle vertex lies strictly inside an
// edge that only one triangle has (the long side of a T-junction, where the
// triangle across was split and this one was not). Exact: orient2d decides
// that the vertex is on the edge's line, coordinate comparisons that it is
// strictly between the ends. The free edges go into the uniform segment grid
// (kernel/segment_grid.hpp), which lists each in every cell it may pass
// through, so each vertex is tested against the few edges of its own cell:
// near-linear in the vertices plus the free edges.
#include <algorithm>
#include <atomic>

#include "kernel/segment_grid.hpp"
#include "kernel/threads.hpp"
#include "madd/predicates.hpp"
#include "quality/parallel_log.hpp"
#include "quality/verify_mesh_detail.hpp"

namespace madd::detail {

namespace {

// p strictly between a and b, given that the three are collinear.
bool strictly_between(Point a, Point b, Point p) noexcept {
  if (a.x != b.x) return std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x);
  return std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y);
}

}  // namespace

void check_hanging_vertices(const Mesh& m, const std::vector<Segment>& boundary, ProblemLog& log, unsigned threads) {
  if (boundary.empty()) return;
  const auto& P = m.points;
  // The vertices triangles use, flagged in parts of the triangles on the
  // threads (a flag set by two parts is set either way: relaxed stores).
  std::vector<std::uint8_t> vertex(P.size(), 0);
  const std::size_t nt = m.triangles.size();
  const std::size_t parts = 4 * std::size_t{thread_count(threads, P.size())};
  for_each_on_threads(parts, threads, [&](std::size_t part) {
    for (std::size_t t = nt * part / parts; t < nt * (part + 1) / parts; ++t)
      for (const std::uint32_t v : m.triangles[t])
        std::atomic_ref<std::uint8_t>(vertex[v]).store(1, std::memory_order_relaxed);
  });
  const SegmentGrid grid(P, boundary);
  log_in_parts(P.size(), parts, threads, log,
               [&](std::size_t, std::size_t begin, std::size_t end, ProblemLog& part_log) {
                 for (auto v = static_cast<std::uint32_t>(begin); v < end; ++v) {
                   if (vertex[v] == 0 || !grid.contains(P[v])) continue;
                   for (const SegmentGrid::Entry& e : grid.cell_at(P[v])) {
                     const Segment& s = boundary[e.item];
                     if (s.a == v || s.b == v) continue;
                     if (orient2d(P[s.a], P[s.b], P[v]) == 0.0 && strictly_between(P[s.a], P[s.b], P[v]))
                       part_log.add("vertex " + std::to_string(v) + " " + point_text(P[v]) + " lies inside edge " +
                                    std::to_string(s.a) + "-" + std::to_string(s.b) + " " + point_text(P[s.a]) + "-" +
                                    point_text(P[s.b]) + ", which only one triangle has (a hanging vertex)");
                   }
                 }
               });
}

}  // namespace madd::detail
