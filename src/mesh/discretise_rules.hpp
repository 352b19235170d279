#pragma once
// The constants of the decoupling condition (docs/mesh.md, "Decoupling").
#include <cstddef>

namespace madd::detail {

// A triangle whose circumcentre encroaches a piece of length L has
// circumradius at most L / sqrt(2), hence area at most 3 sqrt(3) L^2 / 8;
// pieces of at most sqrt(8 / (3 sqrt(3))) sqrt(A) = 1.2408 sqrt(A) can never
// be encroached by a triangle that is bad only by its size. 5% below it,
// for the size bound varying between the piece and the triangle.
inline constexpr double size_factor = 1.18;

// Pieces no longer than this share of the distance to the nearest
// non-incident feature: their diametral circles then hold no other feature,
// and the vertices refinement puts near them are spaced like the pieces.
inline constexpr double feature_factor = 0.5;

// Along a segment the target length grows from its ends' targets by at
// most this much per unit of length (half the local feature size's own
// Lipschitz bound of 1), so neighbouring pieces differ by a bounded factor.
inline constexpr double grading = 0.5;

// A bound on the split points of one segment (a size bound many orders of
// magnitude below the segment's length is refused as a limit elsewhere).
inline constexpr std::size_t max_pieces_per_segment = std::size_t{1} << 24;

}  // namespace madd::detail
