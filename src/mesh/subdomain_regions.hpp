#pragma once
// The input's regions (Triangle's -A and -a) as each subdomain sees them
// (docs/mesh.md, "Interior constraints and regions"). A region is the face
// of the input's segments holding its point; separators cut faces into
// subdomain pieces but are no constraint of the input, so a region point in
// one subdomain may colour triangles of several. Each subdomain is meshed
// alone, so it gets its own regions: one point strictly inside each face of
// its own segments (rings and interior pieces) that lies in a region, with
// that region's attribute and area bound. Flooding those inside the
// subdomain gives every triangle the region the whole-domain flood gives it.
#include <utility>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"

namespace madd::detail {

struct RegionView {
  // Per subdomain: its regions, as above.
  std::vector<std::vector<Region>> regions;
  // Per segment of d: the smallest max_area (> 0) of the regions on its two
  // sides, +infinity for none: the regional size bound discretise splits it
  // for (the decoupling holds for the triangles next to it only if it does).
  std::vector<double> segment_area;
  // Per subdomain: (area, max_area) of each of its faces in a region with
  // max_area > 0, for the work estimate (a region's bound can make a
  // subdomain far finer than the size bound alone says).
  std::vector<std::vector<std::pair<double, double>>> bounded_faces;
};

// The regions of every subdomain of `d` and the regional bound along every
// segment; no regions and no bounds when d.regions is empty. The region of
// a face is decided once, on the constrained triangulation of every
// boundary and interior piece of d, by Triangle's rule (of two region
// points in one face the later wins). The subdomains' faces are found on
// `threads` threads; deterministic, the same for any count.
RegionView region_view(const Decomposition& d, unsigned threads = 1);

}  // namespace madd::detail
