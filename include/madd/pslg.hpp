#pragma once
// The input value type: a planar straight line graph (Triangle's .poly model)
// describing one domain, an outer boundary with any number of holes.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

// Sentinel for "no index" in every 32-bit index array of madd.
inline constexpr std::uint32_t no_index = std::numeric_limits<std::uint32_t>::max();

struct Segment {
  std::uint32_t a = 0; // 0-based index into Pslg::points
  std::uint32_t b = 0;
  int marker = 0;
  friend bool operator==(const Segment&, const Segment&) = default;
};

struct Region {
  Point at;
  double attribute = 0.0;
  double max_area = -1.0;
  friend bool operator==(const Region&, const Region&) = default;
};

// Indices are 0-based in memory whatever the file used; `first_index` remembers
// the file's base so that ids in error messages and written files match it.
struct Pslg {
  std::vector<Point> points;
  std::uint32_t attributes_per_point = 0;
  std::vector<double> attributes;  // points.size() * attributes_per_point, row-major
  std::vector<int> point_markers;  // empty, or one per point
  std::vector<Segment> segments;
  bool has_segment_markers = false;
  std::vector<Point> holes;
  std::vector<Region> regions;
  std::uint32_t first_index = 1;   // 0 or 1, as in the file that was read

  // Attribute k of point i. Precondition: k < attributes_per_point.
  double attribute(std::size_t i, std::size_t k) const { return attributes[i * attributes_per_point + k]; }
  friend bool operator==(const Pslg&, const Pslg&) = default;
};

// Where each item of a Pslg came from in its file, for error messages.
// Empty vectors mean "unknown" (a Pslg built in memory).
struct SourceMap {
  std::string path;
  std::string point_path; // file of point_lines when not `path` (a companion .node); empty = `path`
  std::vector<std::uint32_t> point_lines;
  std::vector<std::uint32_t> segment_lines;
  std::vector<std::uint32_t> hole_lines;
};

struct ValidateOptions {
  // Check vertex attribute 1 as a boundary density weight (finite, >= 0);
  // only wanted when boundary-weight grading is on (docs/formats.md).
  bool check_weights = false;
  // Accept a Pslg with no segments and no holes as a point set, to be
  // triangulated over its convex hull (madd triangulate FILE.node): only the
  // coordinate range and duplicate vertices are then checked.
  bool allow_point_set = false;
};

// Checks that `pslg` describes one valid domain (docs/formats.md, "Bad input"):
// no duplicate vertices, no zero-length segments, no crossing, overlapping or
// touching segments (exact, sub-quadratic), every vertex of even degree and
// on a segment, hole points strictly inside the domain and off every segment,
// one connected region; every vertex and hole coordinate 0 or of magnitude in
// [1e-40, 1e70] (the exact range of the predicates, InputProblem::other).
// Throws InvalidInputError naming ids (with the file's base) and coordinates,
// plus the line when `source` knows it.
void validate(const Pslg& pslg, const SourceMap& source = {}, const ValidateOptions& options = {});

// Area of the domain: outer boundary minus holes (sum over closed rings of the
// region flooded as Triangle would). Precondition: validate() passed.
double domain_area(const Pslg& pslg);

} // namespace madd
