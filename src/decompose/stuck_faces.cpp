#include "decompose/stuck_faces.hpp"

#include <cstdio>
#include <queue>
#include <utility>

namespace madd::detail {

void StuckFaces::mark(Subdivision& sub, std::uint32_t face, const DecompositionError& error) {
  if (vertices_.size() < sub.faces.size()) vertices_.resize(sub.faces.size(), 0);
  vertices_[face] = sub.ring_vertex_count(face);
  sub.faces[face].plan = 1;
  changed_ = true;
  last_error_ = error.what();
  last_face_ = error.subdomain();
  last_area_ = error.area();
  separator_angle_deg_ = error.separator_angle_deg();
}

void StuckFaces::release_changed(const Subdivision& sub) {
  for (std::uint32_t f = 0; f < vertices_.size() && f < sub.faces.size(); ++f) {
    if (vertices_[f] != 0 && vertices_[f] != sub.ring_vertex_count(f)) {
      vertices_[f] = 0;
      changed_ = true;
    }
  }
}

std::size_t StuckFaces::count() const {
  std::size_t n = 0;
  for (const std::size_t v : vertices_) n += v != 0 ? 1 : 0;
  return n;
}

void StuckFaces::replan(Subdivision& sub, const GradingState& grading, std::uint32_t target) {
  if (!changed_) return;
  changed_ = false;
  const auto faces = static_cast<std::uint32_t>(sub.faces.size());
  std::uint32_t left = target > faces ? target - faces : 0;  // beyond one per face
  // Largest weight per planned subdomain first; the lower face id on a tie.
  using Entry = std::pair<double, std::int64_t>;  // (weight per part, -face)
  std::priority_queue<Entry> open;
  for (std::uint32_t f = 0; f < faces; ++f) {
    sub.faces[f].plan = 1;
    if (!is_stuck(f)) open.push({grading.weight(sub, f), -static_cast<std::int64_t>(f)});
  }
  if (left > 0 && open.empty()) {
    char message[400];
    std::snprintf(message, sizeof message,
                  "no subdomain can be split with every new angle >= %g degrees: reached %u of %u subdomains "
                  "(%zu cannot be split; the last: %s)",
                  separator_angle_deg_, faces, target, count(), last_error_.c_str());
    throw DecompositionError(message, last_face_, last_area_, separator_angle_deg_);
  }
  for (; left > 0; --left) {
    const auto f = static_cast<std::uint32_t>(-open.top().second);
    open.pop();
    ++sub.faces[f].plan;
    open.push({grading.weight(sub, f) / sub.faces[f].plan, -static_cast<std::int64_t>(f)});
  }
}

}  // namespace madd::detail
