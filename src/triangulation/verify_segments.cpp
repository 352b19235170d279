// verify_triangulation, the PSLG part: every input segment bordering the kept
// region is present as a chain of constrained edges (split at the vertices
// lying exactly on it), and every constrained edge lies on the segment it names.
#include <algorithm>
#include <string>

#include "madd/predicates.hpp"
#include "madd/triangulation.hpp"
#include "triangulation/kept_region.hpp"

namespace madd::detail {

namespace {

struct Constrained {
  std::uint32_t from, to, segment;
  bool operator<(const Constrained& o) const noexcept {
    return from < o.from || (from == o.from && (to < o.to || (to == o.to && segment < o.segment)));
  }
};

}  // namespace

void check_segments(const Triangulation& tri, const Pslg& pslg, const KeptRegion& region, Verification& v) {
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
      edges.push_back({std::min(a, b), std::max(a, b), s});
    }
  }
  std::sort(edges.begin(), edges.end());
  // Each piece (the part of a segment between consecutive vertices on it)
  // bordering the kept region must be one edge, constrained by its segment.
  for (std::uint32_t k = 0; k < region.pieces.size(); ++k) {
    if (!region.must_be_edge[k]) continue;
    const std::uint32_t a = std::min(region.pieces[k].a, region.pieces[k].b);
    const std::uint32_t b = std::max(region.pieces[k].a, region.pieces[k].b);
    const std::uint32_t s = region.source[k];
    if (std::binary_search(edges.begin(), edges.end(), Constrained{a, b, s})) continue;
    v.add("segment " + std::to_string(s) + " (" + std::to_string(pslg.segments[s].a) + "-" +
          std::to_string(pslg.segments[s].b) + ") is not covered by constrained edges: its piece " + std::to_string(a) +
          "-" + std::to_string(b) + " is missing");
    return;
  }
}

}  // namespace madd::detail
