#include "background_mesh.hpp"

#include <cmath>
#include <cstdio>

#include "madd/error.hpp"
#include "madd/poly_io.hpp"

namespace madd::cli {

namespace {
std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}
} // namespace

std::vector<ValuedPoint> read_background(const std::string& path, bool areas) {
  const PolyFile file = read_poly_file(path);
  const Pslg& p = file.pslg;
  const auto line_of = [&](std::size_t i) -> std::size_t {
    return i < file.source.point_lines.size() ? file.source.point_lines[i] : 1;
  };
  const char* what = areas ? "required area" : "density weight";
  if (p.attributes_per_point == 0)
    throw ParseError(path, 1, 1, std::string("a background mesh needs one attribute per node, the ") + what);
  std::vector<ValuedPoint> out;
  out.reserve(p.points.size());
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const double v = p.attribute(i, 0);
    if (!(std::isfinite(v) && (areas ? v > 0 : v >= 0)))
      throw ParseError(path, line_of(i), 1,
                       std::string("node ") + std::to_string(p.first_index + i) + ": a " + what + (areas ? " must be > 0" : " must be >= 0") +
                           " and finite, got " + number_text(v));
    out.push_back({p.points[i], v});
  }
  return out;
}

} // namespace madd::cli
