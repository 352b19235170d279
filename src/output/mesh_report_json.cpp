// The mesh report (include/madd/mesh_output.hpp): the figures of a mesh, then
// those of the run, as `madd mesh --report` and `madd-mpi mesh --report` write them.
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "madd/mesh_output.hpp"
#include "kernel/number_format.hpp"
#include "output/json_object.hpp"

namespace madd {

namespace {

// Seconds vary from run to run: six digits say all they can.
void append_seconds(std::string& out, double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", seconds);
  out += buffer;
}

void add_run_figure(detail::JsonObject& o, std::string& out, const RunFigure& figure) {
  if (const auto* number = std::get_if<double>(&figure.value)) {
    o.number(figure.name, *number, detail::JsonObject::Digits::all);
  } else if (const auto* list = std::get_if<std::vector<double>>(&figure.value)) {
    o.key(figure.name);
    out += "[";
    for (std::size_t i = 0; i < list->size(); ++i) {
      out += i ? ", " : "";
      append_seconds(out, (*list)[i]);
    }
    out += "]";
  } else {
    const auto& phases = std::get<std::vector<PhaseTime>>(figure.value);
    o.key(figure.name);
    out += "{";
    for (std::size_t i = 0; i < phases.size(); ++i) {
      out += i ? ", " : "";
      detail::append_json_string(out, phases[i].name);
      out += ": ";
      append_seconds(out, phases[i].seconds);
    }
    out += "}";
  }
}

}  // namespace

std::string format_mesh_report_json(const MeshMetrics& m, const std::vector<RunFigure>& run) {
  std::string out;
  detail::JsonObject o(out);
  constexpr auto all = detail::JsonObject::Digits::all;  // as madd mesh has always written them
  o.count("subdomains", m.subdomains);
  o.count("triangles", m.triangles);
  o.count("vertices", m.vertices);
  o.number("min_angle_bound_deg", m.min_angle_bound_deg, all);
  o.number("max_area_bound", m.max_area_bound, all);
  o.number("smallest_angle_deg", m.smallest_angle_deg, all);
  if (!std::isnan(m.median_smallest_angle_deg)) o.number("median_smallest_angle_deg", m.median_smallest_angle_deg, all);
  o.count("below_bound", m.below_bound);
  o.number("share_below_bound", m.share_below_bound(), all);
  o.count("below_bound_input_angle", m.shortfall.input_angle);
  o.count("below_bound_separator", m.shortfall.separator);
  o.count("below_bound_precision", m.shortfall.precision);
  o.count("below_bound_limit", m.shortfall.limit);
  o.key("smallest_angle_histogram_10deg");
  out += "[";
  for (std::size_t i = 0; i < m.smallest_angle_histogram.size(); ++i) {
    out += i ? ", " : "";
    detail::append_int(out, static_cast<std::int64_t>(m.smallest_angle_histogram[i]));
  }
  out += "]";
  o.number("max_over_mean_triangles", m.max_over_mean_triangles(), all);
  for (const RunFigure& figure : run) add_run_figure(o, out, figure);
  o.close();
  return out;
}

}  // namespace madd
