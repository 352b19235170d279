#pragma once
// The faces of a decomposition, for the writers that put region points in a
// .poly (outputs 1 and 2, docs/formats.md "Interior segments in the outputs").
// Triangle floods a region point's attribute and area bound up to the nearest
// segments, so a subdomain that interior segments cut into several parts
// needs a region point in each part, and an input region must be repeated in
// every part of the input's region it covered, on both sides of every
// separator that now cuts through it.
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"

namespace madd::detail {

// One part of one subdomain bounded by its rings and interior segments (a
// subdomain without interior segments is one face).
struct DecompositionFace {
  std::uint32_t subdomain = 0;
  Point point;  // strictly inside the face, on no segment
  // The input region (index into Decomposition::regions) whose attribute and
  // area bound Triangle gives this part of the input: of the region points
  // lying in the part of the domain bounded by input segments (boundary and
  // interior pieces, not separators) that holds this face, the last in file
  // order. no_index when none does.
  std::uint32_t region = no_index;
  friend bool operator==(const DecompositionFace&, const DecompositionFace&) = default;
};

// Every face, ordered by subdomain, then by where the face's first triangle
// comes in a triangulation of the whole decomposition (deterministic). A
// face's point is the point of the input region covering it when that lies
// strictly inside the face; else, for a subdomain without interior segments
// (one face), its interior_point; else the centroid of the face's largest
// triangle. Without
// interior segments and without regions this costs nothing (no triangulation).
// Precondition: the decomposition passes verify_decomposition (its segments
// are a valid PSLG). Throws InternalError on a face no subdomain bounds
// consistently.
std::vector<DecompositionFace> decomposition_faces(const Decomposition& decomposition);

}  // namespace madd::detail
