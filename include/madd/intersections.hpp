#pragma once
// Resolving crossing and overlapping segments of a PSLG by inserting their
// intersection vertices, as Triangle and CDT libraries do, so that a PSLG
// drawn by hand (lines crossing, boundaries drawn twice) can be triangulated.
#include <cstdint>
#include <vector>

#include "madd/pslg.hpp"

namespace madd {

struct ResolvedPslg {
  // The input's points, then the new intersection vertices (their
  // attributes interpolated along a segment through them, their markers 0);
  // the segments are pieces of the input's, that meet only at shared
  // endpoints. Holes, regions and the id base are the input's.
  Pslg pslg;
  std::vector<std::uint32_t> source_segment;  // per segment of pslg: the input segment it is part of
  std::size_t new_vertices = 0;
  std::size_t crossings = 0;  // pairs of input segments found crossing (first pass)
  std::size_t overlaps = 0;   // pairs of input segments found overlapping (first pass)
  friend bool operator==(const ResolvedPslg&, const ResolvedPslg&) = default;
};

// Splits every segment at each vertex lying on it and at every point where
// it crosses another segment; overlapping pieces become one segment (the
// first in input order, with its marker). A crossing point is computed in
// floating point and rounded, so the pieces meeting there bend by at most
// a rounding error; the search is repeated on the pieces until no two meet
// other than at a shared endpoint. Precondition: validate_pslg() passed
// with allow_intersections. Deterministic. Throws InvalidInputError when
// more than 2^20 pairs intersect, or the pieces do not settle.
ResolvedPslg resolve_intersections(const Pslg& pslg);

}  // namespace madd
