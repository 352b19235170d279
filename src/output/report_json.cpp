// Output 5: the quality report, every figure of docs/quality.md as one JSON
// object. Key names match those of the independent checker used in development
// (ddcheck.py) where both compute a figure.
#include "madd/output.hpp"
#include "kernel/number_format.hpp"
#include "output/json_object.hpp"

namespace madd {

std::string format_report_json(const Metrics& m) {
  std::string out;
  detail::JsonObject o(out);
  o.count("subdomains", m.subdomains);
  o.count("points", m.points);
  o.count("segments", m.segments);
  o.count("separator_segments", m.separator_segments);
  o.number("domain_area", m.domain_area);
  o.number("mean_area", m.mean_area);
  o.number("min_angle_bound", m.min_angle_bound_deg);
  o.count("new_angles", m.new_angles);
  o.number("angle_min", m.angle_min);
  o.number("angle_p10", m.angle_p10);
  o.number("angle_median", m.angle_median);
  o.number("angle_p90", m.angle_p90);
  o.count("boundary_angles", m.boundary_angles);
  o.number("boundary_angle_min", m.boundary_angle_min);
  o.number("boundary_angle_median", m.boundary_angle_median);
  o.number("separator_length", m.separator_length);
  o.number("separator_length_norm", m.separator_length_norm);
  o.number("mean_separator_per_subdomain", m.mean_separator_per_subdomain);
  o.number("max_sep_len_over_area_norm", m.max_separator_over_area_norm);
  o.number("max_area_over_mean", m.max_area_over_mean);
  o.number("min_area_over_mean", m.min_area_over_mean);
  o.number("max_weight_over_mean", m.max_weight_over_mean);
  o.number("min_weight_over_mean", m.min_weight_over_mean);
  o.number("shortest_new_segment_norm", m.shortest_new_segment_norm);
  if (m.subdomain_area_ratio > 0.0) {  // only for a decomposition split to a required area
    o.number("area_ratio_bound", m.subdomain_area_ratio);
    o.number("max_area_over_required", m.max_area_over_required);
    o.count("subdomains_over_area_bound", m.subdomains_over_area_bound);
  }
  o.key("times");
  out += "{";
  for (std::size_t i = 0; i < m.times.size(); ++i) {
    out += i == 0 ? "" : ", ";
    detail::append_json_string(out, m.times[i].name);
    out += ": ";
    detail::append_shortest(out, m.times[i].seconds);
  }
  out += "}";
  o.close();
  return out;
}

}  // namespace madd
