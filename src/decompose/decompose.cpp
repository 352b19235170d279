// The N-way driver (Algorithm 4, Sec. 5), run in rounds: every face still
// planned to become k > 1 subdomains is split in the same round, the splits
// computed in parallel from one snapshot and committed in face-id order
// (decompose/scheduler.hpp), so the output is identical for any thread count.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <unordered_map>

#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/triangulation.hpp"
#include "decompose/grading.hpp"
#include "kernel/resource_limits.hpp"
#include "split/split.hpp"
#include "decompose/decompose_valid.hpp"
#include "decompose/rebalance.hpp"
#include "decompose/scheduler.hpp"
#include "decompose/stuck_faces.hpp"
#include "kernel/stopwatch.hpp"
#include "subdivision/subdivision.hpp"

namespace madd {

namespace detail {

// New-angle check of the committed geometry (C1), independent of the split logic.
void check_new_angles(const Subdivision& sub, double separator_angle_deg);

}  // namespace detail

namespace {

using detail::Subdivision;

// Face f of `sub` as a domain of its own, as DecomposeOptions::face_work reads it.
Pslg face_domain(const Subdivision& sub, std::uint32_t f) {
  Pslg out;
  out.first_index = 0;
  out.has_segment_markers = true;
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  const auto id = [&](std::uint32_t v) {
    const auto [it, fresh] = local.try_emplace(v, static_cast<std::uint32_t>(out.points.size()));
    if (fresh) out.points.push_back(sub.points[v]);
    return it->second;
  };
  const detail::Face& face = sub.faces[f];
  for (std::size_t r = 0; r < face.rings.size(); ++r) {
    const auto& ring = face.rings[r];
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::uint32_t seg = face.ring_segments[r][k];
      const int marker =
          sub.origin[seg] == no_index ? 0 : (sub.segments[seg].marker != 0 ? sub.segments[seg].marker : 1);
      out.segments.push_back({id(ring[k]), id(ring[(k + 1) % ring.size()]), marker});
    }
    if (r > 0) out.holes.push_back(sub.hole_point(f, r));
  }
  return out;
}

unsigned thread_count(const DecomposeOptions& options, std::size_t tasks) {
  unsigned n = options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::min<std::size_t>(n, std::max<std::size_t>(tasks, 1)));
}

Decomposition to_decomposition(const Subdivision& sub, const Pslg& domain, const DecomposeOptions& options,
                               const detail::GradingState& grading) {
  Decomposition d;
  d.points = sub.points;
  d.segments = sub.segments;
  d.segment_origin = sub.origin;
  d.holes = domain.holes;
  d.regions = domain.regions;
  d.separator_angle_deg = options.separator_angle_deg;
  const bool required_area = has_required_area(options);
  if (required_area) d.subdomain_area_ratio = options.subdomain_area_ratio;
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    Subdomain s;
    s.rings = sub.faces[f].rings;
    s.ring_segments = sub.faces[f].ring_segments;
    s.area = sub.face_area(f);
    s.weight = grading.weight(sub, f);
    if (required_area) s.required_area = grading.required(sub, f);
    s.interior_point = sub.faces[f].interior;
    for (std::size_t r = 1; r < s.rings.size(); ++r) s.hole_points.push_back(sub.hole_point(f, r));
    s.interior_segments = sub.faces[f].inner_segments;
    s.interior_points = sub.faces[f].inner_points;
    std::sort(s.interior_segments.begin(), s.interior_segments.end());
    std::sort(s.interior_points.begin(), s.interior_points.end());
    d.subdomains.push_back(std::move(s));
  }
  return d;
}

// Area-driven grading (Sec. 5.2): each round plans one split for every face
// whose area exceeds subdomain_area_ratio x its required area (the smallest
// required area inside it; none inside: unconstrained), the largest ratios
// first (ties: lower face id), while the total stays <= options.subdomains.
void plan_area_round(Subdivision& sub, const detail::GradingState& grading, const DecomposeOptions& options,
                     const detail::StuckFaces& stuck) {
  std::vector<std::pair<double, std::uint32_t>> over;
  for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
    if (stuck.is_stuck(f)) continue;
    const double required = grading.required(sub, f);
    if (!std::isfinite(required)) continue;
    const double ratio = sub.face_area(f) / required;
    if (ratio > options.subdomain_area_ratio) over.emplace_back(-ratio, f);
  }
  std::sort(over.begin(), over.end());
  const std::size_t budget = options.subdomains > sub.faces.size() ? options.subdomains - sub.faces.size() : 0;
  for (std::size_t k = 0; k < std::min(budget, over.size()); ++k) sub.faces[over[k].second].plan = 2;
}

// DecomposeOptions::progress, after a commit (on the calling thread: run_round commits there).
void report_progress(const DecomposeOptions& options, const Subdivision& sub) {
  if (options.progress) options.progress(static_cast<std::uint32_t>(sub.faces.size()), options.subdomains);
}

detail::SplitOptions split_options_of(const DecomposeOptions& options) {
  detail::SplitOptions split_options;
  split_options.separator_angle_deg = options.separator_angle_deg;
  split_options.boundary_refinement = options.boundary_refinement;
  split_options.min_split_quality = options.min_split_quality;
  split_options.max_split_retries = std::max(0, options.max_split_retries);
  split_options.seed = options.seed;
  split_options.smoothing_iterations = std::max(0, options.smoothing_iterations);
  split_options.adaptive_boundary_refinement = options.adaptive_boundary_refinement;
  return split_options;
}

}  // namespace

