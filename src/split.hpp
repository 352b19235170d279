#pragma once
// One MADD split of one face (paper Sec. 4): refine, triangulate, build and
// contract G_D, bisect G'_D (repartitioning per Sec. 4.3), and return the
// separators as geometry. Reads the subdivision only, so splits of different
// faces can run on different threads.
#include <cstdint>

#include "subdivision.hpp"

namespace madd::detail {

struct SplitOptions {
  double min_angle_deg = 60.0;
  double refine = 3.0;          // r
  double imbalance = 0.75;      // accept when each side has >= this share of its target
  double good_balance = 0.95;   // stop trying targets and refining at this balance quality
  int max_refinement_rounds = 4;
  std::uint64_t seed = 1;
};

// Splits face `face`, planned to become `plan` >= 2 final subdomains, aiming
// at floor(plan/2)/plan of its weight on side 0. Throws DecompositionError
// naming the face, its area and Phi0 when no valid separator exists after all
// refinement rounds.
SplitResult compute_split(const Subdivision& sub, std::uint32_t face, std::uint32_t plan, const SplitOptions& options);

} // namespace madd::detail
