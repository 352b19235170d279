#pragma once
// The angle figures `madd mesh --report` and `madd-mpi mesh` print.
#include <cstddef>

#include "madd/mesh.hpp"
#include "madd/mesh_share.hpp"

namespace madd::cli {

// Angle figures of the mesh: the smallest angle, a histogram in 10-degree
// bins of each triangle's smallest angle, and the share below the bound.
struct AngleFigures {
  double min_deg = 180, median_deg = 0;
  std::size_t bins[6] = {};  // [0,10) [10,20) [20,30) [30,40) [40,50) [50,60]
  std::size_t below = 0;
};

AngleFigures angle_figures(const Mesh& m);
AngleFigures angle_figures(const LocalMesh& m);  // a madd-mpi share's part

} // namespace madd::cli
