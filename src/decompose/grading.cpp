// Graded decompositions (Sec. 5.2): per-face weights and required areas.
#include "decompose/grading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "madd/error.hpp"

#include "kernel/box.hpp"
#include "kernel/rings.hpp"

namespace madd::detail {

GradingMode grading_mode(const DecomposeOptions& options) {
  GradingMode m;
  m.area_driven = static_cast<bool>(options.subdomain_area_function) || !options.subdomain_area_samples.empty();
  m.a = options.gradation;
  m.p = options.interpolation;
  m.r = options.boundary_refinement;
  if (options.weight_function) {
    m.weights = WeightSource::function;
  } else if (!options.weight_samples.empty()) {
    m.weights = WeightSource::background;
  } else if (options.gradation > 0.0) {
    m.weights = WeightSource::boundary;
  }
  // A weight function or background weights grade by themselves: without a
  // gradation factor they count as much as the area (a = 1).
  if ((m.weights == WeightSource::function || m.weights == WeightSource::background) && !(m.a > 0.0)) m.a = 1.0;
  return m;
}

bool point_in_face(const Subdivision& sub, std::uint32_t face, Point p) {
  int winding = 0;
  for (const auto& ring : sub.faces[face].rings) winding += winding_number(RingView(sub.points, ring), p);
  return winding != 0;
}

namespace {
// A required area is a size: 0, a negative value or NaN has no meaning, and
// would either stop all splitting or never stop it, so it is refused like a
// background area of that value (check_options).
double checked_required_area(const std::function<double(double, double)>& subdomain_area_function, Point q) {
  const double v = subdomain_area_function(q.x, q.y);
  if (std::isfinite(v) && v > 0.0) return v;
  char where[96];
  std::snprintf(where, sizeof where, "(%.9g, %.9g) it is %.9g", q.x, q.y, v);
  throw OptionError("subdomain_area_function",
                    std::string("must be finite and > 0 everywhere in the domain; at ") + where);
}
}  // namespace

FaceSamples function_samples(const Subdivision& sub, std::uint32_t face, const DecomposeOptions& options) {
  Box box;
  for (std::uint32_t v : sub.faces[face].rings[0]) box.add(sub.points[v]);
  const double dx = box.width() / grid_cells;
  const double dy = box.height() / grid_cells;
  FaceSamples out;
  auto take = [&](Point q, double cell_area) {
    // A density cannot be negative: negative and NaN values count as 0.
    const double f = options.weight_function ? options.weight_function(q.x, q.y) : 0.0;
    if (options.weight_function) out.weights.push_back({q, f > 0.0 ? f * cell_area : 0.0});
    if (options.subdomain_area_function)
      out.areas.push_back({q, checked_required_area(options.subdomain_area_function, q)});
  };
  // Cell centres, so that the weight is a midpoint-rule integral of f over the face.
  for (int i = 0; i < grid_cells; ++i) {
    for (int j = 0; j < grid_cells; ++j) {
      const Point q{box.lo.x + (i + 0.5) * dx, box.lo.y + (j + 0.5) * dy};
      if (point_in_face(sub, face, q)) take(q, dx * dy);
    }
  }
  // A sliver no grid point falls into is still sampled once, at its interior point.
  if (out.weights.empty() && out.areas.empty()) take(sub.faces[face].interior, sub.face_area(face));
  return out;
}

FaceSamples background_samples(const DecomposeOptions& options, const std::vector<std::uint32_t>& weights_inside,
                               const std::vector<std::uint32_t>& areas_inside) {
  FaceSamples out;
  for (std::uint32_t i : weights_inside) out.weights.push_back(options.weight_samples[i]);
  for (std::uint32_t i : areas_inside) out.areas.push_back(options.subdomain_area_samples[i]);
  return out;
}

double boundary_weight(const Subdivision& sub, std::uint32_t face, const std::vector<double>& point_weights) {
  double total = 0.0;
  std::vector<std::uint32_t> counted;
  for (const auto& ring : sub.faces[face].rings) {
    for (std::uint32_t v : ring) total += point_weights[v];
    if (!sub.faces[face].inner_segments.empty()) counted.insert(counted.end(), ring.begin(), ring.end());
  }
  // The vertices of the interior segments weigh too, once each, as in the
  // split's density (split/density.cpp counts every working point that is a vertex).
  if (sub.faces[face].inner_segments.empty()) return total;
  std::vector<std::uint32_t> inner;
  for (const std::uint32_t seg : sub.faces[face].inner_segments) {
    inner.push_back(sub.segments[seg].a);
    inner.push_back(sub.segments[seg].b);
  }
  std::sort(counted.begin(), counted.end());
  std::sort(inner.begin(), inner.end());
  inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
  for (const std::uint32_t v : inner)
    if (!std::binary_search(counted.begin(), counted.end(), v)) total += point_weights[v];
  return total;
}

double required_area(const FaceSamples& samples) {
  double best = std::numeric_limits<double>::infinity();
  for (const ValuedPoint& s : samples.areas) {
    if (s.value > 0.0) best = std::min(best, s.value);
  }
  return best;
}

double sample_weight(const FaceSamples& samples) {
  double total = 0.0;
  for (const ValuedPoint& s : samples.weights) total += s.value;
  return total;
}

namespace {

double weight_along(const Subdivision& sub, std::uint32_t segment, Point at, const std::vector<double>& w) {
  const Segment& s = sub.segments[segment];
  const Point a = sub.points[s.a], b = sub.points[s.b];
  const double len = distance(a, b);
  const double t = len > 0.0 ? std::clamp(distance(a, at) / len, 0.0, 1.0) : 0.5;
  return (1.0 - t) * w[s.a] + t * w[s.b];
}

double base_weight(const Subdivision& sub, const EndRef& e, const std::vector<double>& w) {
  if (e.kind == EndRef::vertex) return w[e.id];
  if (e.kind == EndRef::inside_segment) return weight_along(sub, e.id, e.p, w);
  return 0.0;
}

}  // namespace

void collect_end_weights(const Subdivision& snapshot, const SplitResult& result,
                         const std::vector<double>& point_weights, double p, EndWeights& out) {
  // Circumcentres: mean of the boundary ends of the spokes meeting there.
  std::vector<std::pair<Point, std::pair<double, int>>> centres;
  auto add_centre = [&](Point c, double w) {
    for (auto& entry : centres) {
      if (entry.first == c) {
        entry.second.first += w;
        ++entry.second.second;
        return;
      }
    }
    centres.push_back({c, {w, 1}});
  };
  for (const SeparatorEdge& e : result.edges) {
    for (const EndRef* end : {&e.a, &e.b}) {
      const EndRef* other = end == &e.a ? &e.b : &e.a;
      if (end->kind == EndRef::inside_segment) out.push_back({end->p, p * base_weight(snapshot, *end, point_weights)});
      if (end->kind == EndRef::centre && other->kind != EndRef::centre) {
        add_centre(end->p, base_weight(snapshot, *other, point_weights));
      }
    }
  }
  for (const auto& [c, sum] : centres) out.push_back({c, p * sum.first / sum.second});
}

void assign_new_weights(const std::vector<Point>& points, EndWeights ends, std::vector<double>& point_weights) {
  const auto key = [](const std::pair<Point, double>& e) { return std::pair{e.first.x, e.first.y}; };
  std::stable_sort(ends.begin(), ends.end(), [&](const auto& l, const auto& r) { return key(l) < key(r); });
  for (std::size_t v = point_weights.size(); v < points.size(); ++v) {
    const std::pair<double, double> k{points[v].x, points[v].y};
    const auto it = std::lower_bound(ends.begin(), ends.end(), k,
                                     [&](const auto& e, const std::pair<double, double>& q) { return key(e) < q; });
    point_weights.push_back(it != ends.end() && key(*it) == k ? it->second : 0.0);
  }
}

}  // namespace madd::detail
