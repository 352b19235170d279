// No two segments of a decomposition cross, overlap or touch away from a
// shared endpoint. Reuses validate()'s exact contact test and uniform grid
// (kernel/segment_grid.hpp, pslg/validate_detail.hpp), so there is one grid in madd.
#include "madd/pslg.hpp"
#include "pslg/validate_detail.hpp"
#include "quality/verify_decomposition_detail.hpp"

namespace madd::detail {

void check_segments_disjoint(const std::vector<Point>& points, const std::vector<Segment>& segments, ProblemLog& log) {
  Pslg graph;
  graph.points = points;
  graph.segments = segments;
  const SegmentGrid grid(graph.points, graph.segments);
  const std::optional<SegmentConflict> conflict = find_segment_conflict(graph, grid);
  if (!conflict) return;
  const Segment& s = segments[conflict->earlier];
  const Segment& t = segments[conflict->later];
  const char* how = conflict->contact.kind == Contact::cross   ? "cross"
                    : conflict->contact.kind == Contact::touch ? "touch away from a shared endpoint (T-junction)"
                                                               : "overlap";
  log.add("segments " + std::to_string(conflict->earlier) + " " + point_text(points[s.a]) + "-" +
          point_text(points[s.b]) + " and " + std::to_string(conflict->later) + " " + point_text(points[t.a]) + "-" +
          point_text(points[t.b]) + " " + how + " at " + point_text(conflict->contact.at) +
          " (the first such pair; there may be more)");
}

}  // namespace madd::detail
