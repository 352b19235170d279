#pragma once
// The MADD decomposition (paper Sec. 3-5): options, the result value, the
// one free function that does the whole job, and the independent check of a
// result.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "madd/error.hpp"
#include "madd/geometry.hpp"
#include "madd/pslg.hpp"

namespace madd {

// Table III of the paper, plus the engineering knobs. Angles are in degrees
// here (the paper's `f` is a fraction of pi: f = separator_angle_deg / 180).
struct DecomposeOptions {
  std::uint32_t subdomains = 2;       // N
  double separator_angle_deg = 60.0;  // Phi0, criterion C1: every new angle a separator makes
  double boundary_refinement = 3.0;   // r: uniform refinement factor of the boundary
  // The paper's adaptive refine level (Table I): with boundary weights
  // (Sec. 5.2 case 1), a boundary edge heavier than the subdomain's mean is
  // divided into up to this many times more pieces, in proportion to its
  // weight ("segments that have greater weight will be refined more", Sec. 6).
  // 1 refines every edge alike. In [1, 64].
  double adaptive_boundary_refinement = 4.0;
  // i, the paper's acceptable imbalance of one split, as a quality: a split's
  // quality is mean / largest final subdomain it implies (= 1 / its balance,
  // docs/api.md, "Names"). A split of lower quality is retried at finer and
  // other boundary samplings before it is taken, and smoothing never lowers a
  // split below it (docs/algorithm.md, step 6).
  double min_split_quality = 0.75;
  unsigned threads = 0;  // 0 = hardware concurrency
  std::uint64_t seed = 1;
  // How many more times a split below min_split_quality is retried, each
  // time at half the boundary spacing, before the best one found is taken.
  int max_split_retries = 4;

  // Smoothing (Sec. 5.1): iterations of step 2 (0 turns smoothing off,
  // step 1's edge-weight coefficients included). See docs/smoothing.md.
  int smoothing_iterations = 1;
  // Balance repair (C3, our extension; docs/algorithm.md, "Rebalancing"):
  // once N is reached, a subdomain whose balance (its area / the mean area)
  // is above repair_balance_above is merged with one or two smaller
  // neighbours and the union split again, kept when every new part is smaller
  // than it. 0 turns it off; otherwise >= 1. Uniform decompositions and those
  // graded by weight samples (on the weights); not other graded runs, nor a
  // required area.
  double repair_balance_above = 1.2;
  // What the repair balances in a run graded by weight samples, when set: the
  // work of a face, given as a domain of its own (its rings; separators with
  // marker 0, boundary pieces with their input marker or 1; a hole point per
  // hole; interior segments left out). Read once per face. madd mesh sets it
  // to the face's expected triangle count, which the samples only
  // approximate (docs/mesh.md, "Balance by work"). Unset: the samples.
  std::function<double(const Pslg& face)> face_work;

  // Graded decomposition (Sec. 5.2). A subdomain's density weight is
  // boundary_refinement * area + gradation * weight, where weight comes from,
  // in order: the weight function, the weight samples, or the boundary weights
  // (vertex attribute 1; used when gradation > 0 and neither of the others is set).
  // With a weight function or weight samples, gradation 0 counts as 1;
  // negative or NaN function values count as 0. See docs/grading.md.
  double gradation = 0.0;      // a
  double interpolation = 0.0;  // p: weight of new separator points = p * lerp of endpoint weights
  std::function<double(double x, double y)> weight_function;          // case 3, evaluated on a grid per subdomain
  std::function<double(double x, double y)> subdomain_area_function;  // case 3: required area at (x, y)
  std::vector<ValuedPoint> weight_samples;          // case 2: a subdomain's weight = sum of those inside it
  std::vector<ValuedPoint> subdomain_area_samples;  // case 2: required area = min of those inside it
  // With a required area (subdomain_area_function or subdomain_area_samples),
  // subdomains are split while area / required area exceeds this ratio, up
  // to `subdomains` (largest ratio first; docs/grading.md gives the exact rule).
  double subdomain_area_ratio = 1.0;

  // Resource limits (docs/hostile.md): decompose() throws LimitError when a
  // split, or a refinement round of one, starts after this many seconds, or
  // when the process's resident memory exceeds this many bytes (checked at
  // the same points). 0 = no limit.
  double time_limit_seconds = 0.0;
  std::size_t max_memory_bytes = 0;

