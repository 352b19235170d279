// The size bound at a point: max_triangle_area, hmax, the area function, the
// samples and the size field, the smallest of those that are set (area_bound.hpp).
#include "quality/area_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "madd/error.hpp"

namespace madd {

namespace detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

namespace {

// The field of a bound built without the domain: none, and field terms refused.
SizeField no_field(const MeshSizeOptions& size) {
  if (size.has_field_terms())
    throw OptionError("distance_rate",
                      "the distance, feature-size and gradation terms of the size field need the domain they grade");
  return SizeField();
}

double constant_bound(const MeshSizeOptions& size) {
  double bound = size.max_triangle_area > 0.0 ? size.max_triangle_area : infinity;
  if (size.max_edge_length > 0.0) bound = std::min(bound, area_of_edge(size.max_edge_length));
  return bound;
}

}  // namespace

AreaBound::AreaBound(const MeshSizeOptions& size, const Pslg* domain, unsigned threads)
    : size_(size), constant_(constant_bound(size)), samples_(size.triangle_area_samples, size.sample_interpolation),
      field_(domain ? SizeField(*domain, size, threads) : no_field(size)) {
  if (!size.triangle_area_function && size.triangle_area_samples.empty()) {
    const double floor = field_.least_edge();  // 0 without hmin: no floor
    least_ = field_.empty() ? constant_ : floor > 0.0 ? std::min(constant_, area_of_edge(floor)) : 0.0;
    if (!field_.empty()) edge_slope_ = size.size_gradation;
  }
}

double AreaBound::area_of_field_edge(double h) const noexcept {
  return h > 0.0 ? std::min(constant_, area_of_edge(h)) : constant_;
}

bool AreaBound::uniform() const noexcept {
  return !size_.triangle_area_function && size_.triangle_area_samples.empty() && field_.empty();
}

double AreaBound::area_at(Point p, BoundHint* hint) const {
  double bound = constant_;
  if (size_.triangle_area_function) {
    const double v = size_.triangle_area_function(p.x, p.y);
    if (v > 0.0) bound = std::min(bound, v);  // false for NaN too: ignored
  }
  if (!size_.triangle_area_samples.empty()) {
    const double v =
        samples_.area_at(p, hint != nullptr ? &hint->samples : nullptr);  // +infinity where the samples set no bound
    if (v > 0.0) bound = std::min(bound, v);
  }
  if (!field_.empty()) bound = std::min(bound, area_of_field_edge(field_edge_at(p, hint)));
  return bound;
}

}  // namespace detail

// The same code as the mesher's and verify_mesh's bound (built for one
// query: O(samples), like a scan; with field terms, the whole field). For
// many queries with the same options the library builds a detail::AreaBound once.
double area_bound_at(const MeshSizeOptions& size, Point p) { return detail::AreaBound(size).area_at(p); }
double area_bound_at(const MeshSizeOptions& size, const Pslg& domain, Point p) {
  return detail::AreaBound(size, &domain).area_at(p);
}

}  // namespace madd
