#pragma once
// Faces that could not be split: no separator meeting Phi0 was found for them
// at any refinement (paper Sec. 4). Rather than fail the whole decomposition,
// such a face stays one subdomain for now, the other subdomains planned for it
// go to faces that can still be split, and it is tried again once its boundary
// changes (a neighbour's separator ending on a shared side adds a vertex, and
// with it new medial-axis branches). The decomposition fails only when no
// face is left that could take a subdomain.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "madd/error.hpp"
#include "decompose/grading.hpp"
#include "subdivision/subdivision.hpp"

namespace madd::detail {

class StuckFaces {
public:
  // Face `face` had no valid separator: it stays one subdomain for now.
  void mark(Subdivision& sub, std::uint32_t face, const DecompositionError& error);
  // Faces whose boundary changed since they failed may be tried again.
  void release_changed(const Subdivision& sub);
  bool is_stuck(std::uint32_t face) const { return face < vertices_.size() && vertices_[face] != 0; }
  std::size_t count() const;
  // After a face failed or was released: plans the `target` subdomains
  // afresh over the faces that can take them (every face keeps at least one;
  // each further one goes to the face with the largest weight per planned
  // subdomain, ties to the lower face id), so that the subdomains a stuck
  // face gave up go where they do the most for balance. Nothing changes when
  // no face failed. Throws DecompositionError when subdomains are left to
  // place and every face is stuck.
  void replan(Subdivision& sub, const GradingState& grading, std::uint32_t target);

private:
  std::vector<std::size_t> vertices_;  // per face: its ring vertices when it failed; 0 = not stuck
  bool changed_ = false;               // a face failed or was released since the last replan
  std::string last_error_;
  std::int64_t last_face_ = -1;
  double last_area_ = 0.0, separator_angle_deg_ = 0.0;
};

}  // namespace madd::detail
