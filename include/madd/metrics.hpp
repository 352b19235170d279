#pragma once
// The quality figures of a decomposition (criteria C1-C3 of the paper, Sec. 1
// and Sec. 7; docs/quality.md). The independent validity check,
// verify_decomposition, sits beside Decomposition in madd/decomposition.hpp
// (included here, so code that found it here still compiles).
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"

namespace madd {

// Every figure of docs/quality.md. Angles in degrees. A figure that does not exist
// for this decomposition (no new angle when N = 1, no separator) is NaN.
// Quantiles follow Python's statistics.quantiles(n=10) ("exclusive" method),
// as the independent Python checker used in development (ddcheck.py) does, so
// both print the same numbers.
struct Metrics {
  std::uint32_t subdomains = 0;
  std::uint32_t points = 0;
  std::uint32_t segments = 0;
  std::uint32_t separator_segments = 0;
  double domain_area = 0.0;  // sum of the subdomains' ring areas
  double mean_area = 0.0;
  double min_angle_bound_deg = 0.0;  // the Phi0 the decomposition was built with

  // C1: interior angles at subdomain corners where at least one edge is a separator.
  std::uint32_t new_angles = 0;
  double angle_min = 0.0;
  double angle_p10 = 0.0;
  double angle_median = 0.0;
  double angle_p90 = 0.0;
  // The new angles whose corner lies on the original boundary.
  std::uint32_t boundary_angles = 0;
  double boundary_angle_min = 0.0;
  double boundary_angle_median = 0.0;

  // C2: separator size.
  double separator_length = 0.0;
  double separator_length_norm = 0.0;         // / sqrt(domain area)
  double mean_separator_per_subdomain = 0.0;  // each subdomain's separator boundary, averaged
  double max_separator_over_area_norm = 0.0;  // max_s sep_len(s)/area(s) * sqrt(mean area)

  // C3: balance.
  double max_area_over_mean = 0.0;
  double min_area_over_mean = 0.0;
  double max_weight_over_mean = 0.0;
  double min_weight_over_mean = 0.0;

  // Shortest new segment (separator, or piece of a split boundary segment) / sqrt(mean area).
  double shortest_new_segment_norm = 0.0;

  // Split to a required area (Sec. 5.2; Decomposition::subdomain_area_ratio > 0),
  // else NaN and 0: the largest area / required area over the subdomains
  // (unconstrained ones count 0), the bound, and how many subdomains are
  // still above it (> 0 when N, the maximum count, was reached first).
  double max_area_over_required = 0.0;
  double subdomain_area_ratio = 0.0;
  std::uint32_t subdomains_over_area_bound = 0;

  std::vector<PhaseTime> times;
  // Figure by figure, as doubles compare: a NaN figure (undefined, as
  // angle_p10 of fewer than two angles) is unequal even to itself.
  friend bool operator==(const Metrics&, const Metrics&) = default;
};

// Computes every figure from the decomposition alone (areas from the rings).
// Precondition: the rings are well formed (verify_decomposition passes).
Metrics metrics(const Decomposition& decomposition, std::vector<PhaseTime> times = {});

}  // namespace madd
