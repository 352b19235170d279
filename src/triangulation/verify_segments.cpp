// verify_triangulation, the PSLG part: every input segment is present as a
// chain of constrained edges (split at vertices lying exactly on it), and
// every constrained edge lies on the segment it names.
#include <algorithm>
#include <string>

#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

namespace {

struct Constrained {
  std::uint32_t from, to, segment;
  bool operator<(const Constrained& o) const noexcept {
    return from < o.from || (from == o.from && (to < o.to || (to == o.to && segment < o.segment)));
  }
};

// x strictly closer to b than cur along the line ab (all three collinear with
// a, b): exact coordinate comparison on an axis where a and b differ.
bool advances(Point a, Point b, Point cur, Point x) noexcept {
  if (a.x != b.x) return b.x > a.x ? (x.x > cur.x && x.x <= b.x) : (x.x < cur.x && x.x >= b.x);
  return b.y > a.y ? (x.y > cur.y && x.y <= b.y) : (x.y < cur.y && x.y >= b.y);
}

} // namespace

void check_segments(const Triangulation& tri, const Pslg& pslg, Verification& v) {
  std::vector<Constrained> edges;
  const auto& P = tri.points;
  for (std::uint32_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& c = tri.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t s = tri.segment_of[t][i];
      if (s == no_index) continue;
      const std::uint32_t a = c[(i + 1) % 3], b = c[(i + 2) % 3];
      if (s >= pslg.segments.size()) {
        v.add("triangle " + std::to_string(t) + " names segment " + std::to_string(s) + ", which does not exist");
        return;
      }
      const Segment& seg = pslg.segments[s];
      if (orient2d(P[seg.a], P[seg.b], P[a]) != 0 || orient2d(P[seg.a], P[seg.b], P[b]) != 0) {
        v.add("constrained edge " + std::to_string(a) + "-" + std::to_string(b) + " is not on segment " +
              std::to_string(s));
      }
      edges.push_back({a, b, s});
      edges.push_back({b, a, s});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::uint32_t s = 0; s < pslg.segments.size(); ++s) {
    const std::uint32_t a = pslg.segments[s].a, b = pslg.segments[s].b;
    std::uint32_t cur = a;
    while (cur != b) {
      auto it = std::lower_bound(edges.begin(), edges.end(), Constrained{cur, 0, 0});
      std::uint32_t step = no_index;
      for (; it != edges.end() && it->from == cur; ++it) {
        if (it->segment == s && advances(P[a], P[b], P[cur], P[it->to])) step = it->to;
      }
      if (step == no_index) {
        v.add("segment " + std::to_string(s) + " (" + std::to_string(a) + "-" + std::to_string(b) +
              ") is not covered by constrained edges after vertex " + std::to_string(cur));
        break;
      }
      cur = step;
    }
  }
}

} // namespace madd::detail
