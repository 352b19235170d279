#pragma once
// Boundary refinement of one face (paper Sec. 3): the working points a split
// triangulates. They enter the global subdivision only where a separator ends.
#include <array>
#include <cstdint>
#include <vector>

#include "medial/medial_detail.hpp"
#include "madd/pslg.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct FaceDomain {
  Pslg pslg;                           // the refined rings and one hole point per hole ring
  std::vector<BoundaryLinks> links;    // per working point: ring neighbours, Sec. 5.1 bonus
  std::vector<EndRef> refs;            // per working point: where it lies in the subdivision
  std::vector<std::uint32_t> ring_of;  // per working point: the face ring it lies on (0 off the rings)
  // Interior constraints (docs/algorithm.md, "Interior segments"): pslg's
  // segments from ring_segments on are the interior pieces' working edges;
  // inner_edge[s - ring_segments] = {piece (index into Face::inner_segments),
  // the edge's number along the piece's direction}; inner_edges_of[piece]:
  // how many; isolated[k]: where Face::inner_points[k] is. Isolated points
  // are not triangulated: as vertices they would pin every triangle around
  // them into one G'_D vertex (no separator may end at one), which unbalances
  // the split; the bisection only keeps every separator off them.
  std::size_t ring_segments = 0;
  std::vector<std::array<std::uint32_t, 2>> inner_edge;
  std::vector<std::uint32_t> inner_edges_of;
  std::vector<Point> isolated;
  std::vector<std::uint32_t> pinned;  // with pin_isolated instead: their working points
};

// Divides every ring edge of `face`, and every interior piece inside it, into
// ceil(length / spacing) equal pieces (endpoints kept exactly). Existing vertices get the type-1 bonus of
// Sec. 5.1, midpoints of existing edges the type-2 bonus.
// With boundary weights (Sec. 5.2 case 1, one per subdivision vertex), an edge
// whose end weights exceed the face's mean vertex weight gets up to
// `adaptive_level` times more pieces (in proportion to its weight over the
// mean): heavier segments are refined more, the paper's adaptive refine level
// (Table I, setAdaptiveRefineLevel; DecomposeOptions::adaptive_boundary_refinement).
// `pin_isolated`: the face's isolated points become working points where no
// separator may end (FaceDomain::pinned), the fallback when keeping the
// separators off them finds none (a point exactly where every separator of
// a symmetric face passes, such as the centre of a square).
FaceDomain refine_face(const Subdivision& sub, std::uint32_t face, double spacing,
                       const std::vector<double>* point_weights = nullptr, double adaptive_level = 4.0,
                       bool pin_isolated = false);

// Perimeter of a face: total length of its rings.
double face_perimeter(const Subdivision& sub, std::uint32_t face);

}  // namespace madd::detail