  // Progress: when set, called after each split is committed, with the number
  // of subdomains so far (done: 2, 3, ... one more per call) and the target
  // (options.subdomains; with a required area, the maximum, so the last call
  // may have done < target). Not called when nothing is split (N = 1).
  // Always on the thread that called decompose(), between commits, so it may
  // touch the caller's state without locking; keep it short, since the next
  // commit waits for it (a CLI prints a few times a second, not on every call).
  // It sees nothing of the result and cannot change it: the output is the same
  // with or without it, for any thread count. If it throws, decompose() stops
  // (worker threads finish their current split and are joined) and rethrows
  // that exception, with no partial result: a way to cancel.
  std::function<void(std::uint32_t done, std::uint32_t target)> progress;
};

// The most worker threads DecomposeOptions::threads may ask for.
inline constexpr unsigned max_threads = 4096;

// The one check of every option's range and of options that contradict each
// other (two sources of weights, two of required areas, an interpolation
// factor with no boundary weights to interpolate). Throws OptionError naming
// the field ("separator_angle_deg") and the rule it breaks. decompose() calls it;
// front ends call it to refuse bad options before reading any input.
void check_options(const DecomposeOptions& options);
// Only the ranges, each field on its own (for a front end that sets options
// one at a time, like the script's `set`, and checks combinations later).
void check_option_ranges(const DecomposeOptions& options);
// The same, plus what depends on the domain: grading by boundary weights
// (gradation > 0 with no other weight source) needs vertex attributes.
void check_options(const DecomposeOptions& options, const Pslg& domain);

// True when the options give a required area (subdomain_area_function or
// subdomain_area_samples, Sec. 5.2): `subdomains` is then a maximum, not a target.
bool has_required_area(const DecomposeOptions& options) noexcept;

// Wall time of one phase of a run ("read", "refine", "verify"...).
struct PhaseTime {
  std::string name;
  double seconds = 0.0;
  friend bool operator==(const PhaseTime&, const PhaseTime&) = default;
};

// One subdomain, a face of the global subdivision. rings[0] is the outer
// boundary (counter-clockwise), the others are holes (clockwise). Each ring is
// a closed cycle of indices into Decomposition::points (first not repeated);
// ring_segments[r][k] is the segment from rings[r][k] to rings[r][k+1].
struct Subdomain {
  std::vector<std::vector<std::uint32_t>> rings;
  std::vector<std::vector<std::uint32_t>> ring_segments;
  double area = 0.0;
  double weight = 0.0;  // density weight (equals area when not grading)
  // With a required area (has_required_area): the smallest required area
  // inside the subdomain, +infinity where nothing constrains it; 0 otherwise.
  double required_area = 0.0;
  Point interior_point;            // strictly inside the subdomain
  std::vector<Point> hole_points;  // one strictly inside each hole ring
  // Interior constraints inside the subdomain (docs/formats.md, "Interior
  // segments"): pieces of input segments with this subdomain on both sides,
  // as indices into Decomposition::segments (in no ring, of no other
  // subdomain; a separator only ever crosses one at a vertex, so a piece is
  // always inside exactly one subdomain), and the input's isolated vertices
  // strictly inside it, as indices into Decomposition::points.
  std::vector<std::uint32_t> interior_segments;
  std::vector<std::uint32_t> interior_points;
  friend bool operator==(const Subdomain&, const Subdomain&) = default;
};

// A conforming planar subdivision of the domain: every vertex and segment,
// shared by the subdomains on both sides. No T-junctions.
struct Decomposition {
  std::vector<Point> points;                  // the input's points first, same indices, then new ones
  std::vector<Segment> segments;              // marker 0 = separator; boundary pieces keep the input
                                              // marker, or 1 where it was 0 or absent
  std::vector<std::uint32_t> segment_origin;  // input segment a piece comes from, no_index for separators
  std::vector<Point> holes;                   // the input's hole points
  std::vector<Region> regions;                // the input's regions (attribute, area constraint), unchanged
  std::vector<Subdomain> subdomains;
  double separator_angle_deg = 60.0;  // the Phi0 it was built with
  double subdomain_area_ratio = 0.0;  // with a required area: the ratio it was split to; 0 otherwise
  friend bool operator==(const Decomposition&, const Decomposition&) = default;

  bool is_separator(std::uint32_t segment) const { return segment_origin[segment] == no_index; }
};

// Per segment of `decomposition`: the subdomain it is an interior segment of
// (Subdomain::interior_segments), or no_index for separators and boundary pieces.
std::vector<std::uint32_t> interior_segment_owners(const Decomposition& decomposition);

// Decomposes a validated domain into options.subdomains connected subdomains
// (Algorithm 4). Every new angle is >= options.separator_angle_deg. Deterministic:
// the result is identical for any thread count. Throws DecompositionError
// naming the subdomain that could not be split; never returns a partial result.
Decomposition decompose(const Pslg& domain, const DecomposeOptions& options = {});

// The subdomain count verify_decomposition should expect of a decomposition
// asked for `requested` subdomains: `requested`, or, when it was split to a
// required area (subdomain_area_ratio > 0, where N is a maximum), the count made
// if it lies between 1 and `requested`.
std::uint32_t expected_subdomain_count(const Decomposition& decomposition, std::uint32_t requested) noexcept;

// Timings of one decompose() run (not part of the result: they vary from run
// to run), docs/quality.md, "Phase times": "refine" (the boundary
// refinement), "triangulate", "graph" and "bisect" summed over every split
// (on all threads, so with several threads they add up to more than the wall
// time), then "insert", committing the splits to the subdivision (one thread),
// and "rebalance", the balance repair once N is reached (one thread; 0 when off).
struct DecomposeReport {
  std::vector<PhaseTime> phases;
  friend bool operator==(const DecomposeReport&, const DecomposeReport&) = default;
};

// A decomposition and the report of the run that made it.
struct DecomposeRun {
  Decomposition decomposition;
  DecomposeReport report;
  friend bool operator==(const DecomposeRun&, const DecomposeRun&) = default;
};

// decompose(), with the time of each phase: the same decomposition.
DecomposeRun decompose_with_report(const Pslg& domain, const DecomposeOptions& options = {});

// Recomputes every invariant of a decomposition of `domain` into
// `expected_count` subdomains: full cover (the subdomains' and the domain's
// areas summed exactly, equal but for the slivers rounded boundary vertices
// cut off, whose area is bounded from their exact distances; docs/quality.md),
// no two segments crossing, overlapping or touching except at shared endpoints
// (exact, orient2d, uniform grid), one CCW outer ring per subdomain with CW
// holes inside it, conforming (each separator in two rings in opposite
// directions, each boundary piece in one, no T-junctions), boundary pieces
// forming one chain along each input segment, off it by no more than the
// rounding of their interpolation, with the right markers, stored areas
// within rings_area's rounding bound of the exact ones, every new angle
// >= decomposition.separator_angle_deg - 1e-9 deg, interior and hole points strictly
// inside. Never throws on a malformed decomposition: it reports problems.
Verification verify_decomposition(const Decomposition& decomposition, const Pslg& domain, std::uint32_t expected_count);

}  // namespace madd
