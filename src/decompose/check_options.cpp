// The one check of DecomposeOptions: every range and every conflict between
// options lives here, so that the CLI, the script language and library callers
// all refuse the same values with the same words (include/madd/decomposition.hpp).
#include <cmath>
#include <string>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"

namespace madd {
namespace {

bool finite_at_least(double x, double low) { return std::isfinite(x) && x >= low; }
bool finite_above(double x, double low) { return std::isfinite(x) && x > low; }

[[noreturn]] void refuse(const char* option, const std::string& requirement) { throw OptionError(option, requirement); }

void check_ranges(const DecomposeOptions& o) {
  if (o.subdomains == 0) refuse("subdomains", "must be at least 1");
  // Phi0 = 0 would accept any separator, and at 90 degrees no corner can be split (paper Sec. 3).
  if (!(o.separator_angle_deg > 0.0 && o.separator_angle_deg < 90.0))
    refuse("separator_angle_deg", "must lie strictly between 0 and 90 degrees");
  if (!finite_above(o.boundary_refinement, 0.0)) refuse("boundary_refinement", "must be a finite number > 0");
  // i is the share of its target each side must reach (Sec. 4.3): 0 accepts anything, above 1 nothing.
  if (!(o.min_split_quality > 0.0 && o.min_split_quality <= 1.0)) refuse("min_split_quality", "must lie in (0, 1]");
  if (o.threads > max_threads) refuse("threads", "must be at most " + std::to_string(max_threads) + " (0 = all cores)");
  if (o.max_split_retries < 0 || o.max_split_retries > 64) refuse("max_split_retries", "must lie in [0, 64]");
  if (!(o.adaptive_boundary_refinement >= 1.0 && o.adaptive_boundary_refinement <= 64.0))
    refuse("adaptive_boundary_refinement", "must lie in [1, 64] (1 = every edge refined alike)");
  if (!(o.repair_balance_above == 0.0 || (o.repair_balance_above >= 1.0 && o.repair_balance_above <= 1e6)))
    refuse("repair_balance_above", "must be 0 (off) or lie in [1, 1e6]");
  if (o.smoothing_iterations < 0 || o.smoothing_iterations > 1000)
    refuse("smoothing_iterations", "must lie in [0, 1000] (0 = no smoothing)");
  if (!finite_at_least(o.gradation, 0.0)) refuse("gradation", "must be a finite number >= 0");
  if (!finite_at_least(o.interpolation, 0.0)) refuse("interpolation", "must be a finite number >= 0");
  if (!finite_above(o.subdomain_area_ratio, 0.0)) refuse("subdomain_area_ratio", "must be a finite number > 0");
  if (!finite_at_least(o.time_limit_seconds, 0.0))
    refuse("time_limit_seconds", "must be a finite number >= 0 (0 = none)");
}

void check_background(const std::vector<ValuedPoint>& points, bool areas) {
  const char* option = areas ? "subdomain_area_samples" : "weight_samples";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ValuedPoint& p = points[i];
    const bool value_ok = areas ? finite_above(p.value, 0.0) : finite_at_least(p.value, 0.0);
    if (std::isfinite(p.at.x) && std::isfinite(p.at.y) && value_ok) continue;
    refuse(option, std::string("must hold finite points with ") + (areas ? "required areas > 0" : "weights >= 0") +
                       "; point " + std::to_string(i) + " has " + (value_ok ? "a non-finite position" : "a bad value"));
  }
}

// Sec. 5.2 grades by one source of weights and one of required areas; two
// sources of the same thing would silently drop one, so they are refused.
void check_sources(const DecomposeOptions& o) {
  if (o.weight_function && !o.weight_samples.empty())
    refuse("weight_samples", "cannot be combined with weight_function: give one source of density weights");
  if (o.subdomain_area_function && !o.subdomain_area_samples.empty())
    refuse("subdomain_area_samples",
           "cannot be combined with subdomain_area_function: give one source of required areas");
  const bool weights_from_boundary = !o.weight_function && o.weight_samples.empty() && o.gradation > 0.0;
  if (o.interpolation > 0.0 && !weights_from_boundary)
    refuse("interpolation", "only applies to boundary weights (gradation > 0 without weight_function or "
                            "weight_samples); it would be ignored");
}

}  // namespace

void check_option_ranges(const DecomposeOptions& options) {
  check_ranges(options);
  check_background(options.weight_samples, false);
  check_background(options.subdomain_area_samples, true);
}

void check_options(const DecomposeOptions& options) {
  check_option_ranges(options);
  check_sources(options);
}

void check_options(const DecomposeOptions& options, const Pslg& domain) {
  check_options(options);
  const bool weights_from_boundary =
      !options.weight_function && options.weight_samples.empty() && options.gradation > 0.0;
  if (weights_from_boundary && domain.attributes_per_point == 0)
    refuse("gradation", "grades by the domain's vertex weights (attribute 1), but the domain has none: give "
                        "weights in the .poly, a weight function or background weights, or leave gradation at 0");
}

bool has_required_area(const DecomposeOptions& options) noexcept {
  return static_cast<bool>(options.subdomain_area_function) || !options.subdomain_area_samples.empty();
}

std::uint32_t expected_subdomain_count(const Decomposition& decomposition, std::uint32_t requested) noexcept {
  const auto made = static_cast<std::uint32_t>(decomposition.subdomains.size());
  // Split to a required area (Sec. 5.2), N is a maximum: splitting stops once
  // every subdomain is within the bound, so fewer subdomains is a correct result.
  if (decomposition.subdomain_area_ratio > 0.0 && made >= 1 && made <= requested) return made;
  return requested;
}

}  // namespace madd

namespace madd {

std::vector<std::uint32_t> interior_segment_owners(const Decomposition& decomposition) {
  std::vector<std::uint32_t> owner(decomposition.segments.size(), no_index);
  for (std::uint32_t s = 0; s < decomposition.subdomains.size(); ++s) {
    for (const std::uint32_t seg : decomposition.subdomains[s].interior_segments) {
      if (seg < owner.size()) owner[seg] = s;
    }
  }
  return owner;
}

}  // namespace madd
