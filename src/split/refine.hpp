#pragma once
// Boundary refinement of one face (paper Sec. 3): the working points a split
// triangulates. They enter the global subdivision only where a separator ends.
#include <cstdint>
#include <vector>

#include "madd/medial.hpp"
#include "madd/pslg.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct FaceDomain {
  Pslg pslg;                         // the refined rings and one hole point per hole ring
  std::vector<BoundaryLinks> links;  // per working point: ring neighbours, Sec. 5.1 bonus
  std::vector<EndRef> refs;          // per working point: where it lies in the subdivision
  std::vector<std::uint32_t> ring_of;  // per working point: the face ring it lies on
};

// Divides every ring edge of `face` into ceil(length / spacing) equal pieces
// (endpoints kept exactly). Existing vertices get the type-1 bonus of
// Sec. 5.1, midpoints of existing edges the type-2 bonus.
// With boundary weights (Sec. 5.2 case 1, one per subdivision vertex), an edge
// whose end weights exceed the face's mean vertex weight gets up to
// `adaptive_level` times more pieces (in proportion to its weight over the
// mean): heavier segments are refined more, the paper's adaptive refine level
// (Table I, setAdaptiveRefineLevel; DecomposeOptions::adaptive_refine).
FaceDomain refine_face(const Subdivision& sub, std::uint32_t face, double spacing,
                       const std::vector<double>* point_weights = nullptr, double adaptive_level = 4.0);

// Perimeter of a face: total length of its rings.
double face_perimeter(const Subdivision& sub, std::uint32_t face);

} // namespace madd::detail
