#include "input_domain.hpp"

#include <set>

#include "option_table.hpp"
#include "madd/error.hpp"
#include "madd/poly_io.hpp"
#include "madd/polygons.hpp"

namespace madd::cli {

CoastOptions coast_options(const CommandLine& line) {
  CoastOptions options = line.coast;
  const double hmin = line.mesh.size.min_edge_length;
  if (!line.min_island_area_given && hmin > 0) options.min_island_area = 4 * hmin * hmin;
  return options;
}

void default_coast_markers(MeshSizeOptions& size, const CoastDomain& coast, int open_marker) {
  if (!size.coast_markers.empty()) return;
  std::set<int> land;
  for (const Segment& s : coast.domain.segments)
    if (s.marker != open_marker) land.insert(s.marker);
  if (coast.report.open_segments > 0 && !land.empty()) size.coast_markers.assign(land.begin(), land.end());
}

void default_coast_markers(MeshSizeOptions& size, const std::string& path, const CoastDomain& coast,
                           const CommandLine& line) {
  if (is_polygon_file(path)) default_coast_markers(size, coast, line.coast.open_marker);
}

std::string coast_report_line(const std::string& path, const CoastDomain& coast) {
  const CoastReport& r = coast.report;
  std::string s = path + ": " + std::to_string(r.rings_read) + " rings read; kept 1 of " + std::to_string(r.bodies) +
                  " water bodies, " + std::to_string(r.islands) + " islands (" +
                  std::to_string(r.small_islands_removed) + " small ones removed); " +
                  std::to_string(r.vertices_merged) + " vertices merged, " + std::to_string(r.spikes_removed) +
                  " spikes, " + std::to_string(r.crossings_resolved) + " crossings, " + std::to_string(r.pinches) +
                  " touching points, " + std::to_string(r.pockets_dropped) + " pockets cut off; " +
                  std::to_string(r.open_segments) + " open and " + std::to_string(r.land_segments) + " land segments";
  if (coast.projection.geographic) {
    char centre[96];
    std::snprintf(centre, sizeof centre, "; projected about lon %.6g, lat %.6g", coast.projection.lon0_deg,
                  coast.projection.lat0_deg);
    s += centre;
  }
  return s;
}

CoastDomain read_input_domain(const std::string& path, const CommandLine& line, std::FILE* notes,
                              const ValidateOptions& validation) {
  if (!is_polygon_file(path)) {
    // A box, a water point or an island area on a .poly would be ignored: say so instead.
    const char* field = line.coast.clip              ? "clip"
                        : line.coast.water_at        ? "water_at"
                        : line.min_island_area_given ? "min_island_area"
                                                     : nullptr;
    if (field != nullptr) {
      const OptionError e(field, "applies to GeoJSON and shapefile inputs (.geojson, .json, .shp) only");
      throw OptionError(e.option(), e.requirement(), cli_message(e, Scope::coast, options_of("mesh"), line, false));
    }
    return CoastDomain{read_domain(path, validation), {}, {}};
  }
  CoastDomain coast = [&] {
    try {
      return read_coast(path, coast_options(line));
    } catch (const OptionError& e) {
      throw OptionError(e.option(), e.requirement(), cli_message(e, Scope::coast, options_of("mesh"), line));
    }
  }();
  if (notes != nullptr) std::fprintf(notes, "%s\n", coast_report_line(path, coast).c_str());
  return coast;
}

}  // namespace madd::cli
