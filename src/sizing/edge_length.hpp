#pragma once
// Edge lengths and area bounds: the size field is in edge lengths h, a
// triangle's area bound that of the equilateral triangle of side h.

namespace madd::detail {

// The area bound of an edge length: the equilateral triangle's, sqrt(3)/4 h^2.
inline double area_of_edge(double h) noexcept { return 0.4330127018922193 * h * h; }
// The edge length whose equilateral triangle has area a (+infinity when a
// is not > 0, NaN included: no bound).
double edge_of_area(double a) noexcept;

}  // namespace madd::detail
