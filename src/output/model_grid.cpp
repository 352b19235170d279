// The checked columns of a ModelGrid (src/output/model_text.hpp, where the
// node and element lines fort.14 and hgrid.gr3 share are made).
#include <cmath>
#include <string>

#include "madd/error.hpp"
#include "output/model_text.hpp"

namespace madd::detail {

namespace {

template <typename Value, typename Finite>
void check_column(const std::vector<Value>& column, std::size_t points, const char* field, Finite finite) {
  if (!column.empty() && column.size() != points)
    throw OptionError(field, "must be empty or hold one value per mesh point (" + std::to_string(points) + "), not " +
                                 std::to_string(column.size()));
  for (std::size_t v = 0; v < column.size(); ++v)
    if (!finite(column[v])) throw OptionError(field, "must be finite (point " + std::to_string(v) + " is not)");
}

}  // namespace

ModelColumns model_columns(std::size_t points, const ModelGrid& grid) {
  check_column(grid.coordinates, points, "coordinates",
               [](Point p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  check_column(grid.depth, points, "depth", [](double d) { return std::isfinite(d); });
  if (grid.title.find_first_of("\r\n") != std::string::npos)
    throw OptionError("title", "must be one line (it is the file's first line)");
  ModelColumns columns;
  if (!grid.coordinates.empty()) columns.xy = &grid.coordinates;
  if (!grid.depth.empty()) columns.depth = &grid.depth;
  return columns;
}

}  // namespace madd::detail
