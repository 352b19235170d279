#pragma once
// The work of a subdomain: its expected number of triangles (docs/mesh.md,
// "Balance by work").
#include <cstddef>
#include <vector>

#include "madd/decomposition.hpp"
#include "madd/pslg.hpp"
#include "quality/area_bound.hpp"

namespace madd::detail {

// Per subdomain of the discretised decomposition `d` of `domain`: the
// triangles its mesh is expected to have; computed on `threads` threads (0:
// one per core), the same for any count.
std::vector<double> expected_triangles(const Decomposition& d, const Pslg& domain, const AreaBound& size,
                                       unsigned threads = 1);

// Sets the decomposition's weights so that it balances expected triangles
// rather than areas (when the options carry no weights of their own).
void weigh_by_work(DecomposeOptions& options, const Pslg& domain, const AreaBound& size);

// The Steiner points refinement of one subdomain may add before it stops
// (what is left below the bound is then counted as MeshShortfall::limit).
std::size_t steiner_budget(double expected_triangles, std::size_t ring_vertices);

}  // namespace madd::detail
