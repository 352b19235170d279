#pragma once
// The size field of a domain (docs/mesh.md, "Size field"): edge lengths h(x)
// from the distance to the coast, the local width of the water (feature
// size), the user's bounds, limited to a gradation G. Built once per run on a
// background triangulation of the domain; the mesher, the work estimate and
// verify_mesh read it through quality/area_bound.hpp, so they cannot disagree.
#include <cstddef>

#include "madd/geometry.hpp"
#include "madd/mesh.hpp"
#include "madd/pslg.hpp"
#include "sizing/coast_candidates.hpp"
#include "sizing/edge_length.hpp"
#include "sizing/raw_field.hpp"
#include "sizing/size_background.hpp"
#include "sizing/triangle_locator.hpp"

namespace madd::detail {

// What building a field did (for benchmarks and tests; not part of a result).
struct SizeFieldReport {
  std::size_t steiner_points = 0;  // quadtree points of the background
  std::size_t inside_triangles = 0;
  std::size_t exact_triangles = 0;   // inside ones reading the exact distance (coast_candidates.hpp)
  std::size_t coast_candidates = 0;  // coast pieces kept by them, in all
  std::size_t floored_points = 0;    // distance values the safety bound would take to <= 0 (see size_field.cpp)
  std::size_t gradation_pops = 0;
  std::size_t gradation_fixes = 0;
  std::size_t gradation_held = 0;  // triangles held to their safe slope (gradation.hpp)
  bool gradation_fell_back = false;
  double seconds = 0.0;  // to build the whole field
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
  // false. Built on `threads` threads (0: one per core), the same for any count.
  SizeField(const Pslg& domain, const MeshSizeOptions& size, unsigned threads = 1);
  // No field term was asked for: edge_at is +infinity everywhere.
  bool empty() const noexcept { return background_.triangles.empty(); }
  // h at p: linear over the background triangle holding p (+infinity when
  // empty()); in the triangles near the coast that keep their coast pieces
  // (coast_candidates.hpp), the smaller of that and hmin + G d(p), d exact.
  // Continuous: on an edge shared with a linear-only triangle the linear
  // part is already below the exact term. Deterministic and thread-safe.
  // `hint`: where the caller's last query ended (triangle_locator.hpp), or null.
  double edge_at(Point p, WalkHint* hint = nullptr) const;
  // edge_at is never below this (hmin less a hair; 0 without hmin).
  double least_edge() const noexcept { return exact_term(0.0); }
  const SizeBackground& background() const noexcept { return background_; }
  const SizeFieldReport& report() const noexcept { return report_; }

private:
  SizeBackground background_;
  TriangleLocator locator_;     // a grid of start triangles for a walk
  CoastCandidates exact_;       // the coast pieces near each triangle: d exactly
  std::vector<double> graded_;  // per point: the linear part (every term but an exact distance term)
  double hmin_ = 0.0, rate_ = 0.0;
  void lower_to_safe_distance(const std::vector<RawSample>& samples);
  // Less a hair against the rounding of d, computed here and by any checker.
  double exact_term(double d) const noexcept { return (hmin_ + rate_ * d) * (1.0 - 1e-12); }
  SizeFieldReport report_;
  TriangleView view() const noexcept { return {background_.points, background_.triangles, background_.neighbours}; }
};

}  // namespace madd::detail
