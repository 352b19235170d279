#pragma once
// The work of a subdomain: its expected number of triangles (docs/mesh.md,
// "Balance by work").
#include <cstddef>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"
#include "mesh/narrow_gaps.hpp"
#include "mesh/subdomain_regions.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// The whole domain as the work estimate reads it, built once per run after
// the size bound and read by both of its uses: the decomposition's weights
// (weigh_by_work, before decomposing) and every subdomain's estimate
// (expected_triangles, after). Keeps references to `domain` and `size`.
struct DomainWork {
  // `domain` passed validate(). The excess is found on `threads` threads
  // (0: one per core), the same for any count.
  DomainWork(const Pslg& domain, const AreaBound& size, unsigned threads = 1);
  const Pslg& domain;
  const AreaBound& size;
  Triangulation triangulation;  // the domain's constrained Delaunay triangulation
  NarrowGaps gaps;
  // The triangles the estimate's terms do not count, as samples (each in
  // triangles, a hair inside the domain): under one bound everywhere (whose
  // interior is counted by area) the narrow gaps' and the input's small
  // features' excess, a sample per piece of each triangle of the
  // triangulation where a gap binds at its centroid or a corner's local
  // feature size is below the bound's edge (work.cpp, excess_of_features),
  // and the pinches (pinch_excess); under a varying bound (whose
  // integral counts the gaps) the pinches only; without a bound, none. The
  // subdomains' and faces' estimates add them; the weights only under one bound.
  std::vector<ValuedPoint> excess;
};

// Per subdomain of the discretised decomposition `d` of work.domain: the
// triangles its mesh is expected to have; computed on `threads` threads (0:
// one per core), the same for any count. `before`, when given, is `d`
// before the decoupling split its segments (the same subdomains, their
// rings without the split points): under a varying bound the interiors are
// integrated over its rings' triangulations, the boundary layers along d's
// pieces. `view`, when given, is region_view(d) or region_view(*before)
// (the decoupling's split points change no face).
std::vector<double> expected_triangles(const Decomposition& d, const DomainWork& work, unsigned threads = 1,
                                       const Decomposition* before = nullptr, const RegionView* view = nullptr);

// The triangles expected in `face` of a decomposition of work.domain, given
// as DecomposeOptions::face_work gets it: the subdomain estimate above, on
// the face's rings (no interior segments, no region's finer bound).
double expected_triangles_of_face(const Pslg& face, const DomainWork& work);

// Under a varying bound: what the pieces of `face` (a face of a
// decomposition, its separators marker 0) add to its interior's triangles
// (docs/mesh.md, "Balance by work": each piece the decoupling makes), the
// face cut as the decoupling would cut it alone (detail::discretise on the
// face: its own features, not those beyond its separators). Part of
// expected_triangles_of_face.
double face_pieces_layer(const Pslg& face, const AreaBound& size);

// Sets the decomposition's weights so that it balances expected triangles
// rather than areas (when the options carry no weights of their own), and
// the repair to balance each face's expected triangles (face_work).
void weigh_by_work(DecomposeOptions& options, const DomainWork& work);

// The Steiner points refinement of one subdomain may add before it stops
// (what is left below the bound is then counted as MeshShortfall::limit).
std::size_t steiner_budget(double expected_triangles, std::size_t ring_vertices);

}  // namespace madd::detail