Decomposition decompose(const Pslg& domain, const DecomposeOptions& options) {
  return decompose_with_report(domain, options).decomposition;
}

DecomposeRun decompose_with_report(const Pslg& domain, const DecomposeOptions& options) {
  check_options(options, domain);
  validate(domain);
  return detail::decompose_valid(domain, options);
}

DecomposeRun detail::decompose_valid(const Pslg& domain, const DecomposeOptions& options) {
  check_options(options, domain);
  const detail::ResourceGuard guard({.time_limit_seconds = options.time_limit_seconds,
                                     .max_memory_bytes = options.max_memory_bytes,
                                     .subdomains = options.subdomains});
  Subdivision sub = Subdivision::from_domain(domain);
  detail::GradingState grading(options, domain);
  const bool area_driven = grading.mode().area_driven;
  sub.faces[0].plan = area_driven ? 1 : options.subdomains;
  const detail::SplitOptions split_options = split_options_of(options);
  detail::SplitTimes split_times;
  double insert_seconds = 0.0;
  detail::StuckFaces stuck;
  while (true) {
    stuck.release_changed(sub);
    if (area_driven) {
      plan_area_round(sub, grading, options, stuck);
    } else {
      stuck.replan(sub, grading, options.subdomains);
    }
    std::vector<detail::RoundTask> tasks;
    for (std::uint32_t f = 0; f < sub.faces.size(); ++f) {
      if (sub.faces[f].plan > 1) tasks.push_back({f, sub.faces[f].plan, grading.density(sub, f)});
    }
    if (tasks.empty()) break;
    guard.check(sub.faces.size());
    // Every split of the round reads this snapshot while `sub` takes the commits.
    const Subdivision snapshot = sub;
    detail::run_round(
        snapshot, tasks, split_options, thread_count(options, tasks.size()), guard,
        [&](std::size_t i, const detail::SplitResult& r) {
          detail::Stopwatch clock;
          split_times += r.times;
          grading.before_commit(snapshot, r);
          const std::uint32_t f = tasks[i].face;
          const std::uint32_t plan = tasks[i].plan;
          const std::uint32_t k0 = detail::side0_plan(plan, r.weight[0], r.weight[1]);
          const std::uint32_t g = sub.commit(f, r);
          sub.faces[f].plan = k0;
          sub.faces[g].plan = plan - k0;
          grading.after_commit(sub, f, g);
          insert_seconds += clock.lap();
          report_progress(options, sub);
        },
        [&](std::size_t i, const DecompositionError& error) { stuck.mark(sub, tasks[i].face, error); });
    grading.end_round(sub);
  }
  double rebalance_seconds = 0.0;
  if (options.repair_balance_above > 0.0 && !area_driven && !grading.mode().graded()) {
    detail::Stopwatch clock;
    detail::rebalance(sub, split_options, guard, {.target = options.repair_balance_above, .threads = options.threads});
    rebalance_seconds = clock.lap();
  } else if (options.repair_balance_above > 0.0 && grading.can_rebalance()) {
    // Background weights (madd mesh balances expected triangles this way):
    // the same repair, on the graded weights.
    detail::Stopwatch clock;
    // options.face_work, when set, once per face (by its rings' points: the
    // repair reads every face again after each repair, and most are
    // unchanged; the repairs it tries number new points alike in their
    // copies, so ids alone could name two faces).
    // The repairs are tried on several threads: the cache under a lock, a
    // face's work found outside it (two threads may both find it: the same
    // value).
    std::map<std::vector<double>, double> work_of;
    std::mutex work_mutex;
    const auto weight = [&](const detail::Subdivision& s, std::uint32_t f) {
      if (!options.face_work) return grading.weight_from_scratch(s, f);
      std::vector<double> key;
      for (const auto& ring : s.faces[f].rings) {
        for (const std::uint32_t v : ring) key.insert(key.end(), {s.points[v].x, s.points[v].y});
        key.push_back(std::numeric_limits<double>::infinity());  // between rings
      }
      {
        const std::lock_guard lock(work_mutex);
        if (const auto it = work_of.find(key); it != work_of.end()) return it->second;
      }
      const double work = options.face_work(face_domain(s, f));
      const std::lock_guard lock(work_mutex);
      return work_of.try_emplace(std::move(key), work).first->second;
    };
    const detail::FaceMeasure measure{
        weight, [&](const detail::Subdivision& s, std::uint32_t f) { return grading.density_from_scratch(s, f); }};
    detail::rebalance(sub, split_options, guard, {.target = options.repair_balance_above, .threads = options.threads},
                      measure);
    grading.reassign(sub);
    rebalance_seconds = clock.lap();
  }
  DecomposeRun run;
  std::vector<PhaseTime>& phases = run.report.phases;
  phases.push_back({"refine", split_times.refine});
  phases.push_back({"triangulate", split_times.triangulate});
  phases.push_back({"graph", split_times.graph});
  phases.push_back({"bisect", split_times.bisect});
  phases.push_back({"insert", insert_seconds});
  phases.push_back({"rebalance", rebalance_seconds});
  if (sub.faces.size() == 1) sub.faces[0].interior = detail::largest_triangle_centroid(domain);
  detail::check_new_angles(sub, options.separator_angle_deg);
  run.decomposition = to_decomposition(sub, domain, options, grading);
  return run;
}

}  // namespace madd
