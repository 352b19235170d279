#pragma once
// One MADD split of one face (paper Sec. 4): refine, triangulate, build and
// contract G_D, bisect G'_D (repartitioning per Sec. 4.3), and return the
// separators as geometry. Reads the subdivision only, so splits of different
// faces can run on different threads.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "madd/geometry.hpp"
#include "medial/medial_detail.hpp"
#include "madd/triangulation.hpp"
#include "kernel/resource_limits.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct SplitOptions {
  double separator_angle_deg = 60.0;
  double boundary_refinement = 3.0;  // r
  double min_split_quality = 0.75;   // accept when each side has >= this share of its target
  double good_balance = 0.95;        // stop trying targets and refining at this balance quality
  int max_split_retries = 4;
  std::uint64_t seed = 1;
  int smoothing_iterations = 1;  // Sec. 5.1: 0 turns both smoothing steps off
  double adaptive_boundary_refinement =
      4.0;  // graded runs: heavier edges get up to this many times more pieces (refine.hpp)
  double smoothing_tolerance =
      0.03;  // step 2 may lower the balance quality by this much (never below min_split_quality)
};

// What the parts of a face weigh in a graded decomposition (Sec. 5.2). Not
// graded: a G_D vertex weighs its area.
struct FaceDensity {
  bool graded = false;
  double r = 1.0;  // density = r * area + a * weight
  double a = 0.0;
  const std::vector<double>* point_weights = nullptr;  // case 1: per subdivision vertex
  std::vector<ValuedPoint> samples;                    // cases 2/3: weight samples inside the face
};

// Splits face `face`, planned to become `plan` >= 2 final subdomains, aiming
// at floor(plan/2)/plan of its weight on side 0. Throws DecompositionError
// naming the face, its area and Phi0 when no valid separator exists after all
// refinement rounds.
// `limits`, when given, is checked before every refinement round after the
// first, so a time or memory limit stops a long split part way.
SplitResult compute_split(const Subdivision& sub, std::uint32_t face, std::uint32_t plan, const SplitOptions& options,
                          const FaceDensity& density = {}, const ResourceGuard* limits = nullptr);

// A point strictly inside a (validated, non-empty) domain: the centroid of
// the largest triangle of its constrained Delaunay triangulation.
Point largest_triangle_centroid(const Pslg& domain);

// 1 when the best sharing of `plan` between sides weighing w0 and w1 gives
// every final subdomain the mean weight, lower as the largest one grows.
double balance_quality(std::uint32_t plan, double w0, double w1);

// The share of `plan` for side 0 that balance_quality rates best: the plan is
// shared between the sides in proportion to what they actually got, so that
// the imbalance of one level does not compound down the recursion.
std::uint32_t side0_plan(std::uint32_t plan, double w0, double w1);

// Sec. 4.3: pairs of G'_D vertices whose cut separators would pinch a side at
// one boundary point (empty when the bisection `side` is valid). At a point
// of an interior segment (BoundaryLinks::two_sided), one cut separator on each
// side of it is a crossing, not a pinch; at a tip, two cut separators at
// least Phi0 apart pass through it. `links`: one per working point.
std::vector<std::pair<std::uint32_t, std::uint32_t>> pinch_conflicts(const MedialGraph& g,
                                                                     std::span<const BoundaryLinks> links,
                                                                     const std::vector<std::uint8_t>& side,
                                                                     double separator_angle_deg);

struct FaceDomain;

// A cut partial separator: its two ends (indices into MedialGraph::points) and
// the side (0/1) on its left going end[0] -> end[1].
struct CutEnd {
  std::uint32_t end[2];
  std::uint8_t left_side = 0;
};

struct EndSmoothing {
  int iterations = 1;
  double separator_angle_deg = 60.0;
  std::uint32_t plan = 2;
  double min_quality = 0.0;      // balance_quality floor
  double weight_per_area = 1.0;  // to move weight with the swept area
  double min_length = 0.0;       // a move never makes a partial separator shorter than this (unless it was)
};

// Sec. 5.1 step 2 on the ends of the cut separators (see ends.cpp).
void smooth_ends(const MedialGraph& g, const FaceDomain& fd, const EndSmoothing& s, std::vector<CutEnd>& cut,
                 double w[2], const Point interior[2]);
// Density weight of every G_D vertex: r * area + a * (its share of the
// boundary vertex weights, or the weight samples it contains).
std::vector<double> density_weights(const MedialGraph& g, const Triangulation& tri, const FaceDomain& fd,
                                    const FaceDensity& density);

}  // namespace madd::detail
