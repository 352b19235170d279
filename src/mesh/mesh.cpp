// mesh(): decompose, discretise (the decoupling), refine every subdomain on
// its own thread, merge in subdomain order, verify.
//
// Determinism: each subdomain is refined from its own data only, and the
// merge numbers the Steiner points subdomain by subdomain, so the mesh is the
// same for any thread count and any order the threads finish in.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <unordered_map>
#include <utility>

#include "kernel/resource_limits.hpp"
#include "kernel/stopwatch.hpp"
#include "kernel/threads.hpp"
#include "madd/mesh.hpp"
#include "madd/mesh_share.hpp"
#include "decompose/decompose_valid.hpp"
#include "mesh/discretise.hpp"
#include "mesh/merge.hpp"
#include "mesh/mesh_pieces.hpp"
#include "mesh/pieces_check.hpp"
#include "mesh/subdomain_check.hpp"
#include "madd/mesh_pieces.hpp"
#include "mesh/refine.hpp"
#include "mesh/rounds.hpp"
#include "quality/area_bound.hpp"
#include "quality/verify_mesh_bounded.hpp"
#include "mesh/subdomain_regions.hpp"
#include "mesh/work.hpp"

namespace madd {

void check_options(const MeshOptions& options) {
  const MeshSizeOptions& s = options.size;
  if (!(s.min_triangle_angle_deg >= 0 && s.min_triangle_angle_deg < 60))
    throw OptionError("min_triangle_angle_deg",
                      "must lie in [0, 60) degrees (refinement terminates in practice up to about 34)");
  if (!(s.max_triangle_area >= 0) || !std::isfinite(s.max_triangle_area))
    throw OptionError("max_triangle_area", "must be finite and >= 0");
  for (const ValuedPoint& v : s.triangle_area_samples) {
    if (!(v.value > 0) || !std::isfinite(v.value) || !std::isfinite(v.at.x) || !std::isfinite(v.at.y))
      throw OptionError("triangle_area_samples", "every sample must have finite coordinates and a finite area > 0");
  }
  // The size field's terms (each 0 = off).
  const std::pair<const char*, double> field_terms[] = {
      {"min_edge_length", s.min_edge_length}, {"max_edge_length", s.max_edge_length},
      {"distance_rate", s.distance_rate},     {"cells_across", s.cells_across},
      {"size_gradation", s.size_gradation},   {"wavelength_cells", s.wavelength_cells},
      {"slope_cells", s.slope_cells}};
  for (const auto& [field, value] : field_terms)
    if (!(value >= 0) || !std::isfinite(value)) throw OptionError(field, "must be finite and >= 0");
  if (s.min_edge_length > 0 && s.max_edge_length > 0 && s.max_edge_length < s.min_edge_length)
    throw OptionError("max_edge_length", "must be >= min_edge_length");
  if (s.distance_rate > 0 && s.min_edge_length == 0)
    throw OptionError("distance_rate",
                      "needs min_edge_length > 0: the edge length at the coast, which grows by distance_rate per unit "
                      "of distance from it");
  if (s.has_depth_terms() && !s.depth)
    throw OptionError(s.wavelength_cells > 0 ? "wavelength_cells" : "slope_cells", "needs a depth (bathymetry)");
  if (s.slope_cells > 0 && !s.depth_gradient)
    throw OptionError("slope_cells", "needs the depth's gradient (bathymetry)");
  // Gradation only lowers a field some other bound sets.
  const bool other_bound = s.max_triangle_area > 0 || s.triangle_area_function || !s.triangle_area_samples.empty() ||
                           s.max_edge_length > 0 || s.distance_rate > 0 || s.cells_across > 0 || s.has_depth_terms();
  if (s.size_gradation > 0 && !other_bound)
    throw OptionError("size_gradation",
                      "needs a size bound to grade (max_edge_length, distance_rate, cells_across, wavelength_cells, "
                      "slope_cells, max_triangle_area, triangle_area_function or triangle_area_samples)");
}

namespace {

// Refines the subdomains in `todo` (all of them in the first round, then
// those next to separators split since), largest expected work first so that
// the last ones to finish are small; results land in their own slots.
void refine_some(const Decomposition& d, const MeshOptions& options, const detail::AreaBound& field,
                 const std::vector<double>& work, const detail::ResourceGuard& guard, MeshReport& report,
                 const std::vector<std::uint32_t>& todo, const std::vector<std::vector<Region>>& regions,
                 const detail::SubdomainCheck& check, bool last_round, std::vector<detail::SubdomainMesh>& out) {
  const auto n = static_cast<std::uint32_t>(todo.size());
  const auto all = static_cast<std::uint32_t>(d.subdomains.size());
  std::vector<std::uint32_t> order = todo;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return work[a] > work[b]; });
  detail::RefineSettings settings;
  settings.min_triangle_angle_deg = options.size.min_triangle_angle_deg;
  settings.size = field.bounded() ? &field : nullptr;
  settings.off_centres = options.off_centres;
  settings.guard = &guard;
  const unsigned threads = detail::thread_count(options.decomposition.threads, n);
  if (report.thread_seconds.size() < threads) report.thread_seconds.resize(threads, 0.0);
  report.subdomain_seconds.resize(all, 0.0);
  std::atomic<std::uint32_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  // Thread 0 is the calling thread: it reports progress between its subdomains.
  const auto worker = [&](unsigned id) {
    for (;;) {
      const std::uint32_t i = next.fetch_add(1);
      if (i >= n || failed.load()) return;
      const std::uint32_t k = order[i];
      try {
        detail::Stopwatch clock;
        detail::LocalDomain local = detail::local_domain(d, k);
        local.pslg.regions = regions[k];
        detail::RefineSettings mine = settings;
        mine.meshed = &done;
        mine.max_steiner_points = detail::steiner_budget(work[k], local.pslg.points.size());
        mine.expected_triangles = work[k];
        out[k] = detail::refine_subdomain(local.pslg, local.splittable, mine);
        // Checked here, while in this thread's cache, unless a later round
        // meshes it again (a separator piece of it stopped a fix).
        if (check && (out[k].blocking_separators.empty() || last_round)) check(k, local, out[k]);
        const double s = clock.lap();
        report.subdomain_seconds[k] += s;
        report.thread_seconds[id] += s;
        const std::uint32_t finished = done.fetch_add(1) + 1;
        if (id == 0 && options.progress) options.progress(finished, n);  // n: this round's subdomains
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  detail::run_on_threads(threads, worker);
  if (error) std::rethrow_exception(error);
  if (options.progress) options.progress(n, n);
}

// The separator segments of `d` that stopped a fix in the subdomains just
// meshed (global ids, sorted, once each).
std::vector<std::uint32_t> blocking_separators(const Decomposition& d, const std::vector<std::uint32_t>& meshed,
                                               const std::vector<detail::SubdomainMesh>& pieces) {
  std::vector<std::uint32_t> out;
  for (const std::uint32_t k : meshed) {
    if (pieces[k].blocking_separators.empty()) continue;
    const detail::LocalDomain local = detail::local_domain(d, k);
    for (const std::uint32_t s : pieces[k].blocking_separators) out.push_back(local.piece[s]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

namespace detail {

void throw_failed_check(const Verification& v) {
  std::string text = "mesh self-check failed (a bug in madd): " + v.problems.front();
  if (v.problems.size() > 1) text += " (and " + std::to_string(v.problems.size() - 1) + " more)";
  throw InternalError(text);
}

void refine_in_rounds(Decomposition& d, const MeshOptions& options, const AreaBound& field,
                      const std::vector<double>& work, const ResourceGuard& guard, const std::vector<bool>& mine,
                      const SeparatorUnion& union_of, MeshReport& report, std::vector<SubdomainMesh>& pieces,
                      const std::vector<std::vector<Region>>& regions, const SubdomainCheck& check) {
  pieces.assign(d.subdomains.size(), SubdomainMesh{});
  // Splitting separators later changes no face, so the regions hold for every round.
  std::vector<std::uint32_t> todo;
  for (std::uint32_t k = 0; k < d.subdomains.size(); ++k)
    if (mine[k]) todo.push_back(k);
  for (int round = 0;; ++round) {
    refine_some(d, options, field, work, guard, report, todo, regions, check, round == max_separator_rounds, pieces);
    if (round == max_separator_rounds) break;
    const std::vector<std::uint32_t> blocking = union_of(blocking_separators(d, todo, pieces));
    if (blocking.empty()) break;
    todo.clear();
    for (const std::uint32_t k : split_separator_pieces(d, blocking))
      if (mine[k]) todo.push_back(k);
  }
}

}  // namespace detail

namespace detail {

// A run up to its refined subdomains: the discretised decomposition and
// each subdomain's mesh.
struct Refined {
  Decomposition d;
  std::vector<SubdomainMesh> pieces;
};

// The decoupling, the estimate and refinement of `decomposition` of
// work.domain under work.size (built once per run); with check_on_workers,
// each subdomain's mesh is checked by the thread that made it, once final.
Refined refine_decomposition(const Decomposition& decomposition, const DomainWork& work, const MeshOptions& options,
                             MeshReport& report, detail::Stopwatch& clock, bool check_on_workers) {
  const AreaBound& field = work.size;
  const detail::ResourceGuard guard({options.decomposition.time_limit_seconds, options.decomposition.max_memory_bytes,
                                     static_cast<std::uint32_t>(decomposition.subdomains.size())});
  const unsigned threads = options.decomposition.threads;
  Refined out;
  // The subdomains' regions, found once (a triangulation of the whole
  // domain): the decoupling's split points change no face.
  const RegionView view = region_view(decomposition, threads);
  out.d = detail::discretise(decomposition, field, false, &guard, threads, &view);
  report.phases.push_back({"discretise", clock.lap()});
  report.expected_triangles = detail::expected_triangles(out.d, work, threads, &decomposition, &view);
  report.phases.push_back({"estimate", clock.lap()});
  const std::vector<bool> all(out.d.subdomains.size(), true);
  const auto alone = [](const std::vector<std::uint32_t>& mine) { return mine; };
  // Without its regions: they are flooded over the whole mesh after, across
  // the separators (mesh/pieces_check.hpp), not from what each subdomain was given.
  const SubdomainCheck check = [&](std::uint32_t k, const LocalDomain&, const SubdomainMesh& piece) {
    verify_subdomain(out.d, k, {}, piece, options.size.min_triangle_angle_deg, field);
  };
  detail::refine_in_rounds(out.d, options, field, report.expected_triangles, guard, all, alone, report, out.pieces,
                           view.regions, check_on_workers ? check : SubdomainCheck{});
  report.phases.push_back({"refine", clock.lap()});
  return out;
}

// Meshes `decomposition` of work.domain under work.size into one Mesh,
// checked whole.
MeshRun mesh_decomposition_bounded(const Decomposition& decomposition, const DomainWork& work,
                                   const MeshOptions& options) {
  MeshRun run;
  detail::Stopwatch clock;
  Refined refined = refine_decomposition(decomposition, work, options, run.report, clock, false);
  run.mesh = detail::merge(refined.d, refined.pieces, options.size.min_triangle_angle_deg, nullptr,
                           options.decomposition.threads);
  run.report.phases.push_back({"merge", clock.lap()});
  const Verification v = options.verify
                             ? detail::verify_mesh(run.mesh, work.domain, work.size, options.decomposition.threads)
                             : Verification{};
  run.report.phases.push_back({"verify", clock.lap()});
  if (!v.ok()) detail::throw_failed_check(v);
  return run;
}

// The same kept in pieces: each subdomain checked by its worker, what
// crosses subdomains after.
MeshPiecesRun mesh_pieces_bounded(const Decomposition& decomposition, const DomainWork& work,
                                  const MeshOptions& options) {
  MeshPiecesRun run;
  detail::Stopwatch clock;
  Refined refined = refine_decomposition(decomposition, work, options, run.report, clock, options.verify);
  const unsigned threads = options.decomposition.threads;
  MeshPiecesData pieces = detail::assemble(std::move(refined.d), std::move(refined.pieces),
                                           options.size.min_triangle_angle_deg, nullptr, threads);
  run.report.phases.push_back({"assemble", clock.lap()});
  const Verification v =
      options.verify ? detail::verify_pieces(pieces, work.domain, work.size, true, threads) : Verification{};
  run.report.phases.push_back({"verify", clock.lap()});
  if (!v.ok()) detail::throw_failed_check(v);
  run.mesh = MeshPieces(std::move(pieces));
  return run;
}

DecomposeRun decompose_bounded(const DomainWork& work, const MeshOptions& options) {
  DecomposeOptions dopt = options.decomposition;
  if (options.balance_by_work) detail::weigh_by_work(dopt, work);
  return detail::decompose_valid(work.domain, dopt);
}

}  // namespace detail

MeshRun mesh_decomposition(const Decomposition& decomposition, const Pslg& domain, const MeshOptions& options) {
  check_options(options);
  detail::Stopwatch clock;
  const detail::AreaBound field(options.size, &domain, options.decomposition.threads);
  const double field_seconds = clock.lap();
  MeshRun run = detail::mesh_decomposition_bounded(
      decomposition, detail::DomainWork(domain, field, options.decomposition.threads), options);
  if (!field.field().empty()) run.report.phases.insert(run.report.phases.begin(), {"size field", field_seconds});
  return run;
}

DecomposeRun decompose_for_mesh(const Pslg& domain, const MeshOptions& options) {
  check_options(options);
  validate(domain);
  const detail::AreaBound field(options.size, &domain, options.decomposition.threads);
  return detail::decompose_bounded(detail::DomainWork(domain, field, options.decomposition.threads), options);
}

namespace {

// The whole run on `domain`: checks, the size field, the decomposition, then
// mesh_decomposed(decomposition, work, options) (merged or in pieces), the
// first two phases put in front of its report.
template <typename MeshDecomposed>
auto mesh_domain(const Pslg& domain, const MeshOptions& options, const MeshDecomposed& mesh_decomposed) {
  check_options(options);
  detail::Stopwatch clock;
  // The domain is validated once, before the size field is built on it.
  validate(domain);
  const detail::AreaBound field(options.size, &domain, options.decomposition.threads);
  const double field_seconds = clock.lap();
  // One reading of the whole domain's work for the weights and the estimates.
  const detail::DomainWork work(domain, field, options.decomposition.threads);
  const Decomposition d = detail::decompose_bounded(work, options).decomposition;
  const double decompose_seconds = clock.lap();
  auto run = mesh_decomposed(d, work, options);
  run.report.phases.insert(run.report.phases.begin(), {"decompose", decompose_seconds});
  if (!field.field().empty()) run.report.phases.insert(run.report.phases.begin(), {"size field", field_seconds});
  return run;
}

}  // namespace

MeshRun mesh_with_report(const Pslg& domain, const MeshOptions& options) {
  return mesh_domain(domain, options, detail::mesh_decomposition_bounded);
}

Mesh mesh(const Pslg& domain, const MeshOptions& options) { return mesh_with_report(domain, options).mesh; }

MeshPiecesRun mesh_pieces_with_report(const Pslg& domain, const MeshOptions& options) {
  return mesh_domain(domain, options, detail::mesh_pieces_bounded);
}

}  // namespace madd
