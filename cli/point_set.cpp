#include "point_set.hpp"

#include "madd/error.hpp"

namespace madd::cli {

Triangulation triangulate_points(const Pslg& points, const std::string& path) {
  Triangulation tri = delaunay(points.points);
  if (tri.triangle_count() == 0) {
    const std::size_t n = points.points.size();
    const std::string why =
        n < 3 ? "only " + std::to_string(n) + " point(s)" : "all " + std::to_string(n) + " points lie on one line";
    throw InvalidInputError(InputProblem::empty_domain, why + ": there is no triangle", {}, {}, path, 0, 0);
  }
  return tri;
}

}  // namespace madd::cli
