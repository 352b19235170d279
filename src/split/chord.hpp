#pragma once
// A balance fallback for one split (our extension of Sec. 4, not in the
// paper): a single straight separator between two boundary points.
//
// With no interior points, the circumcentre approximation of the medial axis
// of a near-square face has one junction near its centre, so every complete
// separator built from its partial separators cuts off a quadrant or so: the
// best bisection may split 0.65 / 0.35 however fine the boundary. When that
// happens on the last levels it is the largest subdomain of the whole
// decomposition (C3). A chord across the face, such as the one between the
// midpoints of two opposite sides, often balances it exactly while meeting
// the boundary at close to 90 degrees; it is taken only when it satisfies
// every rule the partial separators do (Phi0 at both ends, inside the face,
// clear of the boundary). Its ends are on the face's outer ring; it keeps off
// the holes (islands), each of which then lies on one side, its area
// counted there.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "split/refine.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

struct ChordOptions {
  double separator_angle_deg = 60.0;  // Phi0: both ends, both sides
  std::uint32_t plan = 2;             // final subdomains of the face
  // Chords are rated by a two-sided balance quality: like balance_quality
  // (split.hpp), but the lightest final subdomain counts as well as the
  // heaviest, so it never exceeds balance_quality for the same areas.
  double min_quality = 0.0;    // a chord must balance better than this
  double good_quality = 0.95;  // among chords at least this good, the shortest wins
  bool end_bonus = true;       // Sec. 5.1 smoothing: lengths scaled by the end bonuses (existing vertices, midpoints)
  // A graded split (Sec. 5.2, cases 2 and 3) weighs a side area_weight x
  // its area + sample_weight x the samples inside it (FaceDensity's r and
  // a; the samples all inside the face); by default a side weighs its area.
  double area_weight = 1.0;
  double sample_weight = 0.0;
  std::span<const ValuedPoint> samples;
};

// The chord search reads each sample's and each hole's side of each chord in
// O(1) from a table of (samples + holes) x ring points: faces beyond this are
// not searched (the last levels' faces of a coastline at N = 64 hold 60-200
// samples on at most 1500 ring points).
inline constexpr std::size_t max_chord_sample_table = std::size_t{1} << 20;
// ... nor those whose pairs would read more than this of it in all (ring
// points^2 x columns: 200 columns on 1600 points, about half a second).
inline constexpr double max_chord_sample_work = 0x1p29;

// A chord found on face `fd` (the refined boundary of a face whose rings
// are simple and apart: no point where a ring passes twice or two rings
// meet), with the two-sided balance quality it achieves, or nothing. The
// weights are the areas less the holes', or the graded weights of the
// options. Quadratic in the points of `fd`: nothing is searched beyond a few
// thousand of them.
struct Chord {
  SplitResult result;
  double quality = 0.0;
};
std::optional<Chord> best_chord(const FaceDomain& fd, const ChordOptions& options);

// A face with more samples than this, within the bounds above, is searched
// with them merged on a grid (merged_for_chords): each sample is a column of
// the table, and a face of thousands of them on a short ring (a fuzzed
// domain's repair: 7,126 samples) came up to the work bound, 0.5 s a
// search, 10 s under the sanitizers (libFuzzer's limit). At 512 the balance
// matrix of docs/mesh.md moved in 23 of 81 runs (real faces within the
// bounds hold up to some thousands); at 2048 in one (Maine (c), N = 256).
inline constexpr std::size_t max_chord_columns = 2048;

// `samples` merged per cell of a k x k grid over their bounding box, k^2 <=
// `most`: each cell's weight at its member nearest the cell's weighted
// centroid (a real sample, so inside the face), in cell order. Empty when
// there are `most` samples or fewer (search with them as they are).
std::vector<ValuedPoint> merged_for_chords(std::span<const ValuedPoint> samples, std::size_t most);

}  // namespace madd::detail
