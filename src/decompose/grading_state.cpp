// The driver's grading state between rounds (Sec. 5.2).
#include <numeric>
#include <optional>

#include "decompose/grading.hpp"

#include "kernel/box.hpp"
#include "kernel/rings.hpp"

namespace madd::detail {

GradingState::GradingState(const DecomposeOptions& options, const Pslg& domain)
    : options_(options), mode_(grading_mode(options)) {
  if (mode_.weights == WeightSource::boundary) {
    point_weights_.assign(domain.points.size(), 0.0);
    if (domain.attributes_per_point > 0) {
      for (std::size_t i = 0; i < domain.points.size(); ++i) point_weights_[i] = domain.attribute(i, 0);
    }
  }
  // Face 0 is the whole domain: every background point starts there (points
  // outside the domain are dropped on the first split, or by required()).
  weights_inside_.resize(1);
  areas_inside_.resize(1);
  if (mode_.weights == WeightSource::background) {
    weights_inside_[0].resize(options.weight_samples.size());
    std::iota(weights_inside_[0].begin(), weights_inside_[0].end(), 0u);
  }
  if (!options.subdomain_area_function && !options.subdomain_area_samples.empty()) {
    areas_inside_[0].resize(options.subdomain_area_samples.size());
    std::iota(areas_inside_[0].begin(), areas_inside_[0].end(), 0u);
  }
}

FaceSamples GradingState::samples(const Subdivision& sub, std::uint32_t face) const {
  FaceSamples out;
  if (options_.weight_function || options_.subdomain_area_function) out = function_samples(sub, face, options_);
  FaceSamples bg = background_samples(options_, weights_inside_[face], areas_inside_[face]);
  // The first face holds every point, some perhaps outside the domain: filter them.
  std::optional<WindingIndex> filter;
  if (sub.faces.size() == 1 && (!bg.weights.empty() || !bg.areas.empty()))
    filter.emplace(sub.points, sub.faces[face].rings);
  if (!options_.weight_function) {
    for (const ValuedPoint& p : bg.weights) {
      if (!filter || filter->winding(p.at) != 0) out.weights.push_back(p);
    }
  }
  if (!options_.subdomain_area_function) {
    for (const ValuedPoint& p : bg.areas) {
      if (!filter || filter->winding(p.at) != 0) out.areas.push_back(p);
    }
  }
  return out;
}

FaceDensity GradingState::density(const Subdivision& sub, std::uint32_t face) const {
  FaceDensity d;
  if (!mode_.graded()) return d;
  d.graded = true;
  d.r = mode_.r;
  d.a = mode_.a;
  if (mode_.weights == WeightSource::boundary) {
    d.point_weights = &point_weights_;
  } else {
    d.samples = samples(sub, face).weights;
  }
  return d;
}

double GradingState::weight(const Subdivision& sub, std::uint32_t face) const {
  const double area = sub.face_area(face);
  if (!mode_.graded()) return area;
  const double w = mode_.weights == WeightSource::boundary ? boundary_weight(sub, face, point_weights_)
                                                           : sample_weight(samples(sub, face));
  return mode_.r * area + mode_.a * w;
}

double GradingState::required(const Subdivision& sub, std::uint32_t face) const {
  return required_area(samples(sub, face));
}

void GradingState::before_commit(const Subdivision& snapshot, const SplitResult& result) {
  if (mode_.weights == WeightSource::boundary) collect_end_weights(snapshot, result, point_weights_, mode_.p, ends_);
}

void GradingState::after_commit(const Subdivision& sub, std::uint32_t face, std::uint32_t added) {
  weights_inside_.resize(sub.faces.size());
  areas_inside_.resize(sub.faces.size());
  // Each point goes to exactly one side: the face it is in, else the other.
  // The side with fewer ring vertices is tested (a winding number costs one
  // step per vertex, and a coast's rings have thousands), after its outer
  // ring's bounding box. The first split also drops the points outside the
  // domain, so there both sides are tested.
  const bool first = sub.faces.size() == 2;
  const bool face_smaller = sub.ring_vertex_count(face) <= sub.ring_vertex_count(added);
  const std::uint32_t tested = face_smaller ? face : added, other = face_smaller ? added : face;
  Box box;
  for (const std::uint32_t v : sub.faces[tested].rings[0]) box.add(sub.points[v]);
  const WindingIndex in_tested_face(sub.points, sub.faces[tested].rings);
  std::optional<WindingIndex> in_other_face;
  if (first) in_other_face.emplace(sub.points, sub.faces[other].rings);
  for (auto* lists : {&weights_inside_, &areas_inside_}) {
    const auto& pts = lists == &weights_inside_ ? options_.weight_samples : options_.subdomain_area_samples;
    std::vector<std::uint32_t> in_tested, in_other;
    for (std::uint32_t i : (*lists)[face]) {
      const Point p = pts[i].at;
      const bool in_box = p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y;
      if (in_box && in_tested_face.winding(p) != 0) {
        in_tested.push_back(i);
      } else if (!first || in_other_face->winding(p) != 0) {
        in_other.push_back(i);
      }
    }
    (*lists)[tested] = std::move(in_tested);
    (*lists)[other] = std::move(in_other);
  }
}

void GradingState::end_round(const Subdivision& sub) {
  if (mode_.weights != WeightSource::boundary) return;
  assign_new_weights(sub.points, std::move(ends_), point_weights_);
  ends_.clear();
}

// The samples inside a face, by its outer ring's bounding box first.
std::vector<ValuedPoint> GradingState::weights_in(const Subdivision& sub, std::uint32_t face) const {
  Box box;
  for (const std::uint32_t v : sub.faces[face].rings[0]) box.add(sub.points[v]);
  std::vector<ValuedPoint> out;
  const WindingIndex in_face(sub.points, sub.faces[face].rings);
  for (const ValuedPoint& p : options_.weight_samples) {
    if (p.at.x < box.lo.x || p.at.x > box.hi.x || p.at.y < box.lo.y || p.at.y > box.hi.y) continue;
    if (in_face.winding(p.at) != 0) out.push_back(p);
  }
  return out;
}

double GradingState::weight_from_scratch(const Subdivision& sub, std::uint32_t face) const {
  double w = 0.0;
  for (const ValuedPoint& p : weights_in(sub, face)) w += p.value;
  return mode_.r * sub.face_area(face) + mode_.a * w;
}

FaceDensity GradingState::density_from_scratch(const Subdivision& sub, std::uint32_t face) const {
  FaceDensity d;
  d.graded = true;
  d.r = mode_.r;
  d.a = mode_.a;
  d.samples = weights_in(sub, face);
  return d;
}

void GradingState::reassign(const Subdivision& sub) {
  std::vector<Box> boxes(sub.faces.size());
  std::vector<WindingIndex> faces;
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    for (const std::uint32_t v : sub.faces[f].rings[0]) boxes[f].add(sub.points[v]);
    faces.emplace_back(sub.points, sub.faces[f].rings);
  }
  for (auto* lists : {&weights_inside_, &areas_inside_}) {
    const auto& pts = lists == &weights_inside_ ? options_.weight_samples : options_.subdomain_area_samples;
    if (pts.empty()) continue;
    lists->assign(sub.faces.size(), {});
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
      const Point p = pts[i].at;
      for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
        const Box& b = boxes[f];
        if (p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y) continue;
        if (faces[f].winding(p) != 0) {
          (*lists)[f].push_back(i);
          break;
        }
      }
    }
  }
}

}  // namespace madd::detail
