#pragma once
// The size field of a domain (docs/mesh.md, "Size field"): edge lengths h(x)
// from the distance to the coast, the local width of the water (feature
// size), the user's bounds, limited to a gradation G. Built once per run on a
// background triangulation of the domain; the mesher, the work estimate and
// verify_mesh read it through quality/area_bound.hpp, so they cannot disagree.
#include <array>
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "sizing/triangle_locator.hpp"

namespace madd::detail {

// The triangulation the field is piecewise linear on: the constrained
// Delaunay triangulation of the domain's vertices and Steiner points,
// covering the convex hull of the domain (holes and the outside included, so
// that a walk can always reach a point); `inside` marks the domain's
// triangles, over which the work estimate integrates.
struct SizeBackground {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;   // counterclockwise
  std::vector<std::array<std::uint32_t, 3>> neighbours;  // across edge i (opposite corner i); no_index on the hull
  std::vector<std::uint8_t> inside;                      // per triangle: 1 in the domain
  std::vector<double> edge;                              // per point: h there (+infinity: no bound)
};

// What building a field did (for benchmarks and tests; not part of a result).
struct SizeFieldReport {
  std::size_t steiner_points = 0;       // quadtree points of the background
  std::size_t inside_triangles = 0;
  std::size_t floored_points = 0;       // distance values the safety bound would take to <= 0 (see size_field.cpp)
  std::size_t gradation_pops = 0;
  std::size_t gradation_fixes = 0;
  std::size_t gradation_held = 0;       // triangles held to their safe slope (gradation.hpp)
  bool gradation_fell_back = false;
  double seconds = 0.0;                 // to build the whole field
};

// The ranges of the field's options, without the domain: every length and
// rate finite and >= 0; min_edge_length <= max_edge_length when both are
// set; min_edge_length set when distance_rate or cells_across is (it is the
// field's size at the coast and the floor of the feature-size term: without
// it both would ask for h -> 0 at the coast, and the domain gives no scale to
// default it to). Throws OptionError naming the field.
void check_field_options(const MeshSizeOptions& size);

class SizeField {
public:
  SizeField() = default;  // empty
  // `domain` is a valid domain (validate()); throws OptionError on bad field
  // options (check_field_options, and coast_markers naming a marker no
  // boundary segment has). Builds nothing when size.has_field_terms() is
  // false.
  SizeField(const Pslg& domain, const MeshSizeOptions& size);
  // No field term was asked for: edge_at is +infinity everywhere.
  bool empty() const noexcept { return background_.triangles.empty(); }
  // h at p: linear over the background triangle holding p (+infinity when empty()).
  double edge_at(Point p) const;
  const SizeBackground& background() const noexcept { return background_; }
  const SizeFieldReport& report() const noexcept { return report_; }

private:
  SizeBackground background_;
  TriangleLocator locator_;  // a grid of start triangles for a walk
  SizeFieldReport report_;
  TriangleView view() const noexcept {
    return {background_.points, background_.triangles, background_.neighbours};
  }
};

// The area bound of an edge length: the equilateral triangle's, sqrt(3)/4 h^2.
inline double area_of_edge(double h) noexcept { return 0.4330127018922193 * h * h; }
// The edge length whose equilateral triangle has area a (+infinity when a
// is not > 0, NaN included: no bound).
double edge_of_area(double a) noexcept;

}  // namespace madd::detail
