#pragma once
// What the model grid writers (src/output/mesh_fort14.cpp, mesh_gr3.cpp,
// mesh_2dm.cpp) share: the checked columns of a ModelGrid, fort.14's node and
// element lines (hgrid.gr3 has the same), and the numbers' text.
#include <cstddef>
#include <string>
#include <vector>

#include "kernel/number_format.hpp"
#include "madd/mesh.hpp"
#include "madd/model_output.hpp"
#include "output/mesh_text.hpp"

namespace madd::detail {

// The columns a model file writes per mesh point: the grid's coordinates (or
// the mesh's points) and depths (or none: all 0).
struct ModelColumns {
  const std::vector<Point>* xy = nullptr;
  const std::vector<double>* depth = nullptr;
  double depth_at(std::size_t v) const { return depth != nullptr ? (*depth)[v] : 0.0; }
};

// Checks `grid` against `mesh`: coordinates and depth empty or one per point,
// all finite; the title one line. Throws OptionError naming the field.
ModelColumns model_columns(const Mesh& mesh, const ModelGrid& grid);

// A real as the shortest text that reads back as the same double (every
// model reads it exactly: Fortran list-directed input takes "1e-05").
inline void put_real(std::string& out, double v) { append_shortest(out, v); }

// The part fort.14 and hgrid.gr3 share: the title line, "NE NP" (with a
// comment), NP lines "JN X Y DP" and NE lines "JE 3 N1 N2 N3", 1-based, the
// lines made by bodies that read `mesh` and the columns' arrays.
SectionedText grid_text(const Mesh& mesh, const ModelGrid& grid, const ModelColumns& columns);

}  // namespace madd::detail
