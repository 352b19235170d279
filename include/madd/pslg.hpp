#pragma once
// The input value type: a planar straight line graph (Triangle's .poly model),
// and its two levels of validation: any PSLG (what triangulate() takes:
// isolated vertices, interior and dangling segments, vertices on segments),
// and a domain (what decompose() and mesh() take: one connected region bounded
// by closed rings, an outer boundary with any number of holes, with any
// interior constraints inside it).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "madd/geometry.hpp"

namespace madd {

// Sentinel for "no index" in every 32-bit index array of madd.
inline constexpr std::uint32_t no_index = std::numeric_limits<std::uint32_t>::max();

struct Segment {
  std::uint32_t a = 0;  // 0-based index into Pslg::points
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
  std::uint32_t first_index = 1;  // 0 or 1, as in the file that was read

  // Attribute k of point i. Precondition: k < attributes_per_point.
  double attribute(std::size_t i, std::size_t k) const { return attributes[i * attributes_per_point + k]; }
  friend bool operator==(const Pslg&, const Pslg&) = default;
};

// Where each item of a Pslg came from in its file, for error messages.
// Empty vectors mean "unknown" (a Pslg built in memory).
struct SourceMap {
  std::string path;
  std::string point_path;  // file of point_lines when not `path` (a companion .node); empty = `path`
  std::vector<std::uint32_t> point_lines;
  std::vector<std::uint32_t> segment_lines;
  std::vector<std::uint32_t> hole_lines;
  std::vector<std::uint32_t> region_lines;
  friend bool operator==(const SourceMap&, const SourceMap&) = default;
};

struct ValidateOptions {
  // Check vertex attribute 1 as a boundary density weight (finite, >= 0);
  // only wanted when boundary-weight grading is on (docs/formats.md).
  bool check_weights = false;
  // Accept a Pslg with no segments and no holes as a point set, to be
  // triangulated over its convex hull (madd triangulate FILE.node): only the
  // coordinate range and duplicate vertices are then checked.
  bool allow_point_set = false;
  friend bool operator==(const ValidateOptions&, const ValidateOptions&) = default;
};

// Checks that `pslg` describes one valid domain (docs/formats.md, "The domain"
// and "Bad input"): no duplicate vertices, no zero-length segments, no
// crossing or overlapping segments (exact, sub-quadratic; a vertex inside a
// segment splits it), every segment with the domain on at least one side (on
// both: an interior segment), every isolated vertex inside the domain, hole
// points strictly inside the domain and off every segment, one region
// connected across its interior segments; every vertex and hole coordinate 0 or of magnitude in
// [1e-40, 1e70] (the exact range of the predicates, InputProblem::other).
// Throws InvalidInputError naming ids (with the file's base) and coordinates,
// plus the line when `source` knows it.
void validate(const Pslg& pslg, const SourceMap& source = {}, const ValidateOptions& options = {});

struct ValidatePslgOptions {
  // Accept crossing and overlapping segments, to be resolved by
  // resolve_intersections() (madd/intersections.hpp) before triangulating.
  bool allow_intersections = false;
  friend bool operator==(const ValidatePslgOptions&, const ValidatePslgOptions&) = default;
};

// Checks that `pslg` is a planar straight line graph triangulate() takes
// (docs/formats.md, "PSLGs"): coordinates of vertices, holes and region
// points 0 or of magnitude in [1e-40, 1e70]; no duplicate vertices, no
// zero-length segments; no two segments crossing or overlapping (unless
// `allow_intersections`); no hole point on a segment; no hole point without
// any segment to stop it. Isolated vertices, interior, dangling and open
// segments, and vertices lying inside a segment (the segment is split there)
// are all accepted. Throws InvalidInputError as validate() does.
void validate_pslg(const Pslg& pslg, const SourceMap& source = {}, const ValidatePslgOptions& options = {});

// What a PSLG holds, as `madd check` prints it. "Kept" is the region
// triangulate() keeps without the convex hull option (Triangle's -p): the
// bounded faces of the segments, less those holding a hole point.
struct PslgSummary {
  std::size_t isolated_vertices = 0;         // on no segment
  std::size_t isolated_inside = 0;           // ... of which inside the kept region
  std::size_t vertices_inside_segments = 0;  // lying inside a segment, which is split there
  std::size_t dangling_ends = 0;             // vertices ending exactly one segment (piece)
  // Each segment is one of: interior (the kept region on both sides of some
  // piece of it), boundary (else on one side of some piece), outside (else).
  std::size_t interior_segments = 0;
  std::size_t boundary_segments = 0;
  std::size_t outside_segments = 0;
  std::size_t parts = 0;  // connected faces of the kept region
  double area = 0.0;      // of the kept region
  friend bool operator==(const PslgSummary&, const PslgSummary&) = default;
};

// Precondition: validate_pslg() passed (intersections not allowed).
PslgSummary summarize_pslg(const Pslg& pslg);

// Area of the domain: outer boundary minus holes (sum over closed rings of the
// region flooded as Triangle would). Precondition: validate() passed.
double domain_area(const Pslg& pslg);

}  // namespace madd
