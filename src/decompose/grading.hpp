#pragma once
// Graded decompositions (paper Sec. 5.2): what a face weighs and which area it
// may have, from boundary weights (case 1), background points (case 2) or
// functions sampled on a per-face grid (case 3).
#include <cstdint>
#include <vector>

#include "madd/decomposition.hpp"
#include "split/split.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

enum class WeightSource : std::uint8_t { none, boundary, background, function };

// The grading a run uses, decided once from the options.
struct GradingMode {
  WeightSource weights = WeightSource::none;
  bool area_driven = false;  // subdomain_area_function or subdomain_area_samples set
  double r = 1.0;            // density weight = r * area + a * weight
  double a = 0.0;
  double p = 0.0;  // interpolation factor of new separator points (case 1)
  bool graded() const { return weights != WeightSource::none; }
};

// Case 1 is used when gradation > 0 and neither a weight function nor
// background weights are given (check_options refuses both at once).
GradingMode grading_mode(const DecomposeOptions& options);

// Exact point-in-face test over all rings of `face`. A point on the boundary
// belongs to the face on its right (winding_number, kernel/rings.hpp), so
// every point of the domain is in exactly one face (docs/grading.md).
bool point_in_face(const Subdivision& sub, std::uint32_t face, Point p);

// Samples of a weight (already an integral share: value = f * cell area for
// case 3) or of a required area, lying inside one face.
struct FaceSamples {
  std::vector<ValuedPoint> weights;
  std::vector<ValuedPoint> areas;
};

// Case 3: a grid_cells x grid_cells structured grid over the face's bounding
// box, points inside the face only; weight samples carry f(x,y) * cell area.
constexpr int grid_cells = 20;
FaceSamples function_samples(const Subdivision& sub, std::uint32_t face, const DecomposeOptions& options);

// Case 2: the background points (indices `inside` into the options' lists) as samples.
FaceSamples background_samples(const DecomposeOptions& options, const std::vector<std::uint32_t>& weights_inside,
                               const std::vector<std::uint32_t>& areas_inside);

// Weight of a face from boundary vertex weights (case 1): the sum over its ring vertices.
double boundary_weight(const Subdivision& sub, std::uint32_t face, const std::vector<double>& point_weights);

// Smallest required area among the samples, or +infinity when there is none.
double required_area(const FaceSamples& samples);

// Sum of the weight samples.
double sample_weight(const FaceSamples& samples);

// Case 1: weights of separator ends, keyed by exact coordinates, collected
// from a split before it is committed (the snapshot's segment ends are needed).
// An end on a segment gets p * the linear interpolation of the segment's end
// weights; a circumcentre gets p * the mean of its boundary neighbours' interpolated weights.
using EndWeights = std::vector<std::pair<Point, double>>;
void collect_end_weights(const Subdivision& snapshot, const SplitResult& result,
                         const std::vector<double>& point_weights, double p, EndWeights& out);

// Extends point_weights to every point of `points`, taking new points' weights from `ends`.
void assign_new_weights(const std::vector<Point>& points, EndWeights ends, std::vector<double>& point_weights);

// What the driver keeps between rounds for grading: boundary weights of all
// subdivision vertices (case 1) and, per face, the background points inside it (case 2).
class GradingState {
public:
  GradingState(const DecomposeOptions& options, const Pslg& domain);
  const GradingMode& mode() const { return mode_; }

  // Density for splitting `face` (graded = false when the run is not graded).
  FaceDensity density(const Subdivision& sub, std::uint32_t face) const;
  // r * area + a * weight for a graded run, the area otherwise.
  double weight(const Subdivision& sub, std::uint32_t face) const;
  // Smallest required area inside the face, +infinity when nothing constrains it.
  double required(const Subdivision& sub, std::uint32_t face) const;

  // Call with every split of a round before any is committed (case 1 end weights) ...
  void before_commit(const Subdivision& snapshot, const SplitResult& result);
  // ... after committing face -> (face, added) (case 2 point lists) ...
  void after_commit(const Subdivision& sub, std::uint32_t face, std::uint32_t added);
  // ... and once after the round's commits (case 1 weights of new points).
  void end_round(const Subdivision& sub);

  // Background weights (case 2) only: the weight and split density of a face
  // from the samples found inside it anew (no per-face lists), for the
  // balance repair, which merges and renumbers faces.
  bool can_rebalance() const { return mode_.weights == WeightSource::background && !mode_.area_driven; }
  double weight_from_scratch(const Subdivision& sub, std::uint32_t face) const;
  FaceDensity density_from_scratch(const Subdivision& sub, std::uint32_t face) const;
  // After faces were merged and renumbered: every background sample back in
  // the list of the face it lies in.
  void reassign(const Subdivision& sub);

private:
  FaceSamples samples(const Subdivision& sub, std::uint32_t face) const;
  std::vector<ValuedPoint> weights_in(const Subdivision& sub, std::uint32_t face) const;
  const DecomposeOptions& options_;
  GradingMode mode_;
  std::vector<double> point_weights_;
  EndWeights ends_;
  std::vector<std::vector<std::uint32_t>> weights_inside_, areas_inside_;
};

}  // namespace madd::detail
