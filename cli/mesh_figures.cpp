// The angle figures of a mesh (cli/mesh_figures.hpp).
#include "mesh_figures.hpp"

#include <algorithm>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::cli {

namespace {

template <typename AnyMesh>  // Mesh or LocalMesh: the same fields
AngleFigures figures_of(const AnyMesh& m) {
  AngleFigures f;
  std::vector<double> smallest(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    double s = 180;
    for (int i = 0; i < 3; ++i) {
      const Point a = m.points[m.triangles[t][i]], b = m.points[m.triangles[t][(i + 1) % 3]],
                  c = m.points[m.triangles[t][(i + 2) % 3]];
      s = std::min(s, angle_at(a, b, c) * 180.0 / 3.14159265358979323846);
    }
    smallest[t] = s;
    f.min_deg = std::min(f.min_deg, s);
    ++f.bins[std::min<std::size_t>(5, static_cast<std::size_t>(s / 10))];
    f.below += s < m.min_triangle_angle_deg - 1e-9;
  }
  if (!smallest.empty()) {
    std::nth_element(smallest.begin(), smallest.begin() + static_cast<std::ptrdiff_t>(smallest.size() / 2), smallest.end());
    f.median_deg = smallest[smallest.size() / 2];
  }
  return f;
}

} // namespace

AngleFigures angle_figures(const Mesh& m) { return figures_of(m); }
AngleFigures angle_figures(const LocalMesh& m) { return figures_of(m); }

} // namespace madd::cli
