// A background mesh read from a .node file (include/madd/poly_io.hpp): the
// samples of density weights or areas that grading and sizing interpolate.
#include <cmath>
#include <string>
#include <vector>

#include "kernel/number_format.hpp"
#include "madd/error.hpp"
#include "madd/poly_io.hpp"

namespace madd {

std::vector<ValuedPoint> read_background_samples(const std::string& path, SampleValue value) {
  const PolyFile file = read_poly_file(path);
  const Pslg& p = file.pslg;
  const bool areas = value == SampleValue::area;
  const char* what = areas ? "required area" : "density weight";
  // The header says how many attributes a node has: without one there is no value, however many nodes.
  if (p.attributes_per_point == 0)
    throw ParseError(path, 1, 1, std::string("a background mesh needs one attribute per node, the ") + what);
  const auto line_of = [&](std::size_t i) -> std::size_t {
    return i < file.source.point_lines.size() ? file.source.point_lines[i] : 1;
  };
  std::vector<ValuedPoint> samples;
  samples.reserve(p.points.size());
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const double v = p.attribute(i, 0);
    if (!(std::isfinite(v) && (areas ? v > 0 : v >= 0)))
      throw ParseError(path, line_of(i), 1,
                       "node " + std::to_string(p.first_index + i) + ": a " + what +
                           (areas ? " must be > 0" : " must be >= 0") + " and finite, got " + detail::number_text(v));
    samples.push_back({p.points[i], v});
  }
  return samples;
}

}  // namespace madd
