#pragma once
// What triangulate(pslg, options) must keep, worked out from the faces of the
// segment graph alone, for verify_triangulation to compare the triangles with:
// which pieces of segment must be edges, and the kept area, exactly.
#include <cstdint>
#include <optional>
#include <vector>

#include "kernel/exact_sum.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"

namespace madd::detail {

struct KeptRegion {
  // The segments split at every vertex lying inside one: each piece must be
  // one edge of the triangulation, named by its input segment `source`,
  // when `must_be_edge` (it borders the kept region; a piece inside removed
  // regions only is in no triangle).
  std::vector<Segment> pieces;
  std::vector<std::uint32_t> source;
  std::vector<char> must_be_edge;
  // Twice the kept area: the kept faces (bounded, no hole point in them),
  // plus, with the convex hull, the part of the hull outside every bounded
  // face. Nothing when that part holds a hole point: it can then fall apart
  // into pieces the hole points remove one by one, which the faces alone do
  // not tell (the pieces bordering it are then not checked either).
  std::optional<ExactSum> twice_area;
};

// Precondition: validate_pslg() passed, intersections not allowed.
KeptRegion kept_region(const Pslg& pslg, const TriangulateOptions& options);

}  // namespace madd::detail
